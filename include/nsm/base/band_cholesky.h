// Cholesky factor of a symmetric positive definite sparse matrix whose DoFs
// are numbered into a narrow band (Cuthill-McKee), for repeated solves.
#pragma once

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace nsm
{
  class BandCholesky
  {
  public:
    /// Factors the matrix (LAPACK dpbtrf); throws NumericalError if it is not
    /// positive definite.
    explicit BandCholesky(const dealii::SparseMatrix<double> &matrix);

    /// x <- A^{-1} x (dpbtrs).
    void solve(dealii::Vector<double> &x) const;

  private:
    int                 n_ = 0, bandwidth_ = 0;
    std::vector<double> factor_; ///< upper band storage, (bandwidth + 1) x n
  };
} // namespace nsm
