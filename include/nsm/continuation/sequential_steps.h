// Sequential continuation (the paper's): steps in Omega with a secant
// predictor inside a segment, each solved by Newton at fixed Omega.
#pragma once

#include <nsm/continuation/segment_tracer.h>

namespace nsm
{
  /// A step whose solution moved by more than `Max solution change` times the
  /// solution itself, or whose contact fraction changed by more than `Max
  /// contact change`, has jumped to another branch (over a fold), not followed
  /// it.
  bool stays_on_branch(const BackbonePoint &from, const BackbonePoint &to, const Scene::Continuation &c);

  /// Steps from the backbone's last point; the step grows by 1.5 after a
  /// solve of at most 4 iterations, up to the context's max_step(), and is
  /// quartered on failure or on a jump to another branch, down to Min step
  /// (a fold). Steps stop exactly at the start of the range (coming from
  /// before it) and at its end. With `hand_over` it ends (`approach`) once
  /// the range is reached: another method traces the range.
  SegmentEnd sequential_segment(BranchContext &context, Backbone &backbone, unsigned int segment,
                                bool hand_over = false);

  /// Where a segment that fills a gap (gap_filling.h) ends: before a step
  /// would reach or pass `join_at`, the gap's far side (`joined`), and at a
  /// point above `tongue_above`, not kept (`tongue`).
  struct StepLimits
  {
    double join_at;
    double tongue_above;
  };

  /// sequential_segment within those limits.
  SegmentEnd sequential_segment(BranchContext &context, Backbone &backbone, unsigned int segment,
                                const StepLimits &limits);

  /// The paper's method: sequential_segment.
  class SequentialSteps : public SegmentTracer
  {
  public:
    SegmentEnd trace(BranchContext &context, Backbone &backbone, unsigned int segment) const override
    {
      return sequential_segment(context, backbone, segment);
    }
  };
} // namespace nsm
