// References for the clamped-free pencil (K, M) in long double (64-bit
// mantissa, 2000 times less rounding than double): the pencil's entries are
// the doubles assembled, so these are the same discrete problem's values.
#pragma once

#include <nsm/model/banded_pencil.h>

#include <algorithm>
#include <vector>

namespace extended
{
  /// K - sigma M = L D L^T without pivoting, row by row in the band.
  struct Factor
  {
    Factor(const nsm::BandedPencil &p, const long double sigma)
      : b(p.bandwidth)
      , l(std::size_t(p.n) * (b + 1), 0)
      , d(p.n)
    {
      for (int i = 0; i < p.n; ++i)
        for (int j = std::max(0, i - b); j <= i; ++j)
          {
            const std::size_t entry = (b + j - i) + std::size_t(i) * (b + 1);
            long double       s     = p.k[entry] - sigma * p.m[entry];
            for (int k = std::max(0, i - b); k < j; ++k)
              s -= L(i, k) * d[k] * L(j, k);
            if (j < i)
              L(i, j) = s / d[j];
            else
              d[i] = s == 0 ? 1e-40L : s;
          }
    }
    long double &L(const int i, const int k) { return l[std::size_t(i) * (b + 1) + (k - i + b)]; }

    int                      b;
    std::vector<long double> l, d;
  };

  /// Eigenvalues below sigma: the negative pivots (Sylvester's law of inertia).
  inline int count_below(const nsm::BandedPencil &p, const long double sigma)
  {
    const Factor f(p, sigma);
    return std::count_if(f.d.begin(), f.d.end(), [](const long double v) { return v < 0; });
  }

  /// gamma = e_L^T (K - sigma M)^{-1} e_L and gamma' = h^T M h. With the
  /// contact DoF last (asserted by the caller), L^{-1} e_L = e_L, so
  /// h = L^{-T} e_L / d_L.
  inline std::pair<long double, long double> gamma(const nsm::BandedPencil &p, const long double sigma)
  {
    Factor                   f(p, sigma);
    std::vector<long double> h(p.n, 0);
    for (int i = p.n - 1; i >= 0; --i)
      {
        h[i] = i == p.n - 1 ? 1 / f.d[i] : 0;
        for (int k = i + 1; k <= std::min(p.n - 1, i + f.b); ++k)
          h[i] -= f.L(k, i) * h[k];
      }
    long double mass = 0;
    for (int j = 0; j < p.n; ++j)
      for (int i = std::max(0, j - p.bandwidth); i <= j; ++i)
        mass += (i == j ? 1 : 2) * h[i] * p.m[(p.bandwidth + i - j) + std::size_t(j) * (p.bandwidth + 1)] * h[j];
    return {h[p.n - 1], mass};
  }
} // namespace extended
