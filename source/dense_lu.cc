#include <nsm/dense_lu.h>

#include <cmath>
#include <utility>
#include <vector>

namespace nsm
{
  bool dense_solve(const int n, double *a, double *x)
  {
    // Right-looking elimination: the update of each column is an axpy on
    // contiguous memory, which the compiler vectorises.
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
        for (int j = k + 1; j < n; ++j)
          if (const double f = at(k, j); f != 0)
            for (int i = k + 1; i < n; ++i)
              at(i, j) -= at(i, k) * f;
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
