// The forced response: one frequency-response curve per drive amplitude F,
// traced in W by pseudo-arclength on LOCA's stepper through its folds, from
// Continuation/Omega min to Omega max (harmonic_balance/forced_harmonic_balance.h).
#pragma once

#include <nsm/harmonic_balance/forced_harmonic_balance.h>
#include <nsm/scene/continuation_parameters.h>
#include <nsm/scene/harmonic_balance_parameters.h>

#include <vector>

namespace nsm
{
  struct ForcedPoint
  {
    double              omega;
    ForcedMeasures      measures;
    double              residual; ///< unscaled 2-norm of R
    std::vector<double> x;
  };

  struct ForcedCurve
  {
    double                   forcing;
    std::vector<ForcedPoint> points;
    /// LOCA reached an end of the range; false: a step failed at Min step or
    /// Max steps ran out, and the curve ends where it stopped.
    bool         finished = false;
    /// Steps LOCA accepted whose residual missed the scene's tolerance: not
    /// written.
    unsigned int rejected = 0;
  };

  /// The curve of amplitude `forcing` over [omega_min, omega_max], from the
  /// linear response's guess (no contact) at omega_min, with the scene's
  /// step bounds and Max steps.
  ForcedCurve trace_forced_curve(ForcedHarmonicBalance           &hb,
                                 const HarmonicBalanceParameters &harmonic_balance,
                                 const ContinuationParameters    &continuation,
                                 double                           omega_min,
                                 double                           omega_max,
                                 double                           forcing);
} // namespace nsm
