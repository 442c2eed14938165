// Verification in time of a forced-response point: the driven, damped FE
// model integrated from the point's own motion, with the physical wall.
//
// The model is the forced harmonic balance's own, written at the contact
// DoF in the receptance's modal coordinates q_j = phi_j(L) eta_j:
//     q_j'' + c_j q_j' + w_j^2 q_j = r_j P(t) + s_j F cos(W t),
//     u(L, t) = sum_j q_j + g_far P(t) + h_far F cos(W t),
// r_j = phi_j(L)^2, s_j the drive's weights (DampedReceptance::
// drive_weights: r_j for the drive at the contact end), c_j each mode's
// damping, g_far and h_far the static shares of the modes beyond the sum,
// and P the wall's force. Newmark's average acceleration per mode makes
// u(L, t_{n+1}) linear in P(t_{n+1}); the wall's force then follows in
// closed form (ContactLaw::step_force): on the rigid wall's face, or where
// the compliant wall's spring balances it. The start is the point's own
// harmonics (q_j and q_j' at t = 0 from the damped modal sum).
#pragma once

#include <nsm/harmonic_balance/forced_harmonic_balance.h>
#include <nsm/verification/forced_floquet.h>

#include <cmath>
#include <optional>

#include <vector>

namespace nsm
{
  namespace forced_verification_constants
  {
    /// The share of the start's transient left when the integration ends,
    /// with Forcing/Verify periods = 0: the start is the point's own motion,
    /// within the harmonic balance's truncation (a few per cent at most) of
    /// the orbit, so what is left is 1e-4 of the amplitude or less, well
    /// inside the 1 % it is compared to.
    constexpr double transient_share = 1e-3;
    /// A point the integration stays on: its tip amplitude within this of
    /// the point's, relative (the agreement doc/method.md asks of the
    /// verification; the harmonic balance's own error at M = 40 is 1e-3).
    constexpr double stays_within = 0.01;
  } // namespace forced_verification_constants

  /// The periods that take the slowest mode's free transient down to
  /// transient_share at the drive's Omega: ln(1 / share) / (min_j c_j / 2 T),
  /// rounded up; at most `limit`.
  unsigned int steady_state_periods(const DampedReceptance &receptance, double omega, unsigned int limit);

  struct ForcedVerification
  {
    double tip_amplitude; ///< max |u(L, t)| over the last period integrated
    double energy;        ///< period mean over the last period (the HB's definition)
    double drift;         ///< max |u(L, t) - u(L, t - T)| / g0 over the last period
    unsigned int periods; ///< integrated
    /// Every summed mode's q and v where the integration ended, at t = 0 of
    /// a period (ForcedModalSteps::state): on a stable orbit, the orbit.
    std::vector<double> settled = {};
    /// The point's Floquet multipliers, where asked (Forcing/Floquet).
    std::optional<FloquetMultipliers> floquet = std::nullopt;
  };

  /// Whether the integration stayed on a point of tip amplitude
  /// `tip_amplitude`: its own within stays_within of it.
  inline bool stays_on(const ForcedVerification &v, const double tip_amplitude)
  {
    return std::abs(v.tip_amplitude / tip_amplitude - 1) <= forced_verification_constants::stays_within;
  }

  /// Integrates the point x of `hb` (at its current Omega and forcing) over
  /// `periods` periods of `steps` time steps each.
  ForcedVerification verify_forced_point(const ForcedHarmonicBalance &hb, const std::vector<double> &x,
                                         unsigned int steps, unsigned int periods);
} // namespace nsm
