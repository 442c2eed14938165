// The receptance gamma(w) = e_N^T (K - w^2 M)^{-1} e_N of the contact DoF,
// by a sparse direct solve per frequency or by the modal sum.
#pragma once

#include <nsm/model/discretisation.h>
#include <nsm/model/spectrum.h>
#include <nsm/scene/receptance_parameters.h>

#include <deal.II/lac/vector.h>

#include <limits>
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
               const ReceptanceParameters   &params,
               double                     omega_max);

    ReceptanceValue operator()(double omega) const;

    /// h(w) = (K - w^2 M)^{-1} e_N on the whole mesh (band LU, ShiftedFactor).
    dealii::Vector<double> field(double omega) const;

    /// Number of poles of this gamma strictly below omega (for the modal
    /// method, those of its basis).
    unsigned int poles_below(double omega) const;

    /// Clamped-free eigenvalues w_j^2 up to omega_max.
    const std::vector<double> &poles() const { return poles_; }

    /// Whether gamma(omega) is the modal sum over modes() plus remainder():
    /// the modal method, within the far-mode series' band.
    bool is_modal_sum(double omega) const;
    /// The modes summed one by one (the modal method).
    const ModalData &modes() const { return modal_; }
    /// What the modes not in modes() add at w^2 = sigma (a power series in
    /// sigma), with its slope in sigma.
    ReceptanceValue remainder(double sigma) const;
    /// K and M on the free DoFs, as the receptance reads them.
    const BandedPencil &pencil() const { return pencil_; }


  private:
    /// A truncated modal basis (Receptance/Modes): the modes left out as a
    /// static and a first-order dynamic correction.
    void truncated_basis_remainder();
    /// A full basis: the modes far above omega_max summed once as a series.
    void split_far_modes(double omega_max);
    /// gamma = h_N and h^T M h from one sparse solve.
    ReceptanceValue direct_value(double omega) const;

    const Discretisation &discretisation_;
    ReceptanceMethod      method_;
    /// K and M on the free DoFs, read once: the eigensolvers' and every
    /// direct solve's (a receptance is a snapshot of its discretisation).
    BandedPencil          pencil_;
    std::vector<double>   poles_;
    ModalData             modal_;
    /// Taylor coefficients in w^2 of the modes not summed per frequency.
    std::vector<double> remainder_;
    /// The far modes' series is summed for w^2 <= series_limit_, where they
    /// lie beyond far_ratio * series_limit_; beyond, gamma is a direct solve.
    static constexpr double far_ratio = 16;
    /// w^2 up to which remainder_ holds.
    double series_limit_ = std::numeric_limits<double>::infinity();
  };
} // namespace nsm
