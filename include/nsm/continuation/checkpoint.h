// Where a continuation stood when its run was interrupted, written beside
// the run's output (continuation.resume), so that `nsm-bar SCENE --resume`
// goes on from there and ends with the points an uninterrupted run writes.
#pragma once

#include <nsm/continuation/backbone.h>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  class HarmonicBalance;

  struct ContinuationCheckpoint
  {
    /// Every point traced, in order, before the range filter and the labels
    /// (the points on the way from grazing to the range included).
    std::vector<BackbonePoint> points;
    std::vector<std::string>   events;
    std::vector<double>        folds;
    unsigned int               leaps = 0;
    double                     span  = 0; ///< BranchContext::span
    /// The segment to go on with: from its last point with `step` (the
    /// sequential method stopped mid-segment), or else from its first
    /// point, the last of `points` (arclength: LOCA's state is not kept).
    unsigned int          segment = 0;
    std::optional<double> step;
    /// The continuation had ended (the run was stopped in a later stage),
    /// as `end` says.
    bool        complete = false;
    BackboneEnd end      = BackboneEnd::range;
  };

  /// The checkpoint's name in the output directory.
  constexpr const char *checkpoint_file = "continuation.resume";

  /// Writes the checkpoint as text, numbers in hexadecimal floating point
  /// (exact), after the scene's computation entries (Scene), which a
  /// resumed run must share.
  void write_checkpoint(std::ostream &out, const ContinuationCheckpoint &checkpoint,
                        const std::vector<std::string> &computation_entries);

  /// Reads the checkpoint at `path` for a run of `scene`, the points'
  /// measures computed again with `hb`. Throws InputError naming --resume:
  /// no checkpoint, a checkpoint nsm-bar did not write whole, or a scene
  /// entry that differs from the interrupted run's (named with both values).
  ContinuationCheckpoint read_checkpoint(const std::string &path, const Scene &scene, HarmonicBalance &hb);
} // namespace nsm
