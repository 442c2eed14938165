// The active set {q > 0} of a trigonometric series and the Gram matrix over
// it, against closed forms and a brute-force quadrature.
#include <nsm/harmonic_balance/active_set.h>

#include <gtest/gtest.h>

#include "basis_value.h"

#include <cmath>

namespace
{
  using testing_helpers::basis_value;

  /// The exact rule's grid, as the harmonic balance sets it.
  unsigned int grid(const unsigned int harmonics)
  {
    return 8 * harmonics + 8;
  }

  /// The Dirichlet kernel 1 + 2 sum_k cos(k x), k = 1..M.
  double dirichlet(const unsigned int harmonics, const double x)
  {
    return std::sin((harmonics + 0.5) * x) / std::sin(0.5 * x);
  }
} // namespace

TEST(ActiveSet, RootsOfAShiftedCosineAreAtItsArccos)
{
  const auto       b = nsm::harmonic_basis(3, false);
  nsm::ActiveSet   set(b, nsm::Integration::exact, grid(3));
  std::vector<double> v(b.size(), 0.0);
  v[0] = -0.3, v[1] = 1; // q = cos(tau) - 0.3
  const std::vector<double> r = set.roots(v);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0], std::acos(0.3), 1e-12);
  EXPECT_NEAR(r[1], 2 * M_PI - std::acos(0.3), 1e-12);
  EXPECT_NEAR(set.gram(v).share(), std::acos(0.3) / M_PI, 1e-12);
}

TEST(ActiveSet, GramOverTheWholePeriodIsTheIdentity)
{
  // q = 1 > 0 everywhere: the projection of phi_j on phi_i is delta_ij, for
  // the exact rule and (discrete orthogonality, Nt > 2 M) the sampled one.
  for (const bool full : {false, true})
    for (const auto rule : {nsm::Integration::exact, nsm::Integration::sampled})
      {
        const auto     b = nsm::harmonic_basis(4, full);
        nsm::ActiveSet set(b, rule, rule == nsm::Integration::exact ? grid(4) : 64);
        std::vector<double> v(b.size(), 0.0), gram;
        v[0] = 1;
        EXPECT_DOUBLE_EQ(set.gram(v).share(), 1.0);
        set.gram(v).fill(gram);
        for (unsigned int i = 0; i < b.size(); ++i)
          for (unsigned int j = 0; j < b.size(); ++j)
            EXPECT_NEAR(gram[i * b.size() + j], i == j ? 1.0 : 0.0, 1e-13) << i << ' ' << j;
      }
}

TEST(ActiveSet, ExactGramMatchesABruteForceQuadrature)
{
  const unsigned int  harmonics = 4;
  const auto          b = nsm::harmonic_basis(harmonics, true);
  nsm::ActiveSet      set(b, nsm::Integration::exact, grid(harmonics));
  const std::vector<double> v = {0.1, 0.7, -0.4, 0.25, 0.3, -0.2, 0.15, 0.1, -0.05};
  std::vector<double> gram;
  const double        fraction = set.gram(v).share();
  set.gram(v).fill(gram);

  // Midpoint rule with the indicator of q > 0: its error is about one step
  // per root, 6e-6 here.
  const unsigned int  points = 1u << 20;
  const double        h      = 2 * M_PI / points;
  const unsigned int  n      = b.size();
  std::vector<double> quadrature(n * n, 0.0), f(n);
  unsigned int        active = 0;
  for (unsigned int t = 0; t < points; ++t)
    {
      const double tau = (t + 0.5) * h;
      double       q   = 0;
      for (unsigned int i = 0; i < n; ++i)
        f[i] = basis_value(b, i, tau), q += v[i] * f[i];
      if (q <= 0)
        continue;
      ++active;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          quadrature[i * n + j] += (b.order[i] == 0 ? 1.0 : 2.0) / points * f[i] * f[j];
    }
  ASSERT_GT(active, points / 10);
  ASSERT_LT(active, points - points / 10);
  EXPECT_NEAR(fraction, double(active) / points, 2e-5);
  for (unsigned int k = 0; k < n * n; ++k)
    EXPECT_NEAR(gram[k], quadrature[k], 4e-5) << k;
}

TEST(ActiveSet, FindsAContactShorterThanASampleSpacing)
{
  // q = D_M(tau - tau0) - (2 M + 1 - delta): positive only within x* of
  // tau0, half a grid spacing off the samples, and negative at every sample.
  const unsigned int harmonics = 5;
  const auto         b = nsm::harmonic_basis(harmonics, true);
  const unsigned int samples = grid(harmonics);
  nsm::ActiveSet     set(b, nsm::Integration::exact, samples);
  const double       h = 2 * M_PI / samples, tau0 = 7.5 * h, delta = 1e-3, top = 2.0 * harmonics + 1;
  std::vector<double> v(b.size(), 0.0);
  v[0] = 1 - (top - delta);
  for (unsigned int k = 1; k <= harmonics; ++k)
    {
      v[2 * k - 1] = 2 * std::sin(k * tau0);
      v[2 * k]     = 2 * std::cos(k * tau0);
    }
  ASSERT_LT(dirichlet(harmonics, 0.5 * h), top - delta); // every sample negative

  // x*: D_M(x*) = 2 M + 1 - delta, by bisection on the closed form.
  double lo = 1e-12, hi = 0.5 * h;
  for (int it = 0; it < 200; ++it)
    (dirichlet(harmonics, 0.5 * (lo + hi)) > top - delta ? lo : hi) = 0.5 * (lo + hi);
  const double x = 0.5 * (lo + hi);

  const std::vector<double> r = set.roots(v);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0], tau0 - x, 1e-11);
  EXPECT_NEAR(r[1], tau0 + x, 1e-11);
  EXPECT_NEAR(set.gram(v).share(), 2 * x / (2 * M_PI), 1e-11);
}
