// What tracing a branch reads of a scene: the Continuation subsection, the
// harmonic balance's Newton settings (and its harmonics, for the branch with
// half of them), the contact law's sign (the direction of continuation) and
// how often progress is reported. The continuation's units take this, not
// the whole scene.
#pragma once

#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/continuation_parameters.h>
#include <nsm/scene/harmonic_balance_parameters.h>

#include <string>
#include <vector>

namespace nsm
{
  struct Scene;

  struct BranchParameters
  {
    explicit BranchParameters(const Scene &scene);

    ContactParameters         contact;
    HarmonicBalanceParameters harmonic_balance;
    ContinuationParameters    continuation;
    double                    progress_every; ///< seconds; 0 = never (Output/Progress every)
    /// Scene::computation_entries: a resumed run must share them (checkpoint.h).
    std::vector<std::string>  computation_entries;
    /// The accumulation point of the branch's internal resonances,
    /// (2 Mode - 1) pi / (2 tau) (nsm::accumulation_frequency).
    double                    accumulation_omega;
  };
} // namespace nsm
