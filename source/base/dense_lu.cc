#include <nsm/base/dense_lu.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace nsm
{
  namespace
  {
    /// The rank-1 update of the trailing columns, a[k+1:, j] -= a[k+1:, k] a[k, j]:
    /// axpys on contiguous columns, built for AVX2 and FMA where the processor
    /// has them (GCC function multiversioning) and for plain x86-64 elsewhere.
    __attribute__((target_clones("arch=x86-64-v3", "default"))) void
    eliminate(const int n, const int k, double *a)
    {
      const double *__restrict multipliers = a + std::size_t(k) * n;
      for (int j = k + 1; j < n; ++j)
        {
          double *__restrict column = a + std::size_t(j) * n;
          const double f            = column[k];
          if (f != 0)
            for (int i = k + 1; i < n; ++i)
              column[i] -= multipliers[i] * f;
        }
    }
  } // namespace

  bool dense_solve(const int n, double *a, double *x)
  {
    auto             at = [a, n](const int i, const int j) -> double & { return a[i + std::size_t(j) * n]; };
    std::vector<int> pivots(n);
    for (int k = 0; k < n; ++k)
      {
        int pivot = k;
        for (int i = k + 1; i < n; ++i)
          if (std::abs(at(i, k)) > std::abs(at(pivot, k)))
            pivot = i;
        if (at(pivot, k) == 0)
          return false;
        pivots[k] = pivot;
        if (pivot != k)
          for (int j = 0; j < n; ++j)
            std::swap(at(k, j), at(pivot, j));
        const double inverse = 1 / at(k, k);
        for (int i = k + 1; i < n; ++i)
          at(i, k) *= inverse;
        eliminate(n, k, a);
      }
    // Whole rows were swapped (the multipliers too): P A = L U, so P x first.
    for (int k = 0; k < n; ++k)
      std::swap(x[k], x[pivots[k]]);
    for (int k = 0; k < n; ++k)
      for (int i = k + 1; i < n; ++i)
        x[i] -= at(i, k) * x[k];
    for (int k = n - 1; k >= 0; --k)
      {
        x[k] /= at(k, k);
        for (int i = 0; i < k; ++i)
          x[i] -= at(i, k) * x[k];
      }
    return true;
  }
} // namespace nsm
