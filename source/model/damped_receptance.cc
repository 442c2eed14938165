#include <nsm/model/damped_receptance.h>

#include <algorithm>

namespace nsm
{
  DampedReceptance::DampedReceptance(const Receptance &receptance, const DampingParameters &damping)
    : receptance_(receptance)
  {
    for (const double l : receptance.modes().eigenvalues)
      coefficients_.push_back(damping.coefficient(l));
  }

  double DampedReceptance::slowest_decay() const
  {
    return coefficients_.empty() ? 0.0 : 0.5 * *std::min_element(coefficients_.begin(), coefficients_.end());
  }

  DampedReceptance::Value DampedReceptance::value(const double omega) const
  {
    // r / d and its slope r (2 w - i c) / d^2 with d = l - w^2 + i c w, in
    // real arithmetic (complex division checks for infinities per call),
    // one division per mode, in a loop the compiler vectorises (the forced
    // harmonic balance asks this M times per W of every Newton step).
    const double     sigma = omega * omega;
    const ModalData &modes = receptance_.modes();
    const bool       modal = receptance_.is_modal_sum(omega);
    const ReceptanceValue rest = modal ? receptance_.remainder(sigma) : receptance_(omega);
    const double    *residues = modes.contact_residues.data(), *eigenvalues = modes.eigenvalues.data();
    const double    *damping  = coefficients_.data();
    const int        n        = modes.eigenvalues.size();
    double gr = rest.gamma, gi = 0, sr = 2 * omega * rest.dgamma_domega2, si = 0;
#pragma omp simd reduction(+ : gr, gi, sr, si)
    for (int j = 0; j < n; ++j)
      {
        const double r = residues[j], a = eigenvalues[j] - sigma, b = damping[j] * omega;
        const double inverse = 1 / (a * a + b * b), qr = r * a * inverse, qi = -r * b * inverse; // r / d
        gr += qr;
        gi += qi;
        // (r / d) (2 w - i c) / d: (qr + i qi) (2 w - i c) (a - i b) / |d|^2
        const double pr = qr * 2 * omega + qi * damping[j], pi = qi * 2 * omega - qr * damping[j];
        sr += (pr * a + pi * b) * inverse;
        si += (pi * a - pr * b) * inverse;
      }
    if (!modal) // the direct solve holds the summed modes undamped: take them out
      for (int j = 0; j < n; ++j)
        {
          const double r = residues[j], a = eigenvalues[j] - sigma;
          gr -= r / a;
          sr -= 2 * omega * r / (a * a);
        }
    return {{gr, gi}, {sr, si}};
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
