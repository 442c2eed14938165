// LU factors with partial pivoting of K - sigma M on the band of the free
// DoFs, for a real or complex shift, reused across shifts: the eigensolvers'
// Newton and inverse-iteration steps, the far modes' circle, and the direct
// receptance's solves.
#pragma once

#include <nsm/model/banded_pencil.h>

#include <complex>
#include <vector>

namespace nsm
{
  /// In LAPACK's general band layout (U gains b superdiagonals from the row
  /// swaps). Written out rather than LAPACK's dgbtrf, whose calls per column
  /// cost more than the arithmetic at bandwidth p = 1.
  template <typename Scalar>
  class ShiftedFactor
  {
  public:
    explicit ShiftedFactor(const BandedPencil &pencil);
    /// Factors K - sigma M, reusing the storage (a fresh 100 kB block per
    /// shift would cost more in page faults than the arithmetic). A pivot
    /// that is exactly zero (sigma an eigenvalue to working precision) is
    /// replaced by one at the rounding of the matrix, as LAPACK's dstein
    /// does for inverse iteration; singular() tells.
    void factor(Scalar sigma);
    bool singular() const { return singular_; }
    /// x <- (K - sigma M)^{-1} x.
    void solve(std::vector<Scalar> &x) const;

  private:
    // Entry (i, j) sits at row 2b + i - j of column j, ld = 3b + 1.
    Scalar       &at(const int i, const int j) { return lu_[3 * std::size_t(b_) * j + 2 * b_ + i]; }
    const Scalar &at(const int i, const int j) const { return lu_[3 * std::size_t(b_) * j + 2 * b_ + i]; }
    void          eliminate(int j);

    const BandedPencil &p_;
    int                 n_, b_;
    std::vector<Scalar> lu_;
    std::vector<int>    pivots_;
    std::vector<Scalar> inverse_pivots_; ///< solve() multiplies: no division chain
    double              scale_    = 0;   ///< largest |entry| of K - sigma M
    bool                singular_ = false;
  };
} // namespace nsm
