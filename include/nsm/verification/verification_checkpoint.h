// The points a stopped run had verified in time, written beside its output
// (verification.resume), so that `--resume` verifies only the others.
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/verification/time_verification.h>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  /// The checkpoint's name in the output directory.
  constexpr const char *verification_checkpoint_file = "verification.resume";

  /// Writes each verified point's index, Omega and results, numbers in
  /// hexadecimal floating point (exact), after the Verify steps and periods
  /// they were computed with.
  void write_verification_checkpoint(std::ostream &out, const Backbone &backbone,
                                     const std::vector<std::optional<PointVerification>> &verifications,
                                     const OutputParameters &output);

  /// The results at `path` for `backbone`, one slot per point, `verified`
  /// judged again against Verify tolerance; all empty if there is no file, or
  /// if it was computed with other Verify steps or periods. Throws InputError
  /// naming --resume if the file is not one nsm-bar wrote whole or names a
  /// point that is not the backbone's.
  std::vector<std::optional<PointVerification>> read_verification_checkpoint(const std::string   &path,
                                                                             const Backbone      &backbone,
                                                                             const OutputParameters &output);
} // namespace nsm
