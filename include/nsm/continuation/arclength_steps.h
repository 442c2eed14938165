// Pseudo-arclength continuation of one segment with LOCA (run_arclength),
// kept on its branch by three guards (method.md): a step that changes the
// contact fraction by more than Max contact change, the solution by more than
// Max solution change or Omega by more than Max step has jumped and is retried
// shorter; a tongue is followed up to Tongue energy ratio times the energy
// where the segment first turned back; a step past the end of the range is
// solved exactly at the end.
#pragma once

#include <nsm/continuation/segment_tracer.h>

namespace nsm
{
  /// Arclength from the backbone's last point, first step Initial step
  /// (at most the context's max_step()); a jump retries from the last point
  /// with a quarter of the step, down to Min step, where the segment ends at
  /// a fold. Sets `first_fold` to the backbone index where the segment first
  /// turns back in Omega (left as it is if it never does).
  SegmentEnd arclength_segment(BranchContext &context, Backbone &backbone, unsigned int segment,
                               std::optional<std::size_t> &first_fold);

  /// Pseudo-arclength on the range; from a start before the range (grazing
  /// below Omega min), sequential steps approach it first. It keeps each
  /// segment's first fold for the leap, and the approach's carried step for
  /// a checkpoint (an interrupted arclength segment is traced again).
  class ArclengthSteps : public SegmentTracer
  {
  public:
    SegmentEnd trace(BranchContext &context, Backbone &backbone, unsigned int segment) override;

    std::optional<double> resume_step() const override { return approach_step_; }

    void resume_with(const std::optional<double> &step) override { approach_step_ = step; }

    std::optional<std::size_t> first_fold() const override { return first_fold_; }

  private:
    std::optional<double>      approach_step_;
    std::optional<std::size_t> first_fold_;
  };
} // namespace nsm
