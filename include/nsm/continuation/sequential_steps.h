// Sequential continuation (the paper's): steps in Omega with a secant
// predictor inside a segment, each solved by Newton at fixed Omega.
#pragma once

#include <nsm/continuation/segment_tracer.h>

#include <optional>

namespace nsm
{
  /// A step whose solution moved by more than `Max solution change` times the
  /// solution itself, or whose contact fraction changed by more than `Max
  /// contact change`, has jumped to another branch (over a fold), not followed
  /// it.
  bool stays_on_branch(const BackbonePoint &from, const BackbonePoint &to, const ContinuationParameters &c);

  /// Steps from the backbone's last point; the step grows by 1.5 after a
  /// solve of at most 4 iterations, up to the context's max_step(), and is
  /// quartered on failure or on a jump to another branch, down to Min step
  /// (a fold). Steps stop exactly at the start of the range (coming from
  /// before it) and at its end. With `hand_over` it ends (`approach`) once
  /// the range is reached: another method traces the range. `carried` is the
  /// step carried between segments: on entry the first step (none: Initial
  /// step), on return the step it would take next if Max steps or a stop
  /// signal ended it, and none after any other end.
  SegmentEnd sequential_segment(BranchContext &context, Backbone &backbone, unsigned int segment,
                                std::optional<double> &carried, bool hand_over = false);

  /// sequential_segment from Initial step, its carried step dropped.
  SegmentEnd sequential_segment(BranchContext &context, Backbone &backbone, unsigned int segment);

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

  /// The paper's method: sequential_segment, the step kept past a segment
  /// to segment.
  class SequentialSteps : public SegmentTracer
  {
  public:
    SegmentEnd trace(BranchContext &context, Backbone &backbone, unsigned int segment) override
    {
      return sequential_segment(context, backbone, segment, step_);
    }

    std::optional<double> resume_step() const override { return step_; }

    void resume_with(const std::optional<double> &step) override { step_ = step; }

  private:
    std::optional<double> step_;
  };
} // namespace nsm
