// Floquet multipliers of a forced-response point on the compliant wall, by
// shooting: the periodic orbit of the damped, driven model at the contact DoF
// stepped in time (forced_modal_steps.h; every summed mode's q and v as the
// state) found by Newton's method on the one-period map z -> P(z) from the
// point's own motion, and the eigenvalues of P's Jacobian there, the
// monodromy matrix. The Jacobian is the period's product of the Newmark steps'
// derivatives, carried along the steps (ForcedModalSteps::step with
// tangents): exact for the stepped map, whose wall force k max(u - g0, 0) is
// continuous in the state, so that it needs no saltation at contact's start
// and end and tends to the continuous model's monodromy as the steps shrink.
// The rigid wall's force is not continuous in the state (an impact): its
// steps' derivatives miss the saltation, and no multipliers are computed.
// From the harmonic balance's own start, which is not an orbit of the stepped
// model, the multipliers change with the step (doc/log.md): the shooting is
// what makes them converge.
//
// Off the wall the multipliers are each mode's ((1 + s dt / 2) / (1 - s dt /
// 2))^steps, s = -c_j / 2 +- i (w_j^2 - c_j^2 / 4)^(1/2) (the trapezoidal
// rule, which Newmark's average acceleration is), inside the unit circle. A
// point is unstable where one lies outside it: a real one beyond +1 (a fold
// or a branch point: the fold test's det J < 0 counts them odd), beyond -1 (a
// period doubling), or a complex pair (Neimark-Sacker).
#pragma once

#include <nsm/harmonic_balance/forced_harmonic_balance.h>

#include <complex>
#include <string>
#include <vector>

namespace nsm
{
  namespace floquet_constants
  {
    /// Newton's steps at most, and the orbit's tolerance: |P(z) - z| at
    /// most this share of |z| (the stepped map is piecewise linear in z: on
    /// the piece of the orbit a full step lands at the rounding; measured 1
    /// to 12 steps from the harmonic balance's start).
    constexpr unsigned int newton_steps    = 30;
    constexpr double       orbit_tolerance = 1e-9;
    /// The shortest share of a Newton step tried (halving from 1) before
    /// the shooting gives up.
    constexpr double least_share = 1.0 / 1024;
  } // namespace floquet_constants

  struct FloquetMultipliers
  {
    /// Every multiplier, largest modulus first; empty where the shooting did
    /// not converge.
    std::vector<std::complex<double>> values;
    unsigned int                      newton_steps = 0;
    /// |P(z) - z| / |z| at the orbit.
    double residual = 0;
    /// Found from the integration's settled state (the point's own start
    /// stalled).
    bool from_settled = false;

    bool   converged() const { return !values.empty(); }
    double largest() const { return values.empty() ? 0.0 : std::abs(values.front()); }
    /// Real multipliers beyond +1: odd where the fold test finds det J < 0.
    unsigned int beyond_plus_one() const;
    /// How the largest leaves the unit circle: "fold" (real, beyond +1),
    /// "period doubling" (real, beyond -1), "Neimark-Sacker" (complex);
    /// empty inside it.
    std::string instability() const;
  };

  /// The multipliers of the stepped model's orbit nearest the point x of
  /// `hb` (at its current Omega and forcing; the wall compliant), `steps`
  /// time steps a period. Where the shooting from x's own motion stalls
  /// (the stepped map is piecewise linear: a step across a piece's edge may
  /// not lower the defect), it starts again from `settled` if given: the
  /// state the integration in time ended at (ForcedVerification::settled),
  /// on the orbit where the orbit attracts.
  FloquetMultipliers floquet_multipliers(const ForcedHarmonicBalance &hb, const std::vector<double> &x,
                                         unsigned int steps, const std::vector<double> &settled = {});
} // namespace nsm
