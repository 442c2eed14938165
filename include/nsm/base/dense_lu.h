// Solves a small dense system by LU with partial pivoting, in blocks of
// pivots with a vectorised trailing update: for the harmonic balance's
// Jacobian (M + 1 or 2M + 1 unknowns) the reference LAPACK's dgetrf spends
// more in its BLAS calls than in arithmetic.
#pragma once

namespace nsm
{
  /// The vectors of the blocked factorisation's trailing update: the
  /// processor's widest (eight doubles with AVX-512, else four), or four
  /// (AVX2's; for tests: both give the same factors to the last bit).
  enum class LuVectors
  {
    widest,
    four
  };

  /// P A = L U in place (A n x n column-major; pivots: n interchanges).
  /// False if a pivot is exactly zero (A singular).
  bool lu_factor(int n, double *a, int *pivots, LuVectors vectors = LuVectors::widest);

  /// x <- A^{-1} x from lu_factor's factors and interchanges.
  void lu_solve(int n, const double *lu, const int *pivots, double *x);

  /// The sign of det A (+1 or -1) from lu_factor's factors and
  /// interchanges: the product of U's diagonal's signs, less for each
  /// interchange.
  int lu_determinant_sign(int n, const double *lu, const int *pivots);

  /// x <- A^{-1} x, A n x n column-major (overwritten by its LU factors).
  /// False if a pivot is exactly zero (A singular).
  bool dense_solve(int n, double *a, double *x);
} // namespace nsm
