#include <nsm/model/damped_receptance.h>

#include <nsm/base/errors.h>

#include <algorithm>
#include <string>

namespace nsm
{
  DampedReceptance::DampedReceptance(const Receptance        &receptance,
                                     const DampingParameters &damping,
                                     const LoadModes         *load)
    : receptance_(receptance)
    , load_(load)
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
    return dissipation_sum(receptance_.modes().contact_residues, omega);
  }

  double DampedReceptance::dissipation_sum(const std::vector<double> &weights, const double omega) const
  {
    const double      sigma = omega * omega;
    const ModalData  &modes = receptance_.modes();
    double            sum   = 0;
    for (unsigned int j = 0; j < modes.eigenvalues.size(); ++j)
      sum += weights[j] * coefficients_[j] * sigma /
             std::norm(std::complex<double>(modes.eigenvalues[j] - sigma, coefficients_[j] * omega));
    return sum;
  }

  bool DampedReceptance::drives_at(const double omega) const
  {
    return !load_ || receptance_.is_modal_sum(omega);
  }

  DampedReceptance::Value DampedReceptance::modal_sum(const std::vector<double>   &weights,
                                                      const std::array<double, 2> &far,
                                                      const double                 omega) const
  {
    if (!receptance_.is_modal_sum(omega))
      throw NumericalError("the distributed drive at W = " + std::to_string(omega) +
                           " lies beyond the receptance's modal band");
    const double         sigma = omega * omega;
    const ModalData     &modes = receptance_.modes();
    std::complex<double> gamma = far[0] + far[1] * sigma, slope = 2 * omega * far[1];
    for (unsigned int j = 0; j < modes.eigenvalues.size(); ++j)
      {
        const std::complex<double> d(modes.eigenvalues[j] - sigma, coefficients_[j] * omega);
        gamma += weights[j] / d;
        slope += weights[j] * std::complex<double>(2 * omega, -coefficients_[j]) / (d * d);
      }
    return {gamma, slope};
  }

  double DampedReceptance::energy_sum(const std::vector<double>   &weights,
                                      const std::array<double, 2> &far,
                                      const double                 omega) const
  {
    // far + 2 w^2 far' of far(w^2) = c_0 + c_1 w^2, as energy_factor's.
    const double     sigma = omega * omega;
    const ModalData &modes = receptance_.modes();
    double           sum   = far[0] + 3 * far[1] * sigma;
    for (unsigned int j = 0; j < modes.eigenvalues.size(); ++j)
      sum += weights[j] * (modes.eigenvalues[j] + sigma) /
             std::norm(std::complex<double>(modes.eigenvalues[j] - sigma, coefficients_[j] * omega));
    return sum;
  }

  DampedReceptance::Value DampedReceptance::drive(const double omega) const
  {
    return load_ ? modal_sum(load_->cross, load_->cross_far, omega) : value(omega);
  }

  DampedReceptance::DriveFactors DampedReceptance::drive_energy_factors(const double omega) const
  {
    if (!load_)
      {
        const double factor = energy_factor(omega);
        return {factor, factor};
      }
    return {energy_sum(load_->cross, load_->cross_far, omega), energy_sum(load_->self, load_->self_far, omega)};
  }

  DampedReceptance::DriveFactors DampedReceptance::drive_dissipation_factors(const double omega) const
  {
    if (!load_)
      {
        const double factor = dissipation_factor(omega);
        return {factor, factor};
      }
    return {dissipation_sum(load_->cross, omega), dissipation_sum(load_->self, omega)};
  }

  std::complex<double> DampedReceptance::drive_self(const double omega) const
  {
    return load_ ? modal_sum(load_->self, load_->self_far, omega).gamma : value(omega).gamma;
  }

  const std::vector<double> &DampedReceptance::drive_weights() const
  {
    return load_ ? load_->cross : receptance_.modes().contact_residues;
  }

  DampedReceptance::DriveFactors DampedReceptance::drive_far_static() const
  {
    if (!load_)
      {
        const double share = receptance_.remainder(0).gamma;
        return {share, share};
      }
    return {load_->cross_far[0], load_->self_far[0]};
  }
} // namespace nsm
