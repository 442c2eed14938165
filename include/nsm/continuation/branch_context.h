// What the stages of tracing one branch share (continuation.h has the
// overview): the model and its parameters, the Newton solvers, the direction and
// ends of the Omega range, and when a converged solve becomes a point. The
// stages are separate units: grazing_start, sequential_steps,
// arclength_steps, leap and gap_filling.
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>
#include <nsm/continuation/fewer_harmonics.h>
#include <nsm/base/progress.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  /// How a segment of the branch ended.
  enum class SegmentEnd
  {
    approach,  ///< the start of the range reached from a start before it
    range,     ///< Omega min or max reached
    fold,      ///< no convergence below Min step, or LOCA gave up
    tongue,    ///< energy above Energy max (climbing a resonance tongue)
    max_steps, ///< Max steps points in all
    interrupted, ///< a stop signal ended it at a point (interruption.h)
    refused,   ///< arclength reached a point that is not a contact motion
    jump,      ///< an arclength step left the branch (shortened and retried)
    joined     ///< a segment filling a gap reached its far side (gap_filling.h)
  };

  /// "what at Omega = ..." for the run summary, with the nearest internal
  /// resonance when given the list.
  std::string event_message(const std::string                    &what,
                            double                                omega,
                            const std::vector<InternalResonance> &resonances = {});

  /// The straight line through the unknowns of a and b, evaluated at omega
  /// (a's unknowns if both share one Omega): a Newton guess between points.
  std::vector<double> interpolated_guess(const BackbonePoint &a, const BackbonePoint &b, double omega);

  /// Newton for a guess far from the solution (a leap's, or a point solved
  /// again on another model): a line search and leap_iteration_factor times
  /// the iterations.
  HarmonicBalanceParameters leap_parameters(HarmonicBalanceParameters params);

  /// The first point of the segment the backbone's last point belongs to.
  std::size_t last_segment_start(const Backbone &backbone);

  class BranchContext
  {
  public:
    /// `fewer`, if given, must outlive the context: the branch with half the
    /// harmonics that fewer_harmonics() gives (null: none).
    BranchContext(HarmonicBalance &hb, const BranchParameters &params, std::vector<InternalResonance> resonances,
                  FewerHarmonicsBranch *fewer = nullptr);

    /// A converged solve becomes a point only if it is a genuine contact
    /// motion: the trivial solution (no contact) and, in the full basis, a
    /// solution whose unfolding parameter does not vanish are refused.
    bool make_point(const std::vector<double> &x, double omega, double residual,
                    unsigned int iterations, unsigned int segment, BackbonePoint &point);

    /// Which Newton a solve runs: full steps (a continuation step), a line
    /// search with more iterations (for a guess far from the solution), or
    /// the first and, where it fails, the second.
    enum class Newton
    {
      full_steps,
      line_search,
      both
    };

    /// Newton from the guess.
    bool solve(double omega, const std::vector<double> &guess, unsigned int segment,
               BackbonePoint &point, Newton newton = Newton::full_steps);

    /// Why the last solve() gave no point: Newton stopped unconverged at Max
    /// iterations (in either try; more iterations might converge), stalled or
    /// diverged, or converged to no contact motion.
    enum class SolveFailure
    {
      iteration_limit,
      stalled,
      no_contact
    };
    SolveFailure last_failure() const { return last_failure_; }

    /// Called after each point: Max steps reached, or a stop signal? Also
    /// reports progress.
    bool full(const Backbone &backbone);

    /// How a segment that full() ended ends: interrupted if a stop signal
    /// came, else max_steps.
    SegmentEnd full_end() const;

    bool in_range(double omega) const { return in_omega_range(params.continuation, omega); }

    /// a lies beyond b in the direction of continuation.
    bool beyond(double a, double b) const { return direction * (a - b) > 0; }

    /// Steps never exceed a tenth of the range covered, so that a narrow
    /// range still gets points.
    double max_step() const;

    NewtonCost newton_cost() const;

    /// The same branch traced with half the harmonics, as passed in
    /// (fewer_harmonics.h; null if none or below 2 harmonics): where a leap
    /// finds no landing, its main points, and in a gap of the main branch
    /// (gap_filling.h) all its points there, are guesses that lie near
    /// solutions.
    const Backbone *fewer_harmonics();

    /// A point of that branch as a guess at this M: its unknowns (the same
    /// quantities at both M), the higher harmonics zero (a point with more
    /// harmonics than M loses those above M).
    std::vector<double> guess_from_fewer_harmonics(const BackbonePoint &fewer) const;

    HarmonicBalance                     &hb;
    const BranchParameters               params;
    const std::vector<InternalResonance> resonances;
    const double                         direction;
    const double                         near_end, far_end; ///< the range's ends, first met and last
    double                               span = 0; ///< of the range covered from the start

  private:
    NewtonSolver newton_;
    NewtonSolver leap_newton_;
    Progress     progress_;
    SolveFailure last_failure_ = SolveFailure::stalled;
    FewerHarmonicsBranch *fewer_;
  };

  /// The point of least energy written within `reach` of omega and not
  /// beyond it in the direction of continuation; null if none.
  const BackbonePoint *lowest_point_behind(const BranchContext &context, const Backbone &backbone, double omega,
                                           double reach);

  /// Its energy (infinity if none): how low a landing there may go.
  double least_energy_behind(const BranchContext &context, const Backbone &backbone, double omega, double reach);
} // namespace nsm
