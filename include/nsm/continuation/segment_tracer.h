// The seam for continuation methods: how one segment of the branch is traced
// from the backbone's last point, until a fold, a tongue, the range's end or
// Max steps. The driver (continuation.cc) joins the segments with leaps and
// never asks which method traced them. Sequential steps in Omega
// (sequential_steps.h) and pseudo-arclength (arclength_steps.h) implement
// it; a new method is a class of its own file, a name in the scene's option
// list (Continuation/Method) and a line in make_segment_tracer().
#pragma once

#include <nsm/continuation/branch_context.h>

#include <memory>

namespace nsm
{
  class SegmentTracer
  {
  public:
    virtual ~SegmentTracer() = default;

    /// Appends the segment's points to the backbone (`segment` is their
    /// segment number) and says how the segment ended.
    virtual SegmentEnd trace(BranchContext &context, Backbone &backbone, unsigned int segment) const = 0;
  };

  /// The tracer of Continuation/Method.
  std::unique_ptr<SegmentTracer> make_segment_tracer(ContinuationMethod method);
} // namespace nsm
