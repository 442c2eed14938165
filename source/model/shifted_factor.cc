#include <nsm/model/shifted_factor.h>
#include <nsm/base/assertions.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace nsm
{
  namespace
  {
    /// A pivot's size as LAPACK measures it (|Re| + |Im|: no hypot).
    double size(const double v) { return std::abs(v); }
    double size(const std::complex<double> v) { return std::abs(v.real()) + std::abs(v.imag()); }
  } // namespace

  template <typename Scalar>
  ShiftedFactor<Scalar>::ShiftedFactor(const BandedPencil &pencil)
    : p_(pencil)
    , n_(pencil.n)
    , b_(pencil.bandwidth)
    , lu_(std::size_t(3 * pencil.bandwidth + 1) * pencil.n)
    , pivots_(pencil.n)
    , inverse_pivots_(pencil.n)
  {}

  template <typename Scalar>
  void ShiftedFactor<Scalar>::factor(const Scalar sigma)
  {
    std::fill(lu_.begin(), lu_.end(), Scalar(0));
    scale_    = 0;
    singular_ = false;
    for (int j = 0; j < n_; ++j)
      for (int i = std::max(0, j - b_); i <= j; ++i)
        {
          const std::size_t entry = p_.index(i, j);
          at(i, j) = at(j, i) = p_.k[entry] - sigma * p_.m[entry];
          scale_              = std::max(scale_, size(at(i, j)));
        }
    for (int j = 0; j < n_; ++j)
      eliminate(j);
    for (int j = 0; j < n_; ++j)
      inverse_pivots_[j] = Scalar(1) / at(j, j);
  }

  template <typename Scalar>
  void ShiftedFactor<Scalar>::solve(std::vector<Scalar> &x) const
  {
    AssertDimension(x.size(), static_cast<std::size_t>(n_));
    for (int j = 0; j < n_; ++j)
      {
        std::swap(x[j], x[pivots_[j]]);
        for (int i = j + 1; i <= std::min(n_ - 1, j + b_); ++i)
          x[i] -= at(i, j) * x[j];
      }
    for (int j = n_ - 1; j >= 0; --j)
      {
        x[j] *= inverse_pivots_[j];
        for (int i = std::max(0, j - 2 * b_); i < j; ++i)
          x[i] -= at(i, j) * x[j];
      }
  }

  template <typename Scalar>
  void ShiftedFactor<Scalar>::eliminate(const int j)
  {
    const int last = std::min(n_ - 1, j + b_), right = std::min(n_ - 1, j + 2 * b_);
    int       pivot = j;
    for (int i = j + 1; i <= last; ++i)
      if (size(at(i, j)) > size(at(pivot, j)))
        pivot = i;
    pivots_[j] = pivot;
    if (at(pivot, j) == Scalar(0))
      {
        at(pivot, j) = std::numeric_limits<double>::epsilon() * scale_;
        singular_    = true;
      }
    if (pivot != j)
      for (int k = j; k <= right; ++k)
        std::swap(at(j, k), at(pivot, k));
    for (int i = j + 1; i <= last; ++i)
      at(i, j) /= at(j, j);
    for (int k = j + 1; k <= right; ++k)
      for (int i = j + 1; i <= last; ++i)
        at(i, k) -= at(i, j) * at(j, k);
  }

  template class ShiftedFactor<double>;
  template class ShiftedFactor<std::complex<double>>;
} // namespace nsm
