// The orbits a stopped run had found in time, written beside its output
// (refinement.resume), so that `--resume` shoots only the other points.
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/verification/periodic_orbit.h>
#include <nsm/scene/output_parameters.h>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  /// The checkpoint's name in the output directory.
  constexpr const char *refinement_checkpoint_file = "refinement.resume";

  /// Writes each shot point's index, Omega and orbit (found or not; a found
  /// one with its measures and its displacement at t = 0, from which the next
  /// point may be shot), numbers in hexadecimal floating point (exact), after
  /// the Refine every they were selected with.
  void write_refinement_checkpoint(std::ostream &out, const Backbone &backbone,
                                   const std::vector<std::optional<PeriodicOrbit>> &orbits,
                                   const OutputParameters &output);

  /// The orbits at `path` for `backbone`, one slot per point, `stable` judged
  /// again against Stability margin; all empty if there is no file, or if it
  /// was written with another Refine every. Throws InputError naming --resume
  /// if the file is not one nsm-bar wrote whole or names a point that is not
  /// the backbone's. `dofs`: the length of an orbit's displacement.
  std::vector<std::optional<PeriodicOrbit>> read_refinement_checkpoint(const std::string   &path,
                                                                       const Backbone      &backbone,
                                                                       const OutputParameters &output,
                                                                       unsigned int         dofs);
} // namespace nsm
