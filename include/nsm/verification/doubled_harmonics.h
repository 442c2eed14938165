// The error estimate's blind spot, checked on a sample: the estimate
// |E(M/2) / E(M) - 1| cannot see the internal resonances w_j / k with k > M,
// which neither model holds. A few main points are solved again with 2 M
// harmonics from their own unknowns (the harmonics above M set to zero), and
// the median |E(M) / E(2 M) - 1| is set beside the estimate's median at the
// same points (doc/method.md, "The estimate's blind spot").
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>
#include <nsm/model/discretisation.h>
#include <nsm/scene/receptance_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace nsm
{
  /// Where the 2 M check's median exceeds the estimate's median at the same
  /// points by more than this factor, the estimate under-reads and the run
  /// warns: the factor within which the estimate's median is held to the
  /// truth (doc/method.md, "The error estimate").
  constexpr double under_read_factor = 3;

  struct DoubledHarmonicsCheck
  {
    unsigned int harmonics = 0; ///< 2 M
    /// Per sampled point: its index in the backbone and |E(M) / E(2 M) - 1|
    /// (NaN where not found again on the same motion).
    std::vector<std::size_t> points;
    std::vector<double>      changes;
    std::size_t sampled() const { return points.size(); }
    /// The sampled points found again on the same motion.
    std::size_t found() const
    {
      return std::count_if(changes.begin(), changes.end(), [](const double c) { return std::isfinite(c); });
    }
    /// Median |E(M) / E(2 M) - 1| over the points found again on the same
    /// motion, and the median estimate |E(M/2) / E(M) - 1| over those of
    /// them that carry one (NaN if none).
    double median_change   = std::numeric_limits<double>::quiet_NaN();
    double median_estimate = std::numeric_limits<double>::quiet_NaN();
    /// The resonances w_j / k with M < k <= 2 M between the main branch's
    /// lowest and highest Omega: what the estimate cannot see.
    std::size_t resonances = 0;
  };

  /// Solves the evenly spread main points (spread_main_points) with 2 M
  /// harmonics on a receptance of `model` up to 2 `band` (`band`: M times the
  /// branch's highest Omega), Newton from the point's own unknowns; where that
  /// fails, through 3 M / 2 harmonics first (from a point's own unknowns it
  /// finds 5 of the seed scene's 15, through 3 M / 2 11 in all, and the 5 it finds
  /// directly are the easy ones near grazing: their median reads 0.45 %
  /// against 2.3 % over the 11). `estimates` are the points' M / 2 estimates.
  DoubledHarmonicsCheck check_with_doubled_harmonics(const Discretisation &model, const ReceptanceParameters &receptance,
                                                     const BranchParameters &branch, const Backbone &backbone,
                                                     const std::vector<double> &estimates, double band);

  /// "the estimate checked with 2 M ..." for the run summary.
  std::string doubled_harmonics_summary(const DoubledHarmonicsCheck &check);

  /// The warning naming Harmonic balance/Harmonics where the estimate
  /// under-reads by more than under_read_factor (empty otherwise).
  std::string doubled_harmonics_warning(const DoubledHarmonicsCheck &check);
} // namespace nsm
