// The dense LU solve of the Newton steps against known solutions.
#include <nsm/base/dense_lu.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "random_system.h"

namespace
{
  std::vector<double> times(const std::vector<double> &a, const std::vector<double> &x)
  {
    const std::size_t   n = x.size();
    std::vector<double> b(n, 0.0);
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i)
        b[i] += a[i + j * n] * x[j];
    return b;
  }

  /// LU with partial pivoting solves a nearby system: |A x - b| <= c n eps
  /// |A| |x| with c of order the growth factor (a few for random matrices);
  /// 4 n eps fails a wrong multiplier or a skipped update by orders of
  /// magnitude.
  void expect_backward_stable(const std::vector<double> &a, const std::vector<double> &b,
                              const std::vector<double> &solution)
  {
    const int                 n    = int(b.size());
    const std::vector<double> back = times(a, solution);
    double                    largest = 0;
    for (const double v : solution)
      largest = std::max(largest, std::abs(v));
    for (int i = 0; i < n; ++i)
      EXPECT_LE(std::abs(back[i] - b[i]), 4 * n * 2.2e-16 * largest * n) << n << ' ' << i;
  }
} // namespace

TEST(DenseLu, SolvesARandomSystemOfTheJacobiansSize)
{
  // 41 unknowns (M = 40, cosine basis); entries in [-1, 1]. LU with partial
  // pivoting errs by about n eps cond(A) in x; such matrices have cond(A)
  // ~ 1e2 to 1e3, so 1e-11 leaves a factor 10 and still fails a wrong
  // interchange or multiplier by orders of magnitude.
  const int n     = 41;
  const auto [a, x] = testing_helpers::random_system(n, 7);
  std::vector<double> b = times(a, x), lu = a;
  ASSERT_TRUE(nsm::dense_solve(n, lu.data(), b.data()));
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(b[i], x[i], 1e-11) << i;
}

TEST(DenseLu, IsBackwardStableAtTheJacobiansSizesForHighHarmonics)
{
  // M = 160 and 320 (cosine basis), and sizes between whole blocks of the
  // factorisation (expect_backward_stable).
  for (const int n : {7, 9, 161, 321})
    {
      const auto [a, x]           = testing_helpers::random_system(n, n);
      const std::vector<double> b = times(a, x);
      std::vector<double>       solution = b, lu = a;
      ASSERT_TRUE(nsm::dense_solve(n, lu.data(), solution.data()));
      expect_backward_stable(a, b, solution);
    }
}

TEST(DenseLu, PivotsPastAZeroDiagonal)
{
  // [[0, 2, 0], [1, 0, 0], [0, 1, 3]] (column-major below) has a zero first
  // pivot: only row interchanges solve it.
  std::vector<double>       a = {0, 1, 0, 2, 0, 1, 0, 0, 3};
  const std::vector<double> x = {1, -2, 0.5};
  std::vector<double>       b = times(a, x);
  ASSERT_TRUE(nsm::dense_solve(3, a.data(), b.data()));
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(b[i], x[i], 1e-15) << i;
}

TEST(DenseLu, ReportsASingularMatrix)
{
  std::vector<double> a = {1, 2, 2, 4}, b = {1, 1};
  EXPECT_FALSE(nsm::dense_solve(2, a.data(), b.data()));
}

TEST(DenseLu, GivesTheDeterminantsSign)
{
  // A = H D with H = I - 2 v v^T / |v|^2 a Householder reflection (det H =
  // -1) and D diagonal with entries of random sign and size in [0.5, 1.5]:
  // det A = -prod d_k, known before any factorisation, and A is as well
  // conditioned as D, so rounding cannot flip it. The factorisation pivots
  // its own way, at sizes on both sides of the blocked elimination; a sign
  // taken from the factors' diagonal alone, or from the interchanges alone,
  // fails on some of the 18 cases.
  for (const int n : {7, 41, 161})
    for (unsigned int seed = 0; seed < 6; ++seed)
      {
        const auto [unused, v] = testing_helpers::random_system(n, 100 + seed);
        const auto [other, d]  = testing_helpers::random_system(n, 200 + seed);
        double norm = 0;
        for (const double vi : v)
          norm += vi * vi;
        std::vector<double> a(std::size_t(n) * n);
        int                 expected = -1;
        for (int j = 0; j < n; ++j)
          {
            const double dj = (d[j] < 0 ? -1 : 1) * (0.5 + std::abs(d[j]));
            expected *= dj < 0 ? -1 : 1;
            for (int i = 0; i < n; ++i)
              a[i + std::size_t(j) * n] = ((i == j ? 1.0 : 0.0) - 2 * v[i] * v[j] / norm) * dj;
          }
        std::vector<int> pivots(n);
        ASSERT_TRUE(nsm::lu_factor(n, a.data(), pivots.data()));
        EXPECT_EQ(nsm::lu_determinant_sign(n, a.data(), pivots.data()), expected) << n << ' ' << seed;
        int interchanges = 0;
        for (int k = 0; k < n; ++k)
          interchanges += pivots[k] != k;
        EXPECT_GT(interchanges, 0) << "the test should make the factorisation interchange rows";
      }
}

// The trailing update runs on eight-double vectors with AVX-512 and on four
// otherwise (GCC keeps eight-double vectors in memory without it: 2.6 times
// slower). Each entry gets the same multiply-adds in the same order, so the
// factors and interchanges agree to the last bit, at whole blocks of pivots
// and between them (n = 170: a narrower last block, tails of 10 rows). On a
// processor without AVX-512 both are the four-double build.
TEST(DenseLu, FourAndEightDoubleVectorsGiveTheSameFactors)
{
  for (const int n : {96, 161, 170, 321})
    {
      const auto [a, x]       = testing_helpers::random_system(n, n + 1);
      std::vector<double> wide = a, four = a;
      std::vector<int>    wide_pivots(n), four_pivots(n);
      ASSERT_TRUE(nsm::lu_factor(n, wide.data(), wide_pivots.data(), nsm::LuVectors::widest));
      ASSERT_TRUE(nsm::lu_factor(n, four.data(), four_pivots.data(), nsm::LuVectors::four));
      EXPECT_EQ(wide_pivots, four_pivots) << n;
      EXPECT_EQ(wide, four) << n;
      // And the four-double factors solve the system (the widest are checked
      // above) within LU's backward error.
      const std::vector<double> b = times(a, x);
      std::vector<double>       solution = b;
      nsm::lu_solve(n, four.data(), four_pivots.data(), solution.data());
      expect_backward_stable(a, b, solution);
    }
}
