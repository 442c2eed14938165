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
  /// a fold. Records the segment's first fold in the context.
  SegmentEnd arclength_segment(BranchContext &context, Backbone &backbone, unsigned int segment);

  /// Pseudo-arclength on the range; from a start before the range (grazing
  /// below Omega min), sequential steps approach it first.
  class ArclengthSteps : public SegmentTracer
  {
  public:
    SegmentEnd trace(BranchContext &context, Backbone &backbone, unsigned int segment) const override;
  };
} // namespace nsm
