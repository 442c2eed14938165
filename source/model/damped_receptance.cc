#include <nsm/model/damped_receptance.h>

#include <nsm/base/errors.h>
#include <nsm/base/vector_clones.h>

#include <algorithm>
#include <string>

namespace nsm
{
  namespace
  {
    /// The damped modal sums gamma += sum_j r_j / d_j and slope += sum_j r_j
    /// (2 w - i c_j) / d_j^2, d_j = l_j - w^2 + i c_j w, in real arithmetic
    /// (complex division checks for infinities per call), one division per
    /// mode, in a loop the compiler vectorises: the forced harmonic balance
    /// asks this M times per W of every Newton step. It is built for the
    /// plain x86-64 level only: a build per vector level (as weighted_sum's)
    /// sums in another order, and the last bits it changes decide whether
    /// two traces of a curve meet at a corner (measured: the seed bar's
    /// zeta = 0.001, F = 2e-5 curve of prm/forced.prm, whole with these
    /// sums, two stopped traces 0.003 of W apart with AVX-512's).
    void damped_sums(const int n, const double *residues, const double *eigenvalues, const double *damping,
                     const double omega, double sums[4])
    {
      const double sigma = omega * omega;
      double       gr = sums[0], gi = sums[1], sr = sums[2], si = sums[3];
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
      sums[0] = gr;
      sums[1] = gi;
      sums[2] = sr;
      sums[3] = si;
    }

    /// sum_j weights_j (l_j + w^2) / |d_j|^2 (energy) or sum_j weights_j c_j
    /// w^2 / |d_j|^2 (dissipation), for the measures of a point, built for
    /// each vector level (base/vector_clones.h).
    NSM_CLONES_AVX512_AVX2 double weighted_sum(const int n, const double *weights, const double *eigenvalues,
                                               const double *damping, const double omega, const bool energy)
    {
      const double sigma = omega * omega;
      double       sum   = 0;
#pragma omp simd reduction(+ : sum)
      for (int j = 0; j < n; ++j)
        {
          const double a = eigenvalues[j] - sigma, b = damping[j] * omega;
          sum += weights[j] * (energy ? eigenvalues[j] + sigma : damping[j] * sigma) / (a * a + b * b);
        }
      return sum;
    }
  } // namespace

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
    const double     sigma = omega * omega;
    const ModalData &modes = receptance_.modes();
    const bool       modal = receptance_.is_modal_sum(omega);
    const ReceptanceValue rest = modal ? receptance_.remainder(sigma) : receptance_(omega);
    const double    *residues = modes.contact_residues.data(), *eigenvalues = modes.eigenvalues.data();
    const int        n        = modes.eigenvalues.size();
    double           sums[4]  = {rest.gamma, 0, 2 * omega * rest.dgamma_domega2, 0};
    damped_sums(n, residues, eigenvalues, coefficients_.data(), omega, sums);
    if (!modal) // the direct solve holds the summed modes undamped: take them out
      for (int j = 0; j < n; ++j)
        {
          const double r = residues[j], a = eigenvalues[j] - sigma;
          sums[0] -= r / a;
          sums[2] -= 2 * omega * r / (a * a);
        }
    return {{sums[0], sums[1]}, {sums[2], sums[3]}};
  }

  double DampedReceptance::energy_factor(const double omega) const
  {
    const double          sigma = omega * omega;
    const ModalData      &modes = receptance_.modes();
    const bool            modal = receptance_.is_modal_sum(omega);
    const ReceptanceValue rest  = modal ? receptance_.remainder(sigma) : receptance_(omega);
    double                sum   = rest.gamma + 2 * sigma * rest.dgamma_domega2 +
                         weighted_sum(modes.eigenvalues.size(), modes.contact_residues.data(),
                                      modes.eigenvalues.data(), coefficients_.data(), omega, true);
    if (!modal) // the direct solve holds the summed modes undamped: take them out
      for (unsigned int j = 0; j < modes.eigenvalues.size(); ++j)
        {
          const double distance = modes.eigenvalues[j] - sigma;
          sum -= modes.contact_residues[j] * (modes.eigenvalues[j] + sigma) / (distance * distance);
        }
    return sum;
  }

  double DampedReceptance::dissipation_factor(const double omega) const
  {
    return dissipation_sum(receptance_.modes().contact_residues, omega);
  }

  double DampedReceptance::dissipation_sum(const std::vector<double> &weights, const double omega) const
  {
    const ModalData &modes = receptance_.modes();
    return weighted_sum(modes.eigenvalues.size(), weights.data(), modes.eigenvalues.data(), coefficients_.data(),
                        omega, false);
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
    const ModalData &modes   = receptance_.modes();
    double           sums[4] = {far[0] + far[1] * omega * omega, 0, 2 * omega * far[1], 0};
    damped_sums(modes.eigenvalues.size(), weights.data(), modes.eigenvalues.data(), coefficients_.data(), omega, sums);
    return {{sums[0], sums[1]}, {sums[2], sums[3]}};
  }

  double DampedReceptance::energy_sum(const std::vector<double>   &weights,
                                      const std::array<double, 2> &far,
                                      const double                 omega) const
  {
    // far + 2 w^2 far' of far(w^2) = c_0 + c_1 w^2, as energy_factor's.
    const double     sigma = omega * omega;
    const ModalData &modes = receptance_.modes();
    return far[0] + 3 * far[1] * sigma +
           weighted_sum(modes.eigenvalues.size(), weights.data(), modes.eigenvalues.data(), coefficients_.data(),
                        omega, true);
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
