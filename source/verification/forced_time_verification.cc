#include <nsm/harmonic_balance/trigonometric.h>
#include <nsm/verification/forced_modal_steps.h>
#include <nsm/verification/forced_time_verification.h>

#include <algorithm>
#include <cmath>
#include <complex>

namespace nsm
{
  unsigned int steady_state_periods(const DampedReceptance &receptance, const double omega, const unsigned int limit)
  {
    const double rate = receptance.slowest_decay();
    if (!(rate > 0))
      return limit;
    const double periods =
      std::ceil(std::log(1 / forced_verification_constants::transient_share) / (rate * two_pi / omega));
    return periods >= limit ? limit : std::max(1u, static_cast<unsigned int>(periods));
  }

  ForcedVerification verify_forced_point(const ForcedHarmonicBalance &hb, const std::vector<double> &x,
                                         const unsigned int steps, const unsigned int periods)
  {
    ForcedModalSteps    model(hb, x, steps);
    std::vector<double> previous(steps, 0.0), current(steps, 0.0);
    ForcedVerification  result{0, 0, 0, periods};
    for (unsigned int period = 0; period < periods; ++period)
      {
        const bool last   = period + 1 == periods;
        double     energy = 0;
        for (unsigned int n = 0; n < steps; ++n)
          {
            const double u = model.step();
            current[n]     = u;
            if (last)
              {
                energy += model.energy();
                result.tip_amplitude = std::max(result.tip_amplitude, std::abs(u));
                if (periods > 1)
                  result.drift = std::max(result.drift, std::abs(u - previous[n]) / hb.law().gap());
              }
          }
        if (last)
          result.energy = energy / steps;
        previous.swap(current);
      }
    result.settled = model.state();
    return result;
  }
} // namespace nsm
