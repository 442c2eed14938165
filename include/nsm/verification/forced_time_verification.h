// Verification in time of a forced-response point: the driven, damped FE
// model integrated from the point's own motion, with the physical wall.
//
// The model is the forced harmonic balance's own, written at the contact
// DoF in the receptance's modal coordinates q_j = phi_j(L) eta_j:
//     q_j'' + c_j q_j' + w_j^2 q_j = r_j P(t),   u(L, t) = sum_j q_j + g_far P(t),
// r_j = phi_j(L)^2, c_j each mode's damping, g_far the static share of the
// modes beyond the sum (the receptance's remainder at 0), and P the tip force:
// the drive F cos(W t) plus the wall's. Newmark's average acceleration per
// mode makes u(L, t_{n+1}) linear in P(t_{n+1}); the wall's force then follows
// in closed form (ContactLaw::step_force): on the rigid wall's face, or where
// the compliant wall's spring balances it. The start is the point's own
// harmonics (q_j and q_j' at t = 0 from the damped modal sum).
#pragma once

#include <nsm/harmonic_balance/forced_harmonic_balance.h>

#include <vector>

namespace nsm
{
  struct ForcedVerification
  {
    double tip_amplitude; ///< max |u(L, t)| over the last period integrated
    double energy;        ///< period mean over the last period (the HB's definition)
    double drift;         ///< max |u(L, t) - u(L, t - T)| / g0 over the last period
  };

  /// Integrates the point x of `hb` (at its current Omega and forcing) over
  /// `periods` periods of `steps` time steps each.
  ForcedVerification verify_forced_point(const ForcedHarmonicBalance &hb, const std::vector<double> &x,
                                         unsigned int steps, unsigned int periods);
} // namespace nsm
