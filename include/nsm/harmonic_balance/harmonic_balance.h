// Harmonic balance of the contact law at the contact DoF (the paper's eqs.
// (7)-(10)), in a form that stays bounded through the poles and zeros of the
// receptance.
//
// Per harmonic k (frequency k W) the receptance is written gamma = tan(theta),
// theta continuous in W (each pole passed adds pi). One unknown c per basis
// function carries both coefficients of eq. (8):
//     a = c cos(theta)  (contact force),   b = -s c sin(theta)  (displacement),
// s = +1 with the physical force sign, -1 with the paper's eq. (5). Unknowns
// are scaled, x = c / F with F = g0 / gamma(0), so the scaled system does not
// depend on g0 at all. With tau = W t the residual of eqs. (9)-(10) reads
//     R_i = x_i cos(theta_i) - P_i[max(q, 0)],
//     q(tau) = sum_j x_j D_j phi_j(tau) - a gamma(0),
//     D_j = beta cos(theta_j) - s a sin(theta_j),
// with P_i the Fourier projection on phi_i and (beta, a) the contact law's
// weights: (1, alpha) for the rigid wall, (0, k) for the compliant one. Both integration rules reduce to
// the active Gram matrix G_ij = P_i[phi_j on {q > 0}]: R = diag(cos) x - G v
// with v = D x - a gamma(0) e_0, and J = diag(cos) - G diag(D).
#pragma once

#include <nsm/harmonic_balance/active_set.h>
#include <nsm/model/contact_law.h>
#include <nsm/model/receptance.h>
#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/harmonic_balance_parameters.h>
#include <nsm/harmonic_balance/solution_measures.h>
#include <nsm/harmonic_balance/trigonometric.h>

#include <vector>

namespace nsm
{
  /// Where the HB time goes (wall seconds and counts), for benchmarks. The
  /// linear solves are timed by the NOX/LOCA glue and recorded here too.
  struct HarmonicBalanceCost
  {
    double        receptance_seconds = 0, residual_seconds = 0, jacobian_seconds = 0;
    double        linear_solve_seconds = 0;
    unsigned long frequencies = 0, residuals = 0, jacobians = 0, linear_solves = 0;
  };

  /// Fourier coefficients of a solution in physical units, per basis
  /// function (1, then cos / sin of k W t): lambda = sum force_i phi_i and
  /// u_N = sum displacement_i phi_i.
  struct FourierCoefficients
  {
    std::vector<unsigned int> order;   ///< k
    std::vector<bool>         is_sine;
    std::vector<double>       force;
    std::vector<double>       displacement;
  };

  class HarmonicBalance
  {
  public:
    HarmonicBalance(const HarmonicBalanceParameters &params, const ContactParameters &contact,
                    const Receptance &receptance);

    /// Unknowns: x_0 (mean), then per harmonic k cos (cosine basis) or sin
    /// and cos (full basis). In the full basis slot 1 (sin W t) holds the
    /// unfolding parameter mu of the phase condition instead: the sine part
    /// of the first harmonic is fixed to 0 and mu must vanish at a solution.
    unsigned int n_unknowns() const { return functions_.size(); }
    /// Samples per period: the sampled rule's Time samples, or the grid on
    /// which the exact rule brackets the roots of q.
    unsigned int n_samples() const { return active_set_.n_samples(); }
    bool         has_unfolding() const { return basis_ == HarmonicBasis::full; }

    /// Evaluates the receptance at k W, k = 0..M, once per distinct W.
    void   set_omega(double omega);
    double omega() const { return omega_; }

    /// Residual, and (if asked) the Jacobian (column-major n x n) and dR/dW,
    /// at the current W.
    void evaluate(const std::vector<double> &x,
                  std::vector<double>       *residual,
                  std::vector<double>       *jacobian,
                  std::vector<double>       *domega) const;

    /// Guess near grazing at this W. Rigid wall: an impulsive contact force
    /// at t = 0 whose displacement reaches the gap; empty if no positive
    /// impulse can do it. Compliant wall: the spring's force under u(L) =
    /// A cos(W t), with A where the first harmonic balances alone (the
    /// describing function, ContactLaw::clipped_force_harmonics); empty where
    /// no A > g0 does.
    std::vector<double> grazing_guess() const;

    PeriodicSolutionMeasures measure(const std::vector<double> &x) const;

    /// Period-mean energy carried by each harmonic k = 0..M (Parseval: they
    /// add up to the energy of measure()).
    std::vector<double> harmonic_energies(const std::vector<double> &x) const;

    /// a and b of the solution x at the current W.
    FourierCoefficients coefficients(const std::vector<double> &x) const;

    /// Share of the period with q > 0 (0: the trivial motion).
    double contact_fraction(const std::vector<double> &x) const;

    const Receptance &receptance() const { return receptance_; }

    /// The contact law it balances.
    const ContactLaw &law() const { return law_; }

    const HarmonicBalanceCost &cost() const { return cost_; }

    void record_linear_solve(double seconds) const
    {
      cost_.linear_solve_seconds += seconds;
      ++cost_.linear_solves;
    }

    /// Contact force F that scales the unknowns (c = F x).
    double force_scale() const { return force_scale_; }

  private:
    /// grazing_guess() of the compliant wall.
    std::vector<double> describing_guess() const;

    /// q's coefficients v = D x - a gamma(0) e_0 (slot 1 of the full basis
    /// carries mu, not a coefficient).
    std::vector<double> contact_coefficients(const std::vector<double> &x) const;

    /// x with the unfolding slot (if any) zeroed, for the measures.
    std::vector<double> coefficients_only(const std::vector<double> &x) const;

    const Receptance   &receptance_;
    unsigned int        harmonics_;
    HarmonicBasis       basis_;
    Integration         integration_;
    double              a_gamma0_; ///< a gamma(0): q's constant term
    ContactLaw          law_;
    double              gamma0_;
    double              force_scale_;
    TrigonometricBasis  functions_;
    ActiveSet           active_set_;
    SolutionMeasures    measures_;
    double              omega_ = -1;
    std::vector<HarmonicPhase> phases_;       ///< per harmonic k = 0..M
    mutable HarmonicBalanceCost cost_;
  };
} // namespace nsm
