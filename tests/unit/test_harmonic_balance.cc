// The HB residual: analytic Jacobian and dR/dW against finite differences,
// boundedness through poles and zeros of gamma, the energy against the
// modal (Parseval) formula, and the grazing start.
#include <gtest/gtest.h>

#include <cmath>

#include "hb_model.h"

namespace
{
  using testing_helpers::HbModel;

  /// A converged point on the seed bar's branch near grazing.
  nsm::BackbonePoint seed_point(HbModel &model)
  {
    model.scene.continuation.max_steps = 20;
    return model.backbone().points.back();
  }

  double relative_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double d = 0, n = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      d = std::max(d, std::abs(a[i] - b[i])), n = std::max(n, std::abs(b[i]));
    return d / n;
  }

  /// Centred differences of R in x (columns) and in W.
  void check_derivatives(HbModel &model, const nsm::BackbonePoint &point)
  {
    auto &hb = model.hb;
    const unsigned int n = hb.n_unknowns();
    std::vector<double> jacobian, domega, rp, rm;
    hb.set_omega(point.omega);
    hb.evaluate(point.x, nullptr, &jacobian, &domega);
    std::vector<double> fd(n * n);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double step = 1e-7 * std::max(1.0, std::abs(point.x[j]));
        auto xp = point.x, xm = point.x;
        xp[j] += step, xm[j] -= step;
        hb.evaluate(xp, &rp, nullptr, nullptr);
        hb.evaluate(xm, &rm, nullptr, nullptr);
        for (unsigned int i = 0; i < n; ++i)
          fd[i + j * n] = (rp[i] - rm[i]) / (2 * step);
      }
    // Truncation O(step^2 R''') and round-off O(eps / step): ~1e-7 relative.
    EXPECT_LT(relative_difference(fd, jacobian), 1e-6);

    const double step = 1e-7;
    hb.set_omega(point.omega + step);
    hb.evaluate(point.x, &rp, nullptr, nullptr);
    hb.set_omega(point.omega - step);
    hb.evaluate(point.x, &rm, nullptr, nullptr);
    std::vector<double> fd_omega(n);
    for (unsigned int i = 0; i < n; ++i)
      fd_omega[i] = (rp[i] - rm[i]) / (2 * step);
    EXPECT_LT(relative_difference(fd_omega, domega), 1e-6);
  }
} // namespace

TEST(HarmonicBalance, ExactJacobianMatchesFiniteDifferences)
{
  HbModel model(testing_helpers::hb_scene("1.5 - x", 20));
  check_derivatives(model, seed_point(model));
}

TEST(HarmonicBalance, FullBasisJacobianMatchesFiniteDifferences)
{
  auto scene = testing_helpers::hb_scene("1.5 - x", 20);
  scene.harmonic_balance.basis = nsm::HarmonicBasis::full;
  HbModel model(scene);
  const auto point = seed_point(model);
  // Even motion, phase fixed by the sine part of the first harmonic: mu = 0.
  EXPECT_LT(std::abs(point.x[1]), 1e-9);
  // Perturb the sine parts so the check sees the full coupling.
  auto x = point.x;
  for (unsigned int i = 3; i < x.size(); i += 2)
    x[i] = 1e-2 * x[i + 1];
  check_derivatives(model, {point.segment, point.omega, point.measures, 0, 0, x});
}

TEST(HarmonicBalance, SampledJacobianIsTheDerivativeOfTheSampledResidual)
{
  // The sampled residual is piecewise smooth: finite differences with a step
  // that moves no sample across the contact boundary match it exactly.
  auto scene = testing_helpers::hb_scene("1.5 - x", 20);
  scene.harmonic_balance.integration = nsm::Integration::sampled;
  HbModel model(scene);
  check_derivatives(model, seed_point(model));
}

TEST(HarmonicBalance, BoundedThroughPolesAndZerosOfGamma)
{
  // W = w_j / k puts harmonic k exactly on a pole: residual, Jacobian and
  // dR/dW stay finite and continuous across it (no division by gamma or by
  // 1 / gamma); likewise across a zero (clamped-clamped frequency).
  HbModel model(testing_helpers::hb_scene("1.5 - x", 20));
  const auto point = seed_point(model);
  auto &hb = model.hb;
  const double pole = std::sqrt(model.receptance.poles()[2]) / 7;   // w_3 / 7
  const double zero = 9.40759441432538 / 5;                           // w_cc,3 / 5
  for (const double w : {pole, zero})
    {
      std::vector<double> r0, j0, d0, r1, j1, d1;
      for (const double shift : {-1e-9, 0.0, 1e-9})
        {
          hb.set_omega(w + shift);
          hb.evaluate(point.x, &r1, &j1, &d1);
          for (const auto *v : {&r1, &j1, &d1})
            for (const double value : *v)
              ASSERT_TRUE(std::isfinite(value)) << "W = " << w + shift;
          if (!r0.empty())
            {
              EXPECT_LT(relative_difference(r1, r0), 1e-6) << "R, W = " << w;
              EXPECT_LT(relative_difference(j1, j0), 1e-6) << "J, W = " << w;
              EXPECT_LT(relative_difference(d1, d0), 1e-6) << "dR/dW, W = " << w;
            }
          r0 = r1, j0 = j1, d0 = d1;
        }
    }
}

TEST(HarmonicBalance, MeanEnergyEqualsTheModalFormula)
{
  // method.md section 5: mean energy = a_0^2 gamma(0) / 2 + sum_k a_k^2
  // (gamma + 2 w^2 gamma') / 4, from receptance values directly; the code
  // computes it from the angle variables and the trigonometric energy.
  HbModel model(testing_helpers::hb_scene("1.5 - x", 20));
  const auto point = seed_point(model);
  const double force = model.hb.force_scale();
  double expected = 0;
  for (unsigned int k = 0; k <= 20; ++k)
    {
      const auto   g = model.receptance(k * point.omega);
      const double theta_cos = 1 / std::sqrt(1 + g.gamma * g.gamma) *
                               (model.receptance.poles_below(k * point.omega) % 2 ? -1 : 1);
      const double a = force * point.x[k] * theta_cos;
      const double w2 = k * k * point.omega * point.omega;
      expected += k == 0 ? a * a * g.gamma / 2 : a * a * (g.gamma + 2 * w2 * g.dgamma_domega2) / 4;
    }
  EXPECT_NEAR(point.measures.energy / expected, 1.0, 1e-10);
}

TEST(HarmonicBalance, GrazingStartIsTheLinearModeAtTheGap)
{
  // Just above w1 the contact is brief and the motion is the first linear
  // mode with u(L) = g0: energy w1^2 g0^2 / (2 phi_1(L)^2) to first order in
  // the offset from w1 (1e-3 here, so 2 % with the mode's curvature).
  HbModel model(testing_helpers::hb_scene("1.5 - x", 40));
  model.scene.continuation.max_steps = 1;
  const auto   start = model.backbone().points.front();
  const auto [l1, linear] = model.grazing(1);
  EXPECT_GT(start.omega, std::sqrt(l1));
  EXPECT_NEAR(start.measures.energy / linear, 1.0, 0.02);
}
