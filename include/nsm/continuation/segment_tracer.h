// The seam for continuation methods: how one segment of the branch is traced
// from the backbone's last point, until a fold, a tongue, the range's end or
// Max steps. The driver (continuation.cc) joins the segments with leaps and
// never asks which method traced them. Sequential steps in Omega
// (sequential_steps.h) and pseudo-arclength (arclength_steps.h) implement
// it; a new method is a class of its own file, a name in the scene's option
// list (Continuation/Method) and a line in make_segment_tracer(). What a
// method keeps past a segment (for a checkpoint or a leap) is its own: the driver makes one tracer
// per backbone and asks it only what a checkpoint and a leap need.
#pragma once

#include <nsm/continuation/branch_context.h>

#include <cstddef>
#include <memory>
#include <optional>

namespace nsm
{
  class SegmentTracer
  {
  public:
    virtual ~SegmentTracer() = default;

    /// Appends the segment's points to the backbone (`segment` is their
    /// segment number) and says how the segment ended.
    virtual SegmentEnd trace(BranchContext &context, Backbone &backbone, unsigned int segment) = 0;

    /// After a segment that a stop signal ended: the step with which it goes
    /// on from the backbone's last point, which the checkpoint keeps
    /// (checkpoint.h). None: it is traced again from its first point.
    virtual std::optional<double> resume_step() const { return std::nullopt; }

    /// A resumed run's first segment goes on with `step` (resume_step()).
    virtual void resume_with(const std::optional<double> & /*step*/) {}

    /// The backbone index where the last segment first turned back in Omega,
    /// if the method follows folds (arclength): the leap starts no further
    /// (leap.h). None: the front is sought up to the segment's last point.
    virtual std::optional<std::size_t> first_fold() const { return std::nullopt; }
  };

  /// The tracer of Continuation/Method.
  std::unique_ptr<SegmentTracer> make_segment_tracer(ContinuationMethod method);
} // namespace nsm
