// Harmonic balance of the driven, damped bar at the contact DoF: the drive
// F cos(W t), at the contact end or as a load along the bar (Forcing/Shape;
// the damped receptance's drive(), model/damped_receptance.h), the contact
// law of the backbone (ContactLaw: rigid or compliant wall, either force
// sign), and the damped receptance gamma_d on the full basis (1, sin k tau,
// cos k tau; tau = W t), with no phase condition: the drive fixes the phase.
//
// Per harmonic k the receptance maps the tip force's coefficients (a, b) of
// a cos k tau + b sin k tau to the displacement's
//     (g_r a + g_i b, g_r b - g_i a),   g_r + i g_i = gamma_d(k W),
// a 2 x 2 block Gamma_k. The unknowns are the contact force's coefficients
// scaled as the backbone's, x = lambda / F_s with F_s = g0 / gamma(0). With
// u = u_F - s Gamma lambda (u_F = F H_d e_cos1, the drive's response, H_d =
// gamma_d(W) at the contact end; s the force sign) and the law's weights
// (beta, a), the indicator q = beta lambda - a (g0 - u) has the scaled
// coefficients
//     v = (beta I - a s Gamma) x + a u_F / F_s - a gamma(0) e_0,
// and the Signorini law's projection gives
//     R = x - G v,   J = I - G (beta I - a s Gamma),
// G the Gram matrix of the basis over {q > 0} (active_set.h), exact or
// sampled as the scene integrates.
#pragma once

#include <nsm/harmonic_balance/active_set.h>
#include <nsm/model/contact_law.h>
#include <nsm/model/damped_receptance.h>
#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/harmonic_balance_parameters.h>

#include <complex>
#include <vector>

namespace nsm
{
  /// What frc.csv gives of one forced periodic solution.
  struct ForcedMeasures
  {
    /// Period-mean mechanical energy of the bar (kinetic plus strain) plus
    /// the compliant wall's period-mean stored energy: the backbone's energy
    /// where the motion is conservative (doc/method.md, "The forced response").
    double energy = 0;
    /// max_t |u(L, t)|.
    double tip_amplitude = 0;
    /// Lag of the tip displacement's fundamental behind the force, in
    /// (-pi, pi]: u_1 = A cos(W t - phase); pi / 2 at phase resonance.
    double phase = 0;
    double contact_fraction = 0;
    double max_contact_force = 0;
    /// Period-mean power the drive puts in, and the damping dissipates.
    double input_power = 0, dissipated_power = 0;
  };

  class ForcedHarmonicBalance
  {
  public:
    ForcedHarmonicBalance(const HarmonicBalanceParameters &params, const ContactParameters &contact,
                          const DampedReceptance &receptance);

    /// 2 M + 1: the mean, then sin k tau and cos k tau for k = 1..M.
    unsigned int n_unknowns() const { return functions_.size(); }

    /// The drive's amplitude F (force, along +x; per unit length for a
    /// distributed drive).
    void   set_forcing(double amplitude);
    double forcing() const { return forcing_; }

    /// Evaluates gamma_d at k W, k = 0..M, once per distinct W.
    void   set_omega(double omega);
    double omega() const { return omega_; }
    /// Whether set_omega() can evaluate the drive at W (a distributed
    /// drive's only within the receptance's modal band).
    bool drives_at(double omega) const { return receptance_.drives_at(omega); }

    /// Residual, and (if asked) the Jacobian (column-major n x n) and dR/dW
    /// (-G dv/dW: the active set's edges, where q = 0, add nothing).
    void evaluate(const std::vector<double> &x, std::vector<double> *residual,
                  std::vector<double> *jacobian, std::vector<double> *domega = nullptr) const;

    /// dR/dF at x: -G a H_d e_cos1 / F_s (the drive's response, u_F =
    /// F H_d e_cos1, is the only term F enters; the active set's edges add
    /// nothing, as for dR/dW).
    std::vector<double> dforcing(const std::vector<double> &x) const;

    ForcedMeasures measure(const std::vector<double> &x) const;

    /// The fold test's verdict on x at the current W: det J > 0. Off the
    /// wall J = I (G = 0), and the damped linear response is stable; along
    /// a curve J changes continuously and its determinant changes sign where
    /// a real Floquet multiplier passes +1 (a fold in W, or a branch point).
    /// So det J < 0 means an odd number of multipliers beyond +1: unstable.
    /// det J > 0 rules out only these: a period doubling (a multiplier
    /// through -1) or a Neimark-Sacker pair leaves it unchanged
    /// (doc/method.md, "The forced response"; the verification in time
    /// checks the verdicts).
    bool stable(const std::vector<double> &x) const;

    /// Share of the period in contact (measure()'s, alone).
    double contact_fraction(const std::vector<double> &x) const;

    /// Coefficients of the tip displacement u(L, t) on the basis.
    std::vector<double> displacement(const std::vector<double> &x) const;
    /// Coefficients on the basis of the wall's force on the contact end,
    /// -s times the contact force (the drive's response comes on top).
    std::vector<double> wall_force(const std::vector<double> &x) const;

    const DampedReceptance &receptance() const { return receptance_; }

    double force_scale() const { return force_scale_; }
    const ContactLaw &law() const { return law_; }

  private:
    /// Gamma y for coefficients y on the basis (block k per harmonic).
    std::vector<double> apply_receptance(const std::vector<double> &y) const { return apply(gamma_, y); }
    /// u += F h e_cos1 on the basis: (h_r, -h_i) F on (cos 1, sin 1).
    void add_drive(const std::complex<double> &h, double f, std::vector<double> &u) const;
    /// The blocks of `values` (one complex number per harmonic) applied to y.
    std::vector<double> apply(const std::vector<std::complex<double>> &values, const std::vector<double> &y) const;
    /// The indicator's scaled coefficients v.
    std::vector<double> contact_coefficients(const std::vector<double> &x) const;
    /// max over the period of |series|, from the samples refined near the largest.
    double largest_magnitude(const std::vector<double> &coefficients) const;
    double compliant_wall_energy(const std::vector<double> &u) const;

    const DampedReceptance           &receptance_;
    unsigned int                      harmonics_;
    ContactLaw                        law_;
    double                            beta_;
    double                            gamma0_;
    double                            force_scale_;
    TrigonometricBasis                functions_;
    ActiveSet                         active_set_;
    double                            forcing_ = 0;
    double                            omega_   = -1;
    std::vector<std::complex<double>> gamma_; ///< gamma_d(k W), k = 0..M
    std::vector<std::complex<double>> gamma_slope_; ///< d gamma_d(k W) / dW = k gamma_d'(k W)
    std::complex<double>              drive_, drive_slope_; ///< H_d(W) and dH_d / dW
  };
} // namespace nsm
