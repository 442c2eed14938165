// Main branch, tongue or other family, for every point. The nonsmooth mode is
// the family connected to grazing; it hardens (along the direction of
// continuation its energy rises) and its contact lasts longer. A resonance
// tongue is an excursion above it, which the branch climbs near W = w_j / k
// and comes down from beyond; a leap can land on another family, of less
// contact. So: a point whose energy is more than Tongue share above the lowest
// energy of the mode's family at or beyond its Omega (the monotone lower
// envelope) is a tongue point; an envelope point whose contact fraction lies
// more than Main contact drop below the most contact of the main points
// before it is of another family, and so is a point on its own segment's
// envelope whose contact end's swing a harmonic k > 1 leads (a higher mode's
// motion at k W): both leave the envelope (main_family); every other
// point is on the main branch. A tongue is named after the
// harmonic k >= 3 that stands out most of the spectrum at its highest point
// and the mode j nearest to k W, if w_j / k lies near its Omega; an excursion
// that names only the branch's own fundamental is main.
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>

#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace nsm
{
  /// How far harmonic k stands above the envelope of its neighbours (the
  /// geometric mean of harmonics k - 2 and k + 2, or harmonic k - 2 alone at
  /// the top), as a share of the total energy; 0 for k < 3.
  double harmonic_excess(const std::vector<double> &harmonic_energies, unsigned int k);

  /// The harmonic k >= 3 that stands out most, and its excess (negative if
  /// none stands out); harmonic 0 if there are fewer than 4 harmonics.
  struct SpectralExcess
  {
    unsigned int harmonic;
    double       share;
  };

  SpectralExcess spectral_excess(const std::vector<double> &harmonic_energies);

  /// The resonance w_j / k of harmonic k at Omega: j the clamped-free mode
  /// whose frequency is nearest to k Omega.
  InternalResonance resonance_of(const Receptance &receptance, unsigned int k, double omega);

  /// r if its w_j / k lies within resonance_name_tolerance (constants.h) of
  /// the Omega interval [lo, hi] a tongue spans; unnamed {0, 0, 0} otherwise.
  InternalResonance named_if_near(const InternalResonance &r, double lo, double hi);

  /// Per point, in order: true if its energy exceeds (1 + share) times the
  /// least energy of the points at or beyond its Omega in `direction`.
  /// Only the points `among` count and can be above (all if it is empty).
  std::vector<bool> above_envelope(const std::vector<BackbonePoint> &points,
                                   double                            direction,
                                   double                            share,
                                   const std::vector<bool>          &among = {});

  /// Per point, in order: true if it is not `above` the envelope but lies
  /// behind its segment's front, the farthest Omega in `direction` of the
  /// segment's earlier points that are neither above nor behind. The main
  /// branch is a graph over Omega; a continuation that comes back (the back
  /// of a fold, the middle of an S) is on another branch.
  std::vector<bool> behind_front(const std::vector<BackbonePoint> &points,
                                 double                            direction,
                                 const std::vector<bool>          &above,
                                 const std::vector<bool>          &among = {});

  /// The mode's contact end swings once a period: true if the point's
  /// fundamental leads the contact end's swing. A point led by a harmonic
  /// k > 1 is a higher mode's motion at k W, or a tongue's top.
  bool moves_at_omega(const BackbonePoint &point);

  /// Per point, in order: true if it belongs to the mode's family. In the
  /// direction of continuation, a point whose contact fraction lies more
  /// than `drop` below the most contact before it leaves the family, and so
  /// does a point on its own segment's envelope led by a harmonic other than
  /// the fundamental (a tongue's top may be led by its resonant harmonic:
  /// it lies above its segment's envelope, and stays), and then every point
  /// of the family's envelope led so, until none is; the
  /// most contact counts the family's points that lie on their own
  /// segment's lower envelope (a tongue's climb that comes back down within
  /// its segment does not count), so that another family of less energy
  /// beyond cannot hide the mode. Along the main branch (the family's
  /// envelope points) the contact then never falls by more than `drop`.
  std::vector<bool> main_family(const std::vector<BackbonePoint> &points, double direction, double share,
                                double drop);

  /// Where a hardening branch (the physical force sign) has passed its
  /// accumulation point W_acc (BranchParameters::accumulation_omega):
  /// W_acc (1 + accumulation_reach / M^2), beyond the climb's truncated top;
  /// NaN for a softening branch (eq. (5)'s sign, measured on no bar that
  /// crosses it), whose points are labelled together.
  double accumulation_passed(const BranchParameters &params);

  /// Sets every point's branch, and the resonance of each run of tongue
  /// points from the spectrum of its most energetic point (the scene's Tongue
  /// share, Main contact drop, direction and Mode). Points off the main
  /// family are other; tongue points are the family's points above its
  /// envelope or behind the front. A run whose resonance is the fundamental
  /// at the branch's own mode is main: nothing resonates there (its points
  /// led by a higher harmonic are other). A run is named w_j / k only within
  /// resonance_name_tolerance of its Omega. Every main point moves_at_omega.
  /// The points on either side of accumulation_passed are labelled on
  /// their own.
  void label_branches(HarmonicBalance &hb, const BranchParameters &params, std::vector<BackbonePoint> &points);

  /// Labels one point solved off the backbone (a landing of the gap search,
  /// a field at a given Omega) as label_branches labels it among the
  /// labelled `points`, inserted before `position` (at their end if none:
  /// a segment of its own when its segment number is new). The labels of
  /// `points` are left as they are.
  void label_point(HarmonicBalance                  &hb,
                   const BranchParameters           &params,
                   const std::vector<BackbonePoint> &points,
                   BackbonePoint                    &point,
                   std::optional<std::size_t>        position = std::nullopt);

  /// The envelope at omega: the least energy of `points` not labelled other
  /// at omega or beyond it in `direction` (infinity if none).
  /// The most contact fraction before omega in `direction` of the mode's
  /// family in the labelled `points` (not other, and on their own segment's
  /// envelope, as main_family counts it); minus infinity if none.
  /// Beyond `passed` (accumulation_passed) only the points beyond it count.
  double most_contact_before(const std::vector<BackbonePoint> &points, double omega, double direction, double share,
                             double passed = std::numeric_limits<double>::quiet_NaN());

  /// Beyond `passed` (main_family) only the points beyond it count, and
  /// before it only those before it.
  double envelope_at(const std::vector<BackbonePoint> &points, double omega, double direction,
                     double passed = std::numeric_limits<double>::quiet_NaN());

  /// The intervals (from, to) between consecutive main points of `points` in
  /// `direction`, from `start` to the first one if given (the range's near
  /// end, where the branch was traced from outside the range), and from the
  /// last one to `end` if given.
  std::vector<std::pair<double, double>> main_gaps(const std::vector<BackbonePoint> &points, double direction,
                                                   std::optional<double> end   = std::nullopt,
                                                   std::optional<double> start = std::nullopt);

  /// Those of main_gaps wider than `width`: the gaps the gap search tries
  /// (gap_filling.h) and the Result block names.
  std::vector<std::pair<double, double>> main_gaps_wider_than(const std::vector<BackbonePoint> &points,
                                                              double direction, double width,
                                                              std::optional<double> end   = std::nullopt,
                                                              std::optional<double> start = std::nullopt);

  /// The tongues of a labelled backbone: runs of tongue points of one
  /// resonance, with the Omega of the main points at their feet.
  std::vector<Tongue> collect_tongues(const std::vector<BackbonePoint> &points);
} // namespace nsm
