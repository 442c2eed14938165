// The modes below a bound (Sturm brackets, Newton on 1/gamma, inverse
// iteration) and the far modes' series against independent references: a
// Sturm bisection of the same assembled pencil in extended precision, and
// the full spectrum with its residues from the product formula.
#include <nsm/model/adaptive_refinement.h>
#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/near_modes.h>
#include <nsm/model/spectrum.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "extended_pencil.h"
#include "scene_helpers.h"

namespace
{
  /// lambda_j (0-based) by bisection of the extended-precision counts from a
  /// bracket of relative width 2e-8 around `estimate`; NaN if that bracket
  /// does not hold lambda_j.
  double extended_eigenvalue(const nsm::BandedPencil &p, const int j, const double estimate)
  {
    long double lo = estimate * (1 - 1e-8L), hi = estimate * (1 + 1e-8L);
    if (extended::count_below(p, lo) != j || extended::count_below(p, hi) != j + 1)
      return std::nan("");
    for (int step = 0; step < 64; ++step)
      (extended::count_below(p, 0.5L * (lo + hi)) > j ? hi : lo) = 0.5L * (lo + hi);
    return 0.5L * (lo + hi);
  }

  struct Mesh
  {
    std::string                            name;
    nsm::Scene                             scene;
    std::function<void(nsm::Discretisation &)> refine = [](nsm::Discretisation &) {};
  };

  /// The paper's mesh, high order, and an adaptive mesh whose smallest cell is
  /// below 1/100 of the largest (pairs of nearly equal eigenvalues).
  std::vector<Mesh> meshes()
  {
    std::vector<Mesh> list{{"p1, 4000 cells", testing_helpers::bar_scene("1.5 - x", 1, 4000)},
                           {"p10, 20 cells", testing_helpers::bar_scene("1.5 - x", 10, 20)},
                           {"adaptive", testing_helpers::bar_scene("1.5 - x", 1, 40)}};
    nsm::DiscretisationParameters &adaptive = list.back().scene.discretisation;
    adaptive.refinement                  = nsm::Refinement::adaptive;
    adaptive.adaptive_steps              = 10;
    adaptive.adaptive_tolerance          = 1e-14;
    list.back().refine = [adaptive](nsm::Discretisation &d) { nsm::refine_adaptively(d, adaptive, 8.0); };
    return list;
  }

  /// A mesh built: the discretisation keeps a reference to its bar.
  struct Built
  {
    explicit Built(const Mesh &mesh)
      : bar(mesh.scene.bar)
      , d(bar, mesh.scene.discretisation)
    {
      mesh.refine(d);
    }
    nsm::BarModel       bar;
    nsm::Discretisation d;
  };

  // The paper's band, M = 40 harmonics of Omega <= 2.2; the modes below
  // 16 times its square are the near ones.
  constexpr double band  = 40 * 2.2;
  constexpr double upper = 16 * band * band;
} // namespace

TEST(NearModes, EigenvaluesAreThoseOfTheAssembledPencil)
{
  // Newton's last step (below 1e-8 lambda) leaves step^2 / gap < 1e-14 lambda;
  // the LU of K - sigma M adds its backward error. Measured: at most 3e-12.
  // The bound 1e-11 lies 1000 times below the mass-factored form's floor
  // eps lambda_max / lambda_1 (1e-8 on the paper's mesh).
  for (const Mesh &mesh : meshes())
    {
      const Built         built(mesh);
      const auto         &d = built.d;
      const nsm::BandedPencil p(d, nsm::EndCondition::clamped_free);
      const nsm::ModalData    near = nsm::modes_below(p, upper);
      ASSERT_EQ(int(near.eigenvalues.size()), extended::count_below(p, upper)) << mesh.name;
      ASSERT_GT(near.eigenvalues.size(), 40u) << mesh.name;
      for (std::size_t j = 0; j < near.eigenvalues.size(); ++j)
        EXPECT_NEAR(near.eigenvalues[j] / extended_eigenvalue(p, j, near.eigenvalues[j]), 1.0, 1e-11)
          << mesh.name << ", mode " << j + 1;
    }
}

TEST(NearModes, ResiduesAgreeWithTheProductFormula)
{
  // The product formula's residues carry its eigenvalues' errors (1.6e-11 on
  // the paper's first mode) amplified by the factors 1 - lambda_j / mu_k: the
  // two methods agree to 7e-11 there, 5e-12 elsewhere.
  for (const Mesh &mesh : meshes())
    {
      const Built         built(mesh);
      const auto         &d = built.d;
      const nsm::ModalData near = nsm::modes_below(nsm::BandedPencil(d, nsm::EndCondition::clamped_free), upper);
      const nsm::ModalData full = nsm::compute_spectrum(d, nsm::EndCondition::clamped_free, 0, true);
      for (std::size_t j = 0; j < near.eigenvalues.size(); ++j)
        EXPECT_NEAR(near.contact_residues[j] / full.contact_residues[j], 1.0, 1e-9)
          << mesh.name << ", mode " << j + 1;
    }
}

TEST(NearModes, FarSeriesIsTheSumOverTheFarModes)
{
  // Rounding delta of gamma - sum_near on the circle (radius >= 2 band^2)
  // costs at most 2 delta on |w^2| <= band^2; delta is a few hundred eps
  // gamma(0) from the near sum's terms. Measured: at most 9e-14 gamma(0).
  for (const Mesh &mesh : meshes())
    {
      const Built         built(mesh);
      const auto         &d = built.d;
      const nsm::BandedPencil   p(d, nsm::EndCondition::clamped_free);
      const nsm::ModalData      near   = nsm::modes_below(p, upper);
      const nsm::ModalData      full   = nsm::compute_spectrum(d, nsm::EndCondition::clamped_free, 0, true);
      const std::vector<double> series = nsm::far_mode_series(p, near, upper, band * band, 13);
      double                    gamma0 = 0;
      for (std::size_t j = 0; j < full.eigenvalues.size(); ++j)
        gamma0 += full.contact_residues[j] / full.eigenvalues[j];
      for (const double s : {0.0, 0.5 * band * band, band * band})
        {
          double value = 0, sum = 0;
          for (std::size_t m = series.size(); m-- > 0;)
            value = value * s + series[m];
          for (std::size_t j = near.eigenvalues.size(); j < full.eigenvalues.size(); ++j)
            sum += full.contact_residues[j] / (full.eigenvalues[j] - s);
          EXPECT_NEAR(value, sum, 1e-12 * gamma0) << mesh.name << ", w^2 = " << s;
        }
    }
}
