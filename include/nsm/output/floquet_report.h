// What a run says of the Floquet multipliers computed at the forced curves'
// verified points (Forcing/Floquet; verification/forced_floquet.h): a Result
// line and the continuation log's events.
#pragma once

#include <nsm/output/forced_response_table.h>

#include <string>
#include <vector>

namespace nsm
{
  /// Points with multipliers, where the shooting converged, how many lie
  /// outside the unit circle and how (folds, period doublings,
  /// Neimark-Sacker pairs), and the fold test against them: an odd number of
  /// real multipliers beyond +1 where det J < 0. Empty without multipliers.
  std::string floquet_summary(const std::vector<ForcedCurve> &curves, const ForcedVerifications &verifications);

  /// Along each curve, between consecutive points whose shooting converged:
  /// where the largest multiplier leaves the unit circle (and how) or comes
  /// back inside it.
  std::vector<std::string> floquet_events(const std::vector<ForcedCurve> &curves,
                                          const ForcedVerifications      &verifications);
} // namespace nsm
