// The receptance gamma(w) = e_N^T (K - w^2 M)^{-1} e_N of the contact DoF,
// by a sparse direct solve per frequency or by the modal sum.
#pragma once

#include <nsm/discretisation.h>
#include <nsm/spectrum.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace nsm
{
  struct ReceptanceValue
  {
    double gamma;          ///< e_N^T h
    double dgamma_domega2; ///< h^T M h = d gamma / d(w^2)
  };

  class Receptance
  {
  public:
    /// `omega_max`: the largest frequency this receptance will be asked for;
    /// the poles below it are counted for the phase angle.
    Receptance(const Discretisation      &discretisation,
               const Scene::Receptance   &params,
               double                     omega_max);

    ReceptanceValue operator()(double omega) const;

    /// h(w) = (K - w^2 M)^{-1} e_N on the whole mesh (UMFPACK).
    dealii::Vector<double> field(double omega) const;

    /// Number of poles of this gamma strictly below omega (for the modal
    /// method, those of its basis).
    unsigned int poles_below(double omega) const;

    /// Clamped-free eigenvalues w_j^2 up to omega_max.
    const std::vector<double> &poles() const { return poles_; }


  private:
    /// gamma = h_N and h^T M h from one sparse solve.
    ReceptanceValue direct_value(double omega) const;

    const Discretisation &discretisation_;
    ReceptanceMethod      method_;
    std::vector<double>   poles_;
    ModalData             modal_;
    double                static_remainder_  = 0; ///< gamma(0) minus the truncated sum
    double                dynamic_remainder_ = 0; ///< gamma'(0) minus its truncated sum
  };
} // namespace nsm
