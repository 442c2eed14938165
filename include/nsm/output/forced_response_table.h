// frc.csv, the forced response's table, and its Result lines: each curve's
// extent and peak, and the peak against the backbone's main branch.
#pragma once

#include <nsm/base/csv.h>
#include <nsm/continuation/continuation.h>
#include <nsm/continuation/forced_response.h>

#include <string>
#include <vector>

namespace nsm
{
  /// One row per point of each curve, in the curves' order and along each.
  CsvTable forced_response_table(const std::vector<ForcedCurve> &curves);

  /// Per curve: its points and Omega extent, whether it reached the range's
  /// end, and its peak (largest energy): Omega, energy, phase lag; with a
  /// backbone (not null), the main branch's energy at the peak's Omega, read
  /// between the main points that bracket it, and the relative distance.
  std::vector<std::string> forced_response_summary(const std::vector<ForcedCurve> &curves,
                                                   const Backbone                 *backbone);
} // namespace nsm
