// The Gram matrix in Toeplitz-plus-Hankel form (structured_gram.h) against
// an independent one: Gauss-Legendre quadrature of the basis products over
// the same intervals, exact to rounding for trigonometric polynomials of
// this degree. Both the dense matrix (the Jacobian's) and the product G v
// (the residual's), for the cosine and the full basis, and the sampled rule's
// sums.
#include <nsm/harmonic_balance/structured_gram.h>

#include <gtest/gtest.h>

#include "basis_value.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace
{
  using testing_helpers::basis_value;

  /// Nodes and weights of the n-point Gauss-Legendre rule on [-1, 1], by
  /// Newton on P_n from the Chebyshev estimates.
  void gauss_legendre(const unsigned int n, std::vector<double> &x, std::vector<double> &w)
  {
    x.resize(n), w.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), derivative = 0;
        for (int it = 0; it < 100; ++it)
          {
            double p0 = 1, p1 = z;
            for (unsigned int k = 2; k <= n; ++k)
              {
                const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1, p1 = p2;
              }
            derivative     = n * (z * p1 - p0) / (z * z - 1);
            const double d = p1 / derivative;
            z -= d;
            if (std::abs(d) < 1e-16)
              break;
          }
        x[i] = z, w[i] = 2 / ((1 - z * z) * derivative * derivative);
      }
  }

  /// G_ij = (1 or 2) / 2 pi * integral over the intervals of phi_i phi_j,
  /// row-major: 200 Gauss points per interval integrate the products (up to
  /// frequency 2M = 80 over at most a period) to rounding.
  std::vector<double> quadrature_gram(const nsm::TrigonometricBasis                 &b,
                                      const std::vector<std::pair<double, double>> &intervals)
  {
    const unsigned int  n = b.size();
    std::vector<double> g(n * n, 0.0), x, w;
    gauss_legendre(200, x, w);
    for (const auto &[a, e] : intervals)
      for (std::size_t q = 0; q < x.size(); ++q)
        {
          const double tau = 0.5 * (a + e) + 0.5 * (e - a) * x[q], weight = 0.5 * (e - a) * w[q];
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              g[i * n + j] +=
                (b.order[i] == 0 ? 1.0 : 2.0) / (2 * M_PI) * weight * basis_value(b, i, tau) * basis_value(b, j, tau);
        }
    return g;
  }

  /// Three disjoint random intervals in [0, 2 pi + 1): the last may wrap
  /// past the period's end, as the active set's last interval does.
  std::vector<std::pair<double, double>> random_intervals(std::mt19937 &engine)
  {
    std::uniform_real_distribution<double> uniform(0, 1);
    std::vector<double>                    ends(6);
    for (double &e : ends)
      e = (2 * M_PI + 1) * uniform(engine);
    std::sort(ends.begin(), ends.end());
    return {{ends[0], ends[1]}, {ends[2], ends[3]}, {ends[4], ends[5]}};
  }
} // namespace

TEST(StructuredGram, AgreesWithQuadratureOnRandomActiveSets)
{
  // Entries are O(1); the closed forms and the quadrature each err by a few
  // eps per term summed, far below 1e-12. A wrong sign of the Hankel part
  // (k + l) changes entries by 2 |C_k+l| / 2 pi, of order 0.1.
  std::mt19937 engine(3);
  for (const bool full : {false, true})
    for (int trial = 0; trial < 5; ++trial)
      {
        const auto          b = nsm::harmonic_basis(full ? 20 : 40, full);
        const unsigned int  n = b.size();
        const auto          intervals = random_intervals(engine);
        nsm::StructuredGram gram(b);
        gram.set_intervals(intervals);
        std::vector<double> dense;
        gram.fill(dense);
        const std::vector<double> reference = quadrature_gram(b, intervals);
        for (unsigned int k = 0; k < n * n; ++k)
          ASSERT_NEAR(dense[k], reference[k], 1e-12) << (full ? "full " : "cosine ") << k / n << ' ' << k % n;

        double measure = 0;
        for (const auto &[a, e] : intervals)
          measure += e - a;
        EXPECT_NEAR(gram.share(), measure / (2 * M_PI), 1e-15);

        // The product, on a random state.
        std::uniform_real_distribution<double> uniform(-1, 1);
        std::vector<double>                    v(n), product;
        for (double &x : v)
          x = uniform(engine);
        gram.multiply(v, product);
        for (unsigned int i = 0; i < n; ++i)
          {
            double expected = 0;
            for (unsigned int j = 0; j < n; ++j)
              expected += reference[i * n + j] * v[j];
            EXPECT_NEAR(product[i], expected, 1e-12) << (full ? "full " : "cosine ") << i;
          }
      }
}

TEST(StructuredGram, SampledSumsAreTheSampledRulesProducts)
{
  // The sampled rule: G_ij = (1 or 2) / samples * sum over the active samples
  // of phi_i phi_j, summed here directly.
  std::mt19937 engine(5);
  for (const bool full : {false, true})
    {
      const auto                b = nsm::harmonic_basis(12, full);
      const unsigned int        n = b.size(), samples = 64;
      std::vector<unsigned int> active;
      std::bernoulli_distribution pick(0.3);
      for (unsigned int t = 0; t < samples; ++t)
        if (pick(engine))
          active.push_back(t);
      nsm::StructuredGram gram(b);
      gram.set_samples(active, samples);
      std::vector<double> dense;
      gram.fill(dense);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            double sum = 0;
            for (const unsigned int t : active)
              sum += basis_value(b, i, 2 * M_PI * t / samples) * basis_value(b, j, 2 * M_PI * t / samples);
            EXPECT_NEAR(dense[i * n + j], (b.order[i] == 0 ? 1.0 : 2.0) / samples * sum, 1e-13) << i << ' ' << j;
          }
      EXPECT_DOUBLE_EQ(gram.share(), double(active.size()) / samples);
    }
}
