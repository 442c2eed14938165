// A few modes of the pencil (K, M), and what the modes above a bound add to
// the receptance, without the whole spectrum: on the paper's mesh (4000
// DoFs) 112 modes lie below the band's bound, and an O(n^2) band reduction
// to find all 4000 eigenvalues costs more than everything else.
#pragma once

#include <nsm/model/banded_pencil.h>

#include <vector>

namespace nsm
{
  struct ModalData
  {
    /// Eigenvalues w_j^2, ascending.
    std::vector<double> eigenvalues;
    /// phi_j(L)^2 of the mass-normalised modes (clamped-free only): the
    /// residues of the receptance, gamma(w) = sum_j r_j / (w_j^2 - w^2).
    std::vector<double> contact_residues;
  };

  /// Every eigenvalue lambda_j < upper of the clamped-free pencil, ascending,
  /// with its residue phi_j(L)^2. Each lambda_j is bracketed alone by Sturm
  /// counts (the inertia of K - sigma M) and found by Newton's method on
  /// 1/gamma, whose simple zeros are the poles of gamma; phi_j then comes from
  /// inverse iteration, which tells apart nearly equal eigenvalues (a mode
  /// confined to a small cell) where 1/gamma cannot.
  ModalData modes_below(const BandedPencil &clamped_free, double upper);

  /// The mass-normalised mode of the eigenvalue `lambda` (to working
  /// precision) of the pencil, on its rows (its sign arbitrary): inverse
  /// iteration at lambda, as `modes_below` finds the residues.
  std::vector<double> mode_shape(const BandedPencil &pencil, double lambda);

  /// The lowest `count` eigenvalues of any pencil, as in modes_below with the
  /// last row for the contact row (a bar's modes do not vanish next to its
  /// end; where one does, the Sturm counts find it), without residues. About
  /// 3 band LUs and 2 counts per eigenvalue: cheaper than LAPACK's band
  /// reduction for count < n / (10 p).
  std::vector<double> lowest_eigenvalues(const BandedPencil &pencil, int count);

  /// Taylor coefficients c_m (m < terms) in w^2 of the sum over the modes
  /// above `upper` of r_j / (lambda_j - w^2), for `near` = modes_below(upper).
  /// They are those of gamma - sum_near, analytic in |w^2| < upper, from its
  /// values on a circle in the complex w^2 plane (one complex band solve per
  /// point): no far mode is computed.
  std::vector<double> far_mode_series(const BandedPencil &clamped_free,
                                      const ModalData    &near,
                                      double              upper,
                                      double              limit,
                                      unsigned int        terms);
} // namespace nsm
