// Where a continuation stood when its run was interrupted, written beside
// the run's output (continuation.resume), so that `nsm-bar SCENE --resume`
// goes on from there and ends with the points an uninterrupted run writes.
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>

#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  class HarmonicBalance;

  /// The hashes (fnv1a of the text before the checksum) of the checkpoints
  /// written beside the continuation's, by file name (verification.resume,
  /// refinement.resume): a resumed run reads only these.
  using CheckpointCompanions = std::map<std::string, std::uint64_t>;

  struct ContinuationCheckpoint
  {
    /// Every point traced, in order, before the range filter and the labels
    /// (the points on the way from grazing to the range included).
    std::vector<BackbonePoint> points;
    std::vector<std::string>   events;
    std::vector<double>        folds;
    std::vector<GapSearch>     gap_searches;
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
    /// The checkpoints written beside this one.
    CheckpointCompanions companions;
  };

  /// The checkpoint's name in the output directory.
  constexpr const char *checkpoint_file = "continuation.resume";

  /// Writes the checkpoint as text, numbers in hexadecimal floating point
  /// (exact), after the scene's computation entries (Scene), which a
  /// resumed run must share, and the `companions`' hashes, and before the
  /// model's fingerprint: a hash of the text before it and of the bits of
  /// each point's numbers and of the residual vector `hb` gives it. A run on
  /// the same model computes the same; if any bit of the model (mesh,
  /// receptance, band), of a point or of the text differs, it differs but for
  /// a chance of 2^-64. Unlike the file's checksum, only the program with
  /// the model can make it. Write it with write_checksummed
  /// (base/checkpoint_reader.h).
  void write_checkpoint(std::ostream &out, const ContinuationCheckpoint &checkpoint,
                        const std::vector<std::string> &computation_entries, HarmonicBalance &hb,
                        const CheckpointCompanions &companions = {});

  /// Reads the checkpoint at `path` for a run of `scene`, the points'
  /// measures computed again with `hb`. Throws InputError naming --resume:
  /// no checkpoint, a checkpoint nsm-bar did not write whole (its checksum),
  /// a scene entry that differs from the interrupted run's (every one named
  /// with both values), or points that the model does not reproduce bit for
  /// bit (its fingerprint).
  ContinuationCheckpoint read_checkpoint(const std::string &path, const BranchParameters &params, HarmonicBalance &hb);
} // namespace nsm
