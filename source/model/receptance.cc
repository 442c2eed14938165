#include <nsm/base/errors.h>
#include <nsm/model/near_modes.h>
#include <nsm/model/receptance.h>
#include <nsm/model/shifted_factor.h>
#include <nsm/model/sturm_sequence.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace nsm
{
  namespace
  {
    std::string pole_message(const double omega)
    {
      std::ostringstream msg;
      msg.precision(17);
      msg << "K - w^2 M is singular at w = " << omega
          << ": w is a clamped-free eigenfrequency (a pole of gamma)";
      return msg.str();
    }
  } // namespace

  Receptance::Receptance(const Discretisation    &discretisation,
                         const ReceptanceParameters &params,
                         const double             omega_max)
    : discretisation_(discretisation)
    , method_(params.method)
    , pencil_(discretisation, EndCondition::clamped_free)
  {
    if (method_ == ReceptanceMethod::modal)
      {
        const bool full_basis = params.modes == 0 || params.modes >= unsigned(pencil_.finite);
        // The split needs a band (omega_max^2 > 0: a band of 1e-308 is
        // none) with modes beyond it.
        if (full_basis && omega_max * omega_max > 0 &&
            count_eigenvalues_below(pencil_, far_ratio * omega_max * omega_max) < pencil_.finite)
          split_far_modes(omega_max);
        else
          {
            modal_ = compute_spectrum(discretisation, EndCondition::clamped_free, params.modes,
                                      /*with_contact_residues=*/true);
            // Without inertia at the contact DoF even every finite mode
            // leaves out gamma's limit at infinite frequency: a constant,
            // whose slope in w^2 is zero (round-off, scaled by w^2, would
            // grow without bound).
            if (!full_basis || pencil_.finite < pencil_.n)
              truncated_basis_remainder();
            if (full_basis && pencil_.finite < pencil_.n)
              remainder_.resize(1);
          }
      }
    // The poles counted for the phase angle are those of the gamma evaluated:
    // a truncated modal basis has none beyond its last mode.
    if (method_ == ReceptanceMethod::modal)
      {
        for (const double l : modal_.eigenvalues)
          if (l <= omega_max * omega_max)
            poles_.push_back(l);
      }
    else
      poles_ = eigenvalues_below(pencil_, omega_max);
  }

  void Receptance::truncated_basis_remainder()
  {
    // The modes left out (beyond a truncated basis, or the infinite one of a
    // contact DoF without inertia) respond quasi-statically; their gamma(0)
    // and gamma'(0) come from one direct solve at w = 0.
    const ReceptanceValue exact = direct_value(0.0);
    remainder_                  = {exact.gamma, exact.dgamma_domega2};
    for (unsigned int j = 0; j < modal_.eigenvalues.size(); ++j)
      {
        const double l = modal_.eigenvalues[j];
        remainder_[0] -= modal_.contact_residues[j] / l;
        remainder_[1] -= modal_.contact_residues[j] / (l * l);
      }
  }

  void Receptance::split_far_modes(const double omega_max)
  {
    // The modes with w_j >= 4 omega_max are summed once as the power series
    // sum_m w^2m sum_j r_j / w_j^(2m + 2) in w^2 / w_j^2 <= 1/16, with enough
    // terms to reach the machine precision relative to their static share. On
    // the paper's mesh (4000 modes, M = 40, W <= 2.2) about 110 modes are left
    // to sum per frequency, and only those are computed.
    const unsigned int terms =
      std::ceil(std::log(std::numeric_limits<double>::epsilon()) / std::log(1 / far_ratio));
    series_limit_      = omega_max * omega_max;
    const double upper = far_ratio * series_limit_;
    modal_             = modes_below(pencil_, upper);
    remainder_         = far_mode_series(pencil_, modal_, upper, series_limit_, terms);
  }

  ReceptanceValue Receptance::operator()(const double omega) const
  {
    const double sigma = omega * omega;
    // Beyond the band of the far-mode series only a direct solve holds
    // every mode.
    if (is_modal_sum(omega))
      {
        ReceptanceValue value = remainder(sigma);
        for (unsigned int j = 0; j < modal_.eigenvalues.size(); ++j)
          {
            const double distance = modal_.eigenvalues[j] - sigma;
            if (distance == 0)
              throw NumericalError(pole_message(omega));
            const double term = modal_.contact_residues[j] / distance;
            value.gamma += term;
            value.dgamma_domega2 += term / distance;
          }
        return value;
      }
    return direct_value(omega);
  }

  bool Receptance::is_modal_sum(const double omega) const
  {
    return method_ == ReceptanceMethod::modal && omega * omega <= series_limit_;
  }

  ReceptanceValue Receptance::remainder(const double sigma) const
  {
    ReceptanceValue value{0, 0};
    for (unsigned int m = remainder_.size(); m-- > 0;)
      {
        value.gamma = value.gamma * sigma + remainder_[m];
        if (m > 0)
          value.dgamma_domega2 = value.dgamma_domega2 * sigma + m * remainder_[m];
      }
    return value;
  }

  ReceptanceValue Receptance::direct_value(const double omega) const
  {
    const dealii::Vector<double> h = field(omega);
    dealii::Vector<double>       mh(h.size());
    discretisation_.mass().vmult(mh, h);
    return {h[discretisation_.contact_dof()], h * mh};
  }

  dealii::Vector<double> Receptance::field(const double omega) const
  {
    // The clamped DoF's row of K - w^2 M is its diagonal alone: h = 0 there,
    // and the free DoFs' band holds the rest.
    ShiftedFactor<double> factor(pencil_);
    factor.factor(omega * omega);
    if (factor.singular())
      throw NumericalError(pole_message(omega));
    std::vector<double> x(pencil_.n, 0.0);
    x[pencil_.contact_row] = 1.0;
    factor.solve(x);
    dealii::Vector<double> h(discretisation_.n_dofs());
    for (int i = 0; i < pencil_.n; ++i)
      h[pencil_.dofs[i]] = x[i];
    for (const double v : h)
      if (!std::isfinite(v))
        throw NumericalError(std::isfinite(omega * omega * discretisation_.mass().linfty_norm()) ?
                               pole_message(omega) :
                               "w^2 M overflows at w = " + std::to_string(omega));
    return h;
  }

  unsigned int Receptance::poles_below(const double omega) const
  {
    return std::lower_bound(poles_.begin(), poles_.end(), omega * omega) -
           poles_.begin();
  }
} // namespace nsm
