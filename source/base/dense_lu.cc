#include <nsm/base/dense_lu.h>
#include <nsm/base/vector_clones.h>
#include <nsm/base/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace nsm
{
  namespace
  {
    /// The rank-1 update of the trailing columns, a[k+1:, j] -= a[k+1:, k] a[k, j]:
    /// axpys on contiguous columns, built for AVX-512, for AVX2 and FMA where
    /// the processor has them (GCC function multiversioning) and for plain
    /// x86-64 elsewhere; one portable build on other processors
    /// (base/vector_clones.h).
    NSM_CLONES_AVX512_AVX2 void
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

    /// Below this many unknowns (M < 96 in the cosine basis) the unblocked
    /// elimination is used. On random systems the panels are even with it
    /// at n = 81 and pay beyond (doc/studies.md's table), but on the harmonic
    /// balance's own Jacobians at n = 81 they do not: the authors' work at
    /// M = 80 (doc/log.md) takes 1.31 to 1.33 s in its HB stage with them,
    /// 1.26 to 1.28 s without.
    constexpr int blocked_from = 96;

    /// Partial pivoting's row for column k: the largest |a_ik|, i >= k, by a
    /// vectorised reduction, then its first row (the row a one-pass search
    /// picks); -1 if the column is zero there (A singular).
    int pivot_row(const int n, const int k, const double *column)
    {
      double largest = 0;
#pragma omp simd reduction(max : largest)
      for (int i = k; i < n; ++i)
        largest = std::max(largest, std::abs(column[i]));
      if (largest == 0)
        return -1;
      int pivot = k;
      while (std::abs(column[pivot]) != largest)
        ++pivot;
      return pivot;
    }

    /// Unblocked LU with partial pivoting, whole rows swapped.
    bool factor_unblocked(const int n, double *a, int *pivots)
    {
      auto at = [a, n](const int i, const int j) -> double & { return a[i + std::size_t(j) * n]; };
      for (int k = 0; k < n; ++k)
        {
          const int pivot = pivot_row(n, k, &at(0, k));
          if (pivot < 0)
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
      return true;
    }

    /// Columns factored together: the trailing matrix is updated once per
    /// block of this many pivots instead of once per pivot, so each of its
    /// entries is loaded and stored n / block times instead of n times.
    constexpr int block = 8;

    /// Vectors of `lanes` doubles, unaligned (a typedef's alignment would be
    /// lost as a template argument): eight (one AVX-512 register) for the
    /// AVX-512 build, four (one AVX2 register) for the others, where GCC
    /// keeps eight-double vectors in memory (doc/studies.md, "The Newton
    /// steps' LU").
    template <int lanes>
    struct Lanes;
    template <>
    struct Lanes<8>
    {
      typedef double vector __attribute__((vector_size(64), aligned(8)));
    };
    template <>
    struct Lanes<4>
    {
      typedef double vector __attribute__((vector_size(32), aligned(8)));
    };

    /// A22 -= L21 U12 for `blocks` vectors of rows from row i of columns c0
    /// and c1, held in registers through the block's `block` multiply-adds,
    /// each L21 load serving both columns.
    template <int lanes, int blocks>
    __attribute__((always_inline)) inline void update_rows(const int n, const int i, const double *l, const double *u0,
                                                          const double *u1, double *c0, double *c1, const bool pair)
    {
      typedef typename Lanes<lanes>::vector Vector;
      Vector                                a0[blocks], a1[blocks];
      for (int b = 0; b < blocks; ++b)
        a0[b] = *reinterpret_cast<const Vector *>(c0 + i + lanes * b),
        a1[b] = *reinterpret_cast<const Vector *>(c1 + i + lanes * b);
      for (int p = 0; p < block; ++p)
        for (int b = 0; b < blocks; ++b)
          {
            const Vector lp = *reinterpret_cast<const Vector *>(l + std::size_t(p) * n + i + lanes * b);
            a0[b] -= lp * u0[p], a1[b] -= lp * u1[p];
          }
      for (int b = 0; b < blocks; ++b)
        {
          *reinterpret_cast<Vector *>(c0 + i + lanes * b) = a0[b];
          if (pair)
            *reinterpret_cast<Vector *>(c1 + i + lanes * b) = a1[b];
        }
    }

    /// A22 -= L21 U12 for a whole block of pivots: two columns of A22 at a
    /// time, sixteen rows (then one vector's) per register pass. Every entry
    /// gets the same multiply-adds in the same order whatever the vector, so
    /// the builds' factors agree to the last bit.
    template <int lanes>
    __attribute__((always_inline)) inline void update_trailing_block(const int n, const int k0, double *a)
    {
      const int     first = k0 + block;
      const double *l     = a + std::size_t(k0) * n;
      for (int j = first; j < n; j += 2)
        {
          const bool pair = j + 1 < n;
          double    *c0 = a + std::size_t(j) * n, *c1 = pair ? c0 + n : c0;
          double     u0[block], u1[block];
          for (int p = 0; p < block; ++p)
            u0[p] = c0[k0 + p], u1[p] = pair ? c1[k0 + p] : 0.0;
          int i = first;
          for (; i + 16 <= n; i += 16)
            update_rows<lanes, 16 / lanes>(n, i, l, u0, u1, c0, c1, pair);
          for (; i + lanes <= n; i += lanes)
            update_rows<lanes, 1>(n, i, l, u0, u1, c0, c1, pair);
          for (; i < n; ++i)
            for (int p = 0; p < block; ++p)
              {
                const double lp = l[std::size_t(p) * n + i];
                c0[i] -= lp * u0[p];
                if (pair)
                  c1[i] -= lp * u1[p];
              }
        }
    }

    /// The last, narrower block of pivots: one pivot at a time.
    __attribute__((always_inline)) inline void update_trailing_narrow(const int n, const int k0, const int width,
                                                                     double *a)
    {
      for (int p = 0; p < width; ++p)
        {
          const double *l = a + std::size_t(k0 + p) * n;
          for (int j = k0 + width; j < n; ++j)
            {
              double      *c = a + std::size_t(j) * n;
              const double u = c[k0 + p];
              for (int i = k0 + width; i < n; ++i)
                c[i] -= l[i] * u;
            }
        }
    }

    /// The trailing update A22 -= L21 U12 of the block of `width` pivots from
    /// column k0 on vectors of `lanes` doubles.
    template <int lanes>
    __attribute__((always_inline)) inline void update_trailing_on(const int n, const int k0, const int width,
                                                                 double *a)
    {
      if (width == block)
        update_trailing_block<lanes>(n, k0, a);
      else
        update_trailing_narrow(n, k0, width, a);
    }

    /// Built for AVX-512 on eight-double vectors.
    NSM_TARGET_AVX512 void update_trailing_avx512(const int n, const int k0, const int width, double *a)
    {
      update_trailing_on<8>(n, k0, width, a);
    }

    /// On four-double vectors, built for AVX2 and FMA where the processor has
    /// them (GCC function multiversioning), and for plain x86-64.
    NSM_CLONES_AVX2 void update_trailing_avx2(const int n, const int k0, const int width, double *a)
    {
      update_trailing_on<4>(n, k0, width, a);
    }

    /// The trailing update with the vectors asked for (LuVectors).
    void update_trailing(const int n, const int k0, const int width, double *a, const LuVectors vectors)
    {
      static const bool avx512 = nsm_has_avx512();
      if (avx512 && vectors == LuVectors::widest)
        update_trailing_avx512(n, k0, width, a);
      else
        update_trailing_avx2(n, k0, width, a);
    }

    /// LU with partial pivoting of the panel of columns k0..k0+width-1 (rows
    /// k0..), whole rows swapped; then U12, the panel's rows right of it.
    NSM_CLONES_AVX512_AVX2 bool factor_panel(const int n, const int k0, const int width, double *a, int *pivots)
    {
      auto at = [a, n](const int i, const int j) -> double & { return a[i + std::size_t(j) * n]; };
      for (int k = k0; k < k0 + width; ++k)
        {
          const int pivot = pivot_row(n, k, &at(0, k));
          if (pivot < 0)
            return false;
          pivots[k] = pivot;
          if (pivot != k)
            for (int j = k0; j < k0 + width; ++j)
              std::swap(at(k, j), at(pivot, j));
          const double inverse = 1 / at(k, k);
          for (int i = k + 1; i < n; ++i)
            at(i, k) *= inverse;
          for (int j = k + 1; j < k0 + width; ++j)
            {
              const double f = at(k, j);
              for (int i = k + 1; i < n; ++i)
                at(i, j) -= at(i, k) * f;
            }
        }
      // The panel's interchanges in the other columns, one column at a time
      // (whole rows swapped: the multipliers left of the panel too).
      for (int j = 0; j < n; ++j)
        if (j < k0 || j >= k0 + width)
          for (int k = k0; k < k0 + width; ++k)
            std::swap(at(k, j), at(pivots[k], j));
      // U12 = L11^-1 A12, L11 (unit lower) copied out of the strided panel.
      double unit_lower[block][block];
      for (int k = 0; k < width; ++k)
        for (int i = 0; i < width; ++i)
          unit_lower[k][i] = at(k0 + i, k0 + k);
      // Four columns side by side: the substitution's chain (each u_k waits
      // for the rows above it) runs on four independent columns at once.
      constexpr int columns = 4;
      for (int j = k0 + width; j < n; j += columns)
        {
          const int count = std::min(columns, n - j);
          double    u[block][columns] = {};
          for (int c = 0; c < count; ++c)
            for (int i = 0; i < width; ++i)
              u[i][c] = at(k0 + i, j + c);
          for (int k = 0; k < width; ++k)
            for (int i = k + 1; i < width; ++i)
              for (int c = 0; c < columns; ++c)
                u[i][c] -= unit_lower[k][i] * u[k][c];
          for (int c = 0; c < count; ++c)
            for (int i = 0; i < width; ++i)
              at(k0 + i, j + c) = u[i][c];
        }
      return true;
    }
  } // namespace

  bool lu_factor(const int n, double *a, int *pivots, const LuVectors vectors)
  {
    Assert(n >= 1, dealii::ExcLowerRange(n, 1));
    Assert(a != nullptr && pivots != nullptr, ExcPrecondition("lu_factor: a null matrix or pivot array"));
    if (n < blocked_from)
      return factor_unblocked(n, a, pivots);
    for (int k0 = 0; k0 < n; k0 += block)
      {
        const int width = std::min(block, n - k0);
        if (!factor_panel(n, k0, width, a, pivots))
          return false;
        update_trailing(n, k0, width, a, vectors);
      }
    return true;
  }

  void lu_solve(const int n, const double *a, const int *pivots, double *x)
  {
    auto at = [a, n](const int i, const int j) { return a[i + std::size_t(j) * n]; };
    // Whole rows were swapped (the multipliers too): P A = L U, so P x first.
    for (int k = 0; k < n; ++k)
      {
        // Partial pivoting swaps row k with a row at or below it.
        Assert(pivots[k] >= k && pivots[k] < n, dealii::ExcIndexRangeType<int>(pivots[k], k, n));
        std::swap(x[k], x[pivots[k]]);
      }
    for (int k = 0; k < n; ++k)
      for (int i = k + 1; i < n; ++i)
        x[i] -= at(i, k) * x[k];
    for (int k = n - 1; k >= 0; --k)
      {
        x[k] /= at(k, k);
        for (int i = 0; i < k; ++i)
          x[i] -= at(i, k) * x[k];
      }
  }

  int lu_determinant_sign(const int n, const double *lu, const int *pivots)
  {
    int sign = 1;
    for (int k = 0; k < n; ++k)
      if ((pivots[k] != k) != (lu[k + std::size_t(k) * n] < 0))
        sign = -sign;
    return sign;
  }

  bool dense_solve(const int n, double *a, double *x)
  {
    std::vector<int> pivots(n);
    if (!lu_factor(n, a, pivots.data()))
      return false;
    lu_solve(n, a, pivots.data(), x);
    return true;
  }
} // namespace nsm
