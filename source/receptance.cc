#include <nsm/receptance.h>

#include <deal.II/lac/sparse_direct.h>

#include <algorithm>
#include <cmath>
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
        if (modal_.eigenvalues.size() < discretisation.free_dofs(false).size())
          {
            // Truncated basis: the modes left out respond quasi-statically;
            // their gamma(0) and gamma'(0) come from one direct solve at w = 0.
            const ReceptanceValue exact = direct_value(0.0);
            static_remainder_  = exact.gamma;
            dynamic_remainder_ = exact.dgamma_domega2;
            for (unsigned int j = 0; j < modal_.eigenvalues.size(); ++j)
              {
                const double l = modal_.eigenvalues[j];
                static_remainder_ -= modal_.contact_residues[j] / l;
                dynamic_remainder_ -= modal_.contact_residues[j] / (l * l);
              }
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
      poles_ = eigenvalues_below(discretisation, EndCondition::clamped_free, omega_max);
  }

  ReceptanceValue Receptance::operator()(const double omega) const
  {
    const double sigma = omega * omega;
    if (method_ == ReceptanceMethod::modal)
      {
        ReceptanceValue value{static_remainder_ + sigma * dynamic_remainder_,
                              dynamic_remainder_};
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
