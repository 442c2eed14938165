// The continuation's results: a backbone's points, labelled main or
// tongue, its tongues, how it ended, and the internal resonances that fold
// it. The driver that computes it is continuation.h.
#pragma once

#include <nsm/harmonic_balance/newton_solver.h>
#include <nsm/harmonic_balance/solution_measures.h>
#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/continuation_parameters.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace nsm
{
  enum class Branch
  {
    main,   ///< the nonsmooth mode: its family's monotone lower envelope (main_branch.h)
    tongue, ///< above it, near W = w_j / k, where harmonic k drives mode j near its resonance; or the
            ///< climb's truncated top at the accumulation point (accumulation_tongue.h)
    other   ///< another family (a leap landed on it): less contact than the mode before it
  };

  /// "main", "tongue" or "other", as the CSV files write it.
  inline const char *branch_name(const Branch b)
  {
    return b == Branch::main ? "main" : b == Branch::tongue ? "tongue" : "other";
  }

  /// A tongue's resonance: w_j / k, or unnamed {0, 0, 0} (no w_j / k near
  /// it), or the accumulation point {W_acc, 0, 0} of the w_j / (2j - 1),
  /// their limit (accumulation_tongue.h).
  struct InternalResonance
  {
    double       omega; ///< w_j / k
    unsigned int mode;  ///< j
    unsigned int harmonic; ///< k
  };

  /// The accumulation point W_acc as a tongue's resonance.
  inline InternalResonance accumulation_resonance(const double w_acc)
  {
    return {w_acc, 0, 0};
  }

  /// Whether r is the accumulation point (accumulation_resonance).
  inline bool at_accumulation_point(const InternalResonance &r)
  {
    return r.mode == 0 && r.harmonic == 0 && r.omega > 0;
  }

  /// "internal", "unnamed" or "accumulation", as tongues.csv writes it.
  inline const char *resonance_kind(const InternalResonance &r)
  {
    return at_accumulation_point(r) ? "accumulation" : r.mode == 0 ? "unnamed" : "internal";
  }

  struct BackbonePoint
  {
    unsigned int             segment;
    double                   omega;
    PeriodicSolutionMeasures measures;
    unsigned int             newton_iterations;
    double                   residual;
    std::vector<double>      x; ///< scaled unknowns
    Branch                   branch    = Branch::main;
    InternalResonance        resonance = {0, 0, 0}; ///< of a tongue point; zero on the main branch
  };

  /// A run of tongue points of one resonance along the backbone (the
  /// accumulation point's: all its points, its feet the main points next to
  /// them in Omega).
  struct Tongue
  {
    InternalResonance resonance;
    double            foot_begin; ///< Omega of the point before it
    double            foot_end;   ///< Omega of the point after it
    double            max_energy; ///< highest energy written on it
    unsigned int      points;
  };

  /// How the continuation ended: a study's row says it (backbone_end), so
  /// that a row whose branch was lost is not read as one that covered the range.
  enum class BackboneEnd
  {
    range,      ///< Omega min or max reached, or the range left
    max_steps,  ///< Max steps points in all
    lost,       ///< after a fold or tongue, no leap found the branch again
    energy_max, ///< after a fold or tongue, the leap landed only above Energy max
    refused,    ///< arclength reached a point that is not a contact motion
    interrupted ///< SIGINT or SIGTERM asked the run to stop (interruption.h)
  };

  /// The point nearest to omega with side * (its Omega - omega) >= 0 (either
  /// side for 0), among the main points if `main_only`; null if none.
  const BackbonePoint *nearest_on_side(const std::vector<BackbonePoint> &points, double omega, int side,
                                       bool main_only = false);

  /// "range", "max_steps", "lost", "energy_max", "refused" or "interrupted", as study.csv
  /// writes it.
  const char *backbone_end_name(BackboneEnd end);

  /// A gap of the main branch that the gap search (gap_filling.h) tried:
  /// what its Newton starts from the predicted mode found there, and where a
  /// segment traced into it landed (its points may yet not be main once the
  /// whole backbone is labelled again).
  struct GapSearch
  {
    double       from, to;             ///< Omega of the main points around it, or the range's end
    unsigned int starts          = 0;  ///< Newton solves from the predicted mode
    unsigned int other_family    = 0;  ///< converged on another family (labelled other by label_point)
    unsigned int other_harmonic  = 0;  ///< of those, led by a harmonic other than the fundamental
    unsigned int tongue          = 0;  ///< converged above the envelope (a tongue's flank)
    unsigned int above_energy_max = 0; ///< converged above Energy max (not kept)
    double       most_contact    = 0;  ///< the most contact of the other families led by the fundamental
    double       contact_before  = 0;  ///< the mode's most contact before the gap
    std::optional<double> landed;      ///< where the segment traced into the gap began
  };

  struct ContinuationCheckpoint;

  struct Backbone
  {
    std::vector<BackbonePoint> points;
    std::vector<Tongue>        tongues;
    NewtonCost                 newton_cost; ///< sequential method and leaps
    std::vector<std::string>   events; ///< folds, leaps, stops: for the summary
    std::vector<double>        folds;  ///< Omega of each fold turned or leapt
    std::vector<GapSearch>     gap_searches; ///< the gaps the search left, in the order tried
    /// The gap search's own work: its Newton solves (its starts, leaps and
    /// the steps of the segments it traces; not those of a branch with fewer
    /// harmonics traced for its guesses) and its wall time.
    NewtonCost                 gap_search_cost;
    double                     gap_search_seconds = 0;
    unsigned int               leaps = 0;
    BackboneEnd                end   = BackboneEnd::range;
    /// The branches traced with fewer harmonics for guesses where a leap or
    /// a gap found none (FewerHarmonicsBranch, fewer_harmonics.h: M / 2, and within
    /// it M / 4, ...), each as its harmonics and its points; empty if none
    /// was needed.
    std::vector<std::pair<unsigned int, std::size_t>> fewer_harmonics_traced;
    /// Where the continuation stood when it ended or was interrupted: what
    /// a run stopped by a signal writes for --resume (checkpoint.h).
    std::shared_ptr<const ContinuationCheckpoint> checkpoint;
    /// The Omegas of the points traced from grazing, in the range or not
    /// (only those in it are written): lowest and highest.
    std::pair<double, double> traced_span{0, 0};
    /// The Omega of the first point traced (grazing), in the range or not;
    /// none where no point was traced.
    std::optional<double> traced_start;

    /// The points labelled `branch`.
    unsigned int points_on(Branch branch) const;
    unsigned int main_points() const { return points_on(Branch::main); }

    /// The Omega of the written point furthest in the branch's `direction`
    /// (branch_direction); none if no point was written.
    std::optional<double> omega_reached(double direction) const;

    /// The Omega the branch was traced from (traced_start: grazing, in the
    /// range or not), or its first written point where none was kept; none
    /// if no point was written.
    std::optional<double> traced_from() const;
  };

  /// Omega min <= omega <= Omega max.
  bool in_omega_range(const ContinuationParameters &continuation, double omega);

  /// Why a backbone that ended (not interrupted) wrote no point: the branch
  /// ended before the range's near end, or passed over the range between
  /// two points; "" if it wrote one. An InputError's text naming the entry.
  std::string range_without_points(const Backbone &backbone, const ContinuationParameters &continuation,
                                   double direction);

  /// +1 where the branch leaves grazing upwards in Omega (the physical force
  /// sign), -1 with the paper's eq. (5): the one place this is derived.
  double branch_direction(const ContactParameters &contact);

  /// The internal resonance nearest to omega (resonances not empty).
  const InternalResonance &nearest_resonance(const std::vector<InternalResonance> &resonances,
                                             double                                omega);
} // namespace nsm
