// Pseudo-arclength continuation in Omega on LOCA's stepper, with the
// analytic dR/dW of the harmonic balance.
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>

#include <functional>

namespace nsm
{
  /// Pseudo-arclength from a converged start point with LOCA::Stepper, first
  /// step of length initial_step. `accept` is called for every converged
  /// step and returns false to stop.
  /// Returns true if LOCA finished its run (it reached Omega min or max, or
  /// accept stopped it), false if it failed to converge a step.
  bool run_arclength(HarmonicBalance                                  &hb,
                     const BranchParameters                           &params,
                     const BackbonePoint                              &start,
                     double                                            initial_step,
                     const std::function<bool(const BackbonePoint &)> &accept);
} // namespace nsm
