#include <nsm/model/damped_receptance.h>

namespace nsm
{
  DampedReceptance::DampedReceptance(const Receptance &receptance, const DampingParameters &damping)
    : receptance_(receptance)
  {
    for (const double l : receptance.modes().eigenvalues)
      coefficients_.push_back(damping.coefficient(l));
  }

  std::complex<double> DampedReceptance::operator()(const double omega) const
  {
    const double         sigma = omega * omega;
    const ModalData     &modes = receptance_.modes();
    const bool           modal = receptance_.is_modal_sum(omega);
    std::complex<double> gamma = modal ? receptance_.remainder(sigma).gamma : receptance_(omega).gamma;
    for (unsigned int j = 0; j < modes.eigenvalues.size(); ++j)
      {
        const double distance = modes.eigenvalues[j] - sigma;
        gamma += modes.contact_residues[j] / std::complex<double>(distance, coefficients_[j] * omega);
        if (!modal)
          gamma -= modes.contact_residues[j] / distance;
      }
    return gamma;
  }

  double DampedReceptance::energy_factor(const double omega) const
  {
    const double          sigma = omega * omega;
    const ModalData      &modes = receptance_.modes();
    const bool            modal = receptance_.is_modal_sum(omega);
    const ReceptanceValue rest  = modal ? receptance_.remainder(sigma) : receptance_(omega);
    double                sum   = rest.gamma + 2 * sigma * rest.dgamma_domega2;
    for (unsigned int j = 0; j < modes.eigenvalues.size(); ++j)
      {
        const double distance = modes.eigenvalues[j] - sigma;
        const double weight   = modes.contact_residues[j] * (modes.eigenvalues[j] + sigma);
        sum += weight / std::norm(std::complex<double>(distance, coefficients_[j] * omega));
        if (!modal)
          sum -= weight / (distance * distance);
      }
    return sum;
  }

  double DampedReceptance::dissipation_factor(const double omega) const
  {
    const double      sigma = omega * omega;
    const ModalData  &modes = receptance_.modes();
    double            sum   = 0;
    for (unsigned int j = 0; j < modes.eigenvalues.size(); ++j)
      sum += modes.contact_residues[j] * coefficients_[j] * sigma /
             std::norm(std::complex<double>(modes.eigenvalues[j] - sigma, coefficients_[j] * omega));
    return sum;
  }
} // namespace nsm
