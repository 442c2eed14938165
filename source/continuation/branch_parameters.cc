#include <nsm/continuation/branch_parameters.h>
#include <nsm/model/bar_model.h>
#include <nsm/scene/scene.h>

namespace nsm
{
  BranchParameters::BranchParameters(const Scene &scene)
    : contact(scene.contact)
    , harmonic_balance(scene.harmonic_balance)
    , continuation(scene.continuation)
    , progress_every(scene.output.progress_every)
    , computation_entries(scene.computation_entries)
    , accumulation_omega(accumulation_frequency(scene.bar, scene.continuation.mode))
  {}
} // namespace nsm
