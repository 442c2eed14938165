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
#pragma once

#include <nsm/model/receptance.h>
#include <nsm/scene/damping_parameters.h>

#include <complex>
#include <vector>

namespace nsm
{
  class DampedReceptance
  {
  public:
    /// `receptance` must use the modal method; both are kept by reference.
    DampedReceptance(const Receptance &receptance, const DampingParameters &damping);

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

    const Receptance &undamped() const { return receptance_; }
    /// c_j of each mode of undamped().modes().
    const std::vector<double> &coefficients() const { return coefficients_; }

    /// min_j c_j / 2: the rate at which the slowest of the summed modes'
    /// free motions decays, exp(-c_j t / 2).
    double slowest_decay() const;

  private:
    const Receptance   &receptance_;
    /// c_j of each mode of receptance_.modes().
    std::vector<double> coefficients_;
  };
} // namespace nsm
