#include <nsm/base/errors.h>
#include <nsm/continuation/arclength_steps.h>
#include <nsm/continuation/segment_tracer.h>
#include <nsm/continuation/sequential_steps.h>

namespace nsm
{
  std::unique_ptr<SegmentTracer> make_segment_tracer(const ContinuationMethod method)
  {
    switch (method)
      {
        case ContinuationMethod::sequential:
          return std::make_unique<SequentialSteps>();
        case ContinuationMethod::arclength:
          return std::make_unique<ArclengthSteps>();
      }
    throw NumericalError("no tracer for this continuation method");
  }
} // namespace nsm
