// Eigenfrequencies against the exact Bessel roots, and their convergence in
// h (rate 2p) and in p (exponential) for the tapered seed bar.
#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/spectrum.h>

#include <gtest/gtest.h>

#include <cmath>

#include "exact_bar.h"
#include "extended_pencil.h"
#include "scene_helpers.h"

namespace
{
  const std::vector<double> &exact_clamped_free()
  {
    static const auto roots = exact::roots(exact::tapered_clamped_free, 10);
    return roots;
  }
  const std::vector<double> &exact_clamped_clamped()
  {
    static const auto roots = exact::roots(exact::tapered_clamped_clamped, 10);
    return roots;
  }

  std::vector<double> frequencies(unsigned int degree,
                                  unsigned int cells,
                                  nsm::EndCondition ends,
                                  unsigned int count)
  {
    const nsm::Scene          scene = testing_helpers::bar_scene("1.5 - x", degree, cells);
    const nsm::BarModel       bar(scene.bar);
    const nsm::Discretisation d(bar, scene.discretisation);
    std::vector<double> w = nsm::compute_spectrum(d, ends, count, false).eigenvalues;
    for (double &v : w)
      v = std::sqrt(v);
    return w;
  }

  double mode_error(unsigned int mode, unsigned int degree, unsigned int cells)
  {
    return frequencies(degree, cells, nsm::EndCondition::clamped_free, mode)[mode - 1] /
             exact_clamped_free()[mode - 1] - 1;
  }
} // namespace

TEST(ExactReference, SeedBarFirstFrequenciesMatchMethodNote)
{
  // method.md: w1 = 1.919137 (clamped-free), 3.096918 (clamped-clamped).
  EXPECT_NEAR(exact_clamped_free()[0], 1.919137, 5e-7);
  EXPECT_NEAR(exact_clamped_clamped()[0], 3.096918, 5e-7);
}

TEST(Spectrum, FirstTenFrequenciesOfTheTaperedBar)
{
  // FE_Q(8) on 40 cells: a priori error ~ (w h / p)^(2p); for mode 10
  // (w ~ 30, h = 1/40) that is < 1e-11. Tolerance: 1e-10 relative.
  const auto free = frequencies(8, 40, nsm::EndCondition::clamped_free, 10);
  const auto clamped = frequencies(8, 40, nsm::EndCondition::clamped_clamped, 10);
  for (unsigned int j = 0; j < 10; ++j)
    {
      EXPECT_NEAR(free[j] / exact_clamped_free()[j], 1.0, 1e-10) << "mode " << j + 1;
      EXPECT_NEAR(clamped[j] / exact_clamped_clamped()[j], 1.0, 1e-10) << "mode " << j + 1;
    }
}

TEST(Spectrum, FrequenciesInterlace)
{
  // Clamped-free below clamped-clamped for each j (Rayleigh's separation).
  const auto free = frequencies(2, 100, nsm::EndCondition::clamped_free, 10);
  const auto clamped = frequencies(2, 100, nsm::EndCondition::clamped_clamped, 10);
  for (unsigned int j = 0; j < 10; ++j)
    {
      EXPECT_LT(free[j], clamped[j]);
      if (j + 1 < 10)
        {
          EXPECT_LT(clamped[j], free[j + 1]);
        }
    }
}

TEST(Spectrum, ConvergesLikeHToTheTwoP)
{
  // Rates of mode 5 from three meshes halving h, in the asymptotic range
  // (w5 h / p < 1) and far above round-off (errors > 1e-11; the floor is
  // ~1e-13). Accept within 10 % of 2p.
  const std::vector<std::vector<unsigned int>> meshes = {
    {16, 32, 64}, {16, 32, 64}, {16, 32, 64}, {8, 16, 32}};
  for (unsigned int p = 1; p <= 4; ++p)
    {
      std::vector<double> errors;
      for (const unsigned int cells : meshes[p - 1])
        errors.push_back(mode_error(5, p, cells));
      for (unsigned int i = 0; i + 1 < errors.size(); ++i)
        {
          ASSERT_GT(errors[i + 1], 1e-11) << "p = " << p;
          const double rate = std::log2(errors[i] / errors[i + 1]);
          EXPECT_NEAR(rate, 2.0 * p, 0.2 * p)
            << "p = " << p << ", cells " << meshes[p - 1][i];
        }
    }
}

TEST(Spectrum, ConvergesExponentiallyInP)
{
  // Fixed mesh of 2 cells: each extra degree divides the error by at least 4
  // until round-off, which is reached (< 1e-13) by p = 12.
  double previous = std::abs(mode_error(1, 1, 2));
  double best = previous;
  for (unsigned int p = 2; p <= 12; ++p)
    {
      const double error = std::abs(mode_error(1, p, 2));
      if (previous > 1e-11)
        {
          EXPECT_LT(error, previous / 4) << "p = " << p;
        }
      previous = error;
      best = std::min(best, error);
    }
  EXPECT_LT(best, 1e-13);
}

