#include <nsm/base/band_cholesky.h>
#include <nsm/base/errors.h>
#include <nsm/base/assertions.h>

#include <algorithm>
#include <cstdlib>

extern "C"
{
  void dpbtrf_(const char *, const int *, const int *, double *, const int *, int *, std::size_t);
  void dpbtrs_(const char *, const int *, const int *, const int *, const double *, const int *,
               double *, const int *, int *, std::size_t);
}

namespace nsm
{
  BandCholesky::BandCholesky(const dealii::SparseMatrix<double> &matrix)
    : n_(matrix.m())
  {
    for (int i = 0; i < n_; ++i)
      for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
        bandwidth_ = std::max(bandwidth_, std::abs(int(e->column()) - i));
    const int ld = bandwidth_ + 1;
    factor_.assign(std::size_t(ld) * n_, 0.0);
    for (int i = 0; i < n_; ++i)
      for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
        if (const int j = e->column(); j >= i)
          factor_[(bandwidth_ + i - j) + std::size_t(j) * ld] = e->value();
    int info = 0;
    dpbtrf_("U", &n_, &bandwidth_, factor_.data(), &ld, &info, 1);
    if (info != 0)
      throw NumericalError("band Cholesky: the matrix is not positive definite");
  }

  void BandCholesky::solve(dealii::Vector<double> &x) const
  {
    const int ld = bandwidth_ + 1, one = 1;
    int       info = 0;
    AssertDimension(x.size(), static_cast<unsigned int>(n_));
    dpbtrs_("U", &n_, &bandwidth_, &one, factor_.data(), &ld, x.data(), &n_, &info, 1);
  }
} // namespace nsm
