// The damped receptance of the contact DoF, gamma_d(w) = e_N^T (K - w^2 M +
// i w C)^{-1} e_N, for a damping C that the modes diagonalise (the Damping
// subsection: C = alpha M + beta K plus a modal ratio): the receptance's modal
// sum with each mode's damping,
//     gamma_d(w) = sum_j r_j / (w_j^2 - w^2 + i c_j w) + far(w^2),
// r_j = phi_j(L)^2 and c_j = 2 zeta w_j + alpha + beta w_j^2. The modes of
// the far-mode series (w_j >= 4 w for every w asked) respond quasi-statically
// and are summed undamped: their own damping, c_j w / (w_j^2 - w^2) <= 0.54
// zeta + 1.07 beta w + 0.067 alpha / w of their share, is left out
// (doc/method.md, "The forced response").
// Beyond the far series' band the undamped gamma is a direct solve, and the
// summed modes' damping is added to it as sum_j r_j (1 / d_j - 1 / (w_j^2 -
// w^2)), d_j = w_j^2 - w^2 + i c_j w: the same model.
// The time convention is e^{i w t}: a force P cos(w t) moves the contact DoF
// by Re(gamma_d P e^{i w t}), so Im gamma_d < 0 (the response lags).
//
// The drive F cos(W t) acts at the contact DoF (Forcing/Shape = tip), where
// its weights are the receptance's own, or as a distributed load F f
// (uniform; model/load_modes.h): its response at the contact DoF is then
// H_d(W) = sum_j s_j / d_j + far, and a harmonic's energy and dissipation
// take the cross and self weights of the modal force phi_j(L) P + b_j F.
#pragma once

#include <nsm/model/load_modes.h>
#include <nsm/model/receptance.h>
#include <nsm/scene/damping_parameters.h>

#include <complex>
#include <vector>

namespace nsm
{
  class DampedReceptance
  {
  public:
    /// `receptance` must use the modal method; it, `damping` and `load` are
    /// kept by reference. `load`: a distributed drive's modes, or nullptr for
    /// the drive at the contact DoF.
    DampedReceptance(const Receptance &receptance, const DampingParameters &damping,
                     const LoadModes *load = nullptr);

    std::complex<double> operator()(double omega) const { return value(omega).gamma; }

    struct Value
    {
      std::complex<double> gamma;
      std::complex<double> slope; ///< d gamma_d / d w
    };
    /// gamma_d and its slope in w.
    Value value(double omega) const;

    /// sum_j r_j (w_j^2 + w^2) / |w_j^2 - w^2 + i c_j w|^2 (the far modes'
    /// g + 2 w^2 g'): a force P cos(w t) at the contact DoF, w > 0, gives the
    /// bar a period-mean energy of |P|^2 / 4 times this; at w = 0 a static
    /// force P stores P^2 / 2 times it (= gamma(0)).
    double energy_factor(double omega) const;

    /// sum_j r_j c_j w^2 / |d_j|^2: the period-mean power P^2 / 2 times this
    /// that the damping dissipates under P cos(w t).
    double dissipation_factor(double omega) const;

    /// The drive's response at the contact DoF per unit F at W, and its slope
    /// in W: gamma_d for the drive at the contact DoF.
    Value drive(double omega) const;
    /// Whether the drive is a load along the bar (not at the contact DoF,
    /// where drive() is value()).
    bool distributed_drive() const { return load_ != nullptr; }
    /// Whether drive() can be evaluated at W: a distributed drive's modal
    /// sum only within the receptance's modal band.
    bool drives_at(double omega) const;

    /// The drive's terms in a first harmonic's energy and dissipation: with
    /// the contact force's P = p_cos - i p_sin at W, the period-mean energy
    /// is (|P|^2 energy_factor + 2 F p_cos cross + F^2 self) / 4 and the
    /// dissipated power (|P|^2 dissipation_factor + 2 F p_cos cross + F^2
    /// self) / 2; cross = self = energy_factor (dissipation_factor) for the
    /// drive at the contact DoF.
    struct DriveFactors
    {
      double cross, self;
    };
    DriveFactors drive_energy_factors(double omega) const;
    DriveFactors drive_dissipation_factors(double omega) const;

    /// The drive's own generalised displacement f^T u per unit F under the
    /// unit drive, sum_j b_j^2 / d_j + far (gamma_d at the contact DoF): the
    /// drive's power is -F W Im(H_d P + this F) / 2.
    std::complex<double> drive_self(double omega) const;

    /// s_j per mode (phi_j(L)^2 at the contact DoF), and the static share
    /// of the modes not summed in the drive's response at the contact DoF
    /// and in its own displacement: the verification in time's weights.
    const std::vector<double> &drive_weights() const;
    DriveFactors               drive_far_static() const;

    const Receptance &undamped() const { return receptance_; }
    /// c_j of each mode of undamped().modes().
    const std::vector<double> &coefficients() const { return coefficients_; }

    /// min_j c_j / 2: the rate at which the slowest of the summed modes'
    /// free motions decays, exp(-c_j t / 2).
    double slowest_decay() const;

  private:
    /// sum_j w_j / d_j + far(w^2) and its slope in w, in the modal band.
    Value modal_sum(const std::vector<double> &weights, const std::array<double, 2> &far, double omega) const;
    /// sum_j w_j g_j(w) + far, g_j = (w_j^2 + w^2) / |d_j|^2 (energy) or
    /// c_j w^2 / |d_j|^2 (dissipation; far 0).
    double energy_sum(const std::vector<double> &weights, const std::array<double, 2> &far, double omega) const;
    double dissipation_sum(const std::vector<double> &weights, double omega) const;

    const Receptance   &receptance_;
    const LoadModes    *load_;
    /// c_j of each mode of receptance_.modes().
    std::vector<double> coefficients_;
  };
} // namespace nsm