TEST(Spectrum, StronglyGradedMeshesKeepTheBesselFrequencies)
{
  // The hostile scenes of tests/scenes/hostile_inputs.py: FE_Q(1) on 4000 cells whose last 50 or 60
  // shrink by 0.8, so the smallest cell is 3.6e-9 L or 3.9e-10 L. The
  // round-off floor eps p^2 L / h_min is 6e-8 or 5.7e-7 (the second scene
  // needs Round-off limit >= 5.7e-7). Linear elements resolve w_j to
  // (w_j h)^2 / 24 <= 1e-7 for the two lowest modes of each end condition
  // (h = 2.5e-4 L): error bounds 1e-7 + floor. The mass-factored LAPACK form
  // errs by eps lambda_max ~ 12 eps / h_min^2, far above lambda_1 = 3.7 on
  // the second mesh: it gave w1 = 3.67 there.
  for (const auto &[layers, bound] : std::vector<std::pair<unsigned int, double>>{{50, 2e-7},
                                                                                 {60, 7e-7}})
    {
      nsm::Scene scene = testing_helpers::bar_scene("1.5 - x", 1, 4000);
      scene.discretisation.refinement    = nsm::Refinement::graded;
      scene.discretisation.graded_ratio  = 0.8;
      scene.discretisation.graded_layers = layers;
      const nsm::BarModel       bar(scene.bar);
      const nsm::Discretisation d(bar, scene.discretisation);
      const auto free    = nsm::compute_spectrum(d, nsm::EndCondition::clamped_free, 2, false);
      const auto clamped = nsm::compute_spectrum(d, nsm::EndCondition::clamped_clamped, 2, false);
      ASSERT_EQ(free.eigenvalues.size(), 2u);
      ASSERT_EQ(clamped.eigenvalues.size(), 2u);
      for (unsigned int j = 0; j < 2; ++j)
        {
          EXPECT_NEAR(std::sqrt(free.eigenvalues[j]) / exact_clamped_free()[j], 1.0, bound)
            << layers << " layers, mode " << j + 1;
          EXPECT_NEAR(std::sqrt(clamped.eigenvalues[j]) / exact_clamped_clamped()[j], 1.0, bound)
            << layers << " layers, mode " << j + 1;
        }
    }
}

TEST(Spectrum, FewModesAreThoseOfTheAssembledPencil)
{
  // Ten modes of the paper's mesh come from Sturm counts and Newton (fewer
  // than n / 10 asked). Against the same pencil's counts in long double, each
  // is within 1e-11 (measured: 1e-11 on w1^2 for LAPACK's stiffness-factored
  // form): the tolerance is that of
  // NearModes.EigenvaluesAreThoseOfTheAssembledPencil.
  const nsm::Scene          scene = testing_helpers::bar_scene("1.5 - x", 1, 4000);
  const nsm::BarModel       bar(scene.bar);
  const nsm::Discretisation d(bar, scene.discretisation);
  for (const auto ends : {nsm::EndCondition::clamped_free, nsm::EndCondition::clamped_clamped})
    {
      const nsm::BandedPencil   p(d, ends);
      const std::vector<double> lambda = nsm::compute_spectrum(d, ends, 10, false).eigenvalues;
      ASSERT_EQ(lambda.size(), 10u);
      for (int j = 0; j < 10; ++j)
        {
          EXPECT_EQ(extended::count_below(p, lambda[j] * (1 - 1e-11L)), j) << "mode " << j + 1;
          EXPECT_EQ(extended::count_below(p, lambda[j] * (1 + 1e-11L)), j + 1) << "mode " << j + 1;
        }
    }
}

TEST(Spectrum, PolesBelowABandAreThoseOfTheAssembledPencil)
{
  // The direct receptance's poles below the harmonic-balance band of the
  // paper's scene (40 x 2.2): on FE_Q(4) x 500, 28 poles, fewer than
  // n / (10 p), from Sturm counts and Newton; on FE_Q(4) x 20, from LAPACK.
  // Each is bracketed within 1e-11 by the same pencil's long-double counts,
  // and none is missing or extra.
  const double band = 88;
  for (const unsigned int cells : {500u, 20u})
    {
      const nsm::Scene          scene = testing_helpers::bar_scene("1.5 - x", 4, cells);
      const nsm::BarModel       bar(scene.bar);
      const nsm::Discretisation d(bar, scene.discretisation);
      const nsm::BandedPencil   p(d, nsm::EndCondition::clamped_free);
      const std::vector<double> lambda = nsm::eigenvalues_below(p, band);
      ASSERT_EQ(int(lambda.size()), extended::count_below(p, band * band)) << cells << " cells";
      for (std::size_t j = 0; j < lambda.size(); ++j)
        {
          EXPECT_EQ(extended::count_below(p, lambda[j] * (1 - 1e-11L)), int(j)) << "mode " << j + 1;
          EXPECT_EQ(extended::count_below(p, lambda[j] * (1 + 1e-11L)), int(j + 1)) << "mode " << j + 1;
        }
    }
}
