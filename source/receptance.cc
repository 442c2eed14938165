#include <nsm/receptance.h>

#include <deal.II/lac/sparse_direct.h>

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
                         const Scene::Receptance &params,
                         const double             omega_max)
    : discretisation_(discretisation)
    , method_(params.method)
  {
    if (method_ == ReceptanceMethod::modal)
      {
        modal_ = compute_spectrum(discretisation,
                                  EndCondition::clamped_free,
                                  params.modes,
                                  /*with_contact_residues=*/true);
        summed_modes_ = modal_.eigenvalues.size();
        if (modal_.eigenvalues.size() < discretisation.free_dofs(false).size())
          truncated_basis_remainder();
        else
          split_far_modes(omega_max);
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
      poles_ = eigenvalues_below(discretisation, EndCondition::clamped_free, omega_max);
  }

  void Receptance::truncated_basis_remainder()
  {
    // The modes left out respond quasi-statically; their gamma(0) and
    // gamma'(0) come from one direct solve at w = 0.
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
    // the paper's mesh (4000 modes, M = 40, W <= 2.2) about 150 modes are left
    // to sum per frequency.
    const double       ratio = 16;
    const unsigned int terms = std::ceil(std::log(std::numeric_limits<double>::epsilon()) / std::log(1 / ratio));
    const std::vector<double> &l = modal_.eigenvalues;
    series_limit_                = omega_max * omega_max;
    const unsigned int near =
      std::lower_bound(l.begin(), l.end(), ratio * series_limit_) - l.begin();
    remainder_.assign(terms, 0.0);
    for (unsigned int j = near; j < l.size(); ++j)
      {
        double power = modal_.contact_residues[j] / l[j];
        for (double &coefficient : remainder_)
          {
            coefficient += power;
            power /= l[j];
          }
      }
    summed_modes_ = near;
  }

  ReceptanceValue Receptance::operator()(const double omega) const
  {
    const double sigma = omega * omega;
    if (method_ == ReceptanceMethod::modal)
      {
        // Beyond the band of the series every mode is summed.
        const bool         series = sigma <= series_limit_;
        const unsigned int summed = series ? summed_modes_ : modal_.eigenvalues.size();
        ReceptanceValue    value{0, 0};
        if (series)
          for (unsigned int m = remainder_.size(); m-- > 0;)
            {
              value.gamma = value.gamma * sigma + remainder_[m];
              if (m > 0)
                value.dgamma_domega2 = value.dgamma_domega2 * sigma + m * remainder_[m];
            }
        for (unsigned int j = 0; j < summed; ++j)
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

  ReceptanceValue Receptance::direct_value(const double omega) const
  {
    const dealii::Vector<double> h = field(omega);
    dealii::Vector<double>       mh(h.size());
    discretisation_.mass().vmult(mh, h);
    return {h[discretisation_.contact_dof()], h * mh};
  }

  dealii::Vector<double> Receptance::field(const double omega) const
  {
    dealii::SparseMatrix<double> shifted(
      discretisation_.stiffness().get_sparsity_pattern());
    shifted.copy_from(discretisation_.stiffness());
    shifted.add(-omega * omega, discretisation_.mass());

    dealii::SparseDirectUMFPACK solver;
    try
      {
        solver.factorize(shifted);
      }
    catch (const dealii::SparseDirectUMFPACK::ExcUMFPACKError &)
      {
        throw NumericalError(pole_message(omega));
      }
    dealii::Vector<double> h(discretisation_.n_dofs());
    h[discretisation_.contact_dof()] = 1.0;
    solver.solve(h);
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
