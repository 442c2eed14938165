// Each backbone point's energy error, estimated from the same motion with
// half the harmonics at the same Omega (doc/method.md, "The error estimate").
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/harmonic_balance/newton_solver.h>
#include <nsm/scene/harmonic_balance_parameters.h>

#include <string>
#include <utility>
#include <vector>

namespace nsm
{
  class Progress;

  /// A solution on another model whose contact fraction differs from the
  /// point's by more than this is another motion, not the same one solved
  /// again: the families a leap lands on have 0.15 to 0.24 less contact than
  /// the mode (doc/method.md, "Main branch, tongues and other families"),
  /// while the seed bar's main points change theirs by a median of 0.003 from
  /// M = 40 to M = 20 (doc/method.md, "The error estimate").
  constexpr double same_motion_contact_change = 0.1;

  /// A backbone point solved again on another model (fewer harmonics, a
  /// finer space) at its Omega: Newton from a guess, full steps and, where
  /// they fail, the leaps' Newton (leap_parameters: the guess lies off that
  /// model's solution by what the models differ in).
  class SameMotionSolve
  {
  public:
    SameMotionSolve(HarmonicBalance &model, const HarmonicBalanceParameters &params);

    /// |E / E_point - 1| of the solution found, NaN if Newton finds no
    /// contact motion or one more than same_motion_contact_change away.
    double energy_change(const BackbonePoint &point, const std::vector<double> &guess);

    /// Newton's solution at the point's Omega from `guess` (full steps, then
    /// the search), unconverged where neither converges.
    NewtonResult solve(const BackbonePoint &point, const std::vector<double> &guess);

    /// Whether the last energy_change's NaN is a converged motion of another
    /// contact (or none), rather than a Newton that did not converge.
    bool landed_elsewhere() const { return landed_elsewhere_; }

  private:
    HarmonicBalance &model_;
    double           tolerance_;
    NewtonSolver     full_steps_, searching_;
    bool             landed_elsewhere_ = false;
  };

  /// Up to `count` main points spread evenly over the main points in the
  /// backbone's order (the first and the last among them), as indices into
  /// backbone.points: the points the sampled checks solve again.
  std::vector<std::size_t> spread_main_points(const Backbone &backbone, std::size_t count);

  /// Per backbone point, |E(M / 2) / E(M) - 1|: E(M / 2) the energy of the
  /// harmonic balance with half the harmonics at the point's Omega, Newton
  /// from the point's own unknowns cut to M / 2. NaN where M < 2, where that
  /// Newton finds no contact motion, where it lands on another motion (its
  /// contact fraction more than same_motion_contact_change away), and for the
  /// points a stop signal left. `elsewhere`, if given, is set per point to
  /// whether its NaN is a landing on another motion.
  std::vector<double> estimate_energy_errors(const HarmonicBalance &hb, const BranchParameters &branch,
                                             const Backbone &backbone, Progress &progress,
                                             std::vector<bool> *elsewhere = nullptr);

  /// The median and 90th percentile of the estimates over the main points,
  /// and on how many of them one was found.
  struct EstimateSummary
  {
    std::size_t main = 0, estimated = 0;
    /// Of the main points without an estimate, those whose M / 2 Newton
    /// converged on another motion (the others: it did not converge, or a
    /// stop signal left them).
    std::size_t elsewhere = 0;
    double      median = 0, p90 = 0;
    /// Where the largest tenth of the estimates lie: the Omega spans of
    /// consecutive main points at or above the 90th percentile.
    std::vector<std::pair<double, double>> upper_spans;
  };
  EstimateSummary summarise_estimates(const Backbone &backbone, const std::vector<double> &estimates,
                                     const std::vector<bool> &elsewhere = {});

  /// "estimated energy error ..." for the run summary.
  std::string estimate_summary(const EstimateSummary &summary, unsigned int harmonics);
} // namespace nsm
