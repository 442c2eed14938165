// The receptance gamma(w) against the exact references, and the direct
// (UMFPACK) and modal methods against each other.
#include <nsm/model/adaptive_refinement.h>
#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/receptance.h>

#include <gtest/gtest.h>

#include <cmath>

#include "exact_bar.h"
#include "extended_pencil.h"
#include "scene_helpers.h"

namespace
{
  struct Model
  {
    Model(const std::string &section, unsigned int degree, unsigned int cells)
      : scene(testing_helpers::bar_scene(section, degree, cells))
      , bar(scene.bar)
      , discretisation(bar, scene.discretisation)
    {}
    nsm::Receptance receptance(nsm::ReceptanceMethod method, unsigned int modes = 0) const
    {
      return nsm::Receptance(discretisation, {method, modes}, 40.0);
    }
    nsm::Scene          scene;
    nsm::BarModel       bar;
    nsm::Discretisation discretisation;
  };

  // Between and near the poles (1.919, 4.874, 7.956) and zeros (3.097, 6.258).
  const std::vector<double> tapered_frequencies = {
    0.0, 0.5, 1.5, 1.9, 1.95, 2.5, 3.0, 3.1, 4.0, 4.86, 4.89, 6.0, 7.9};
} // namespace

TEST(Receptance, StaticValueIsLogThree)
{
  // gamma(0) = int dx / (E A) = ln 3. FE_Q(8) on 40 cells has a
  // discretisation error ~ h^16, far below the round-off of the sparse solve
  // (~100 eps measured), so the tolerance is the round-off level, 1e-12.
  const Model model("1.5 - x", 8, 40);
  EXPECT_NEAR(model.receptance(nsm::ReceptanceMethod::direct)(0.0).gamma,
              std::log(3.0), 1e-12);
}

TEST(Receptance, TaperedBarMatchesBesselSolution)
{
  // Relative error of gamma ~ relative error of the nearest eigenvalue times
  // w^2 / |w_j^2 - w^2|: the eigenvalues are exact to 1e-12 with FE_Q(8) on
  // 40 cells, and the closest frequency here is 0.8 % from a pole, so 1e-9.
  const Model model("1.5 - x", 8, 40);
  const auto receptance = model.receptance(nsm::ReceptanceMethod::direct);
  for (const double w : tapered_frequencies)
    EXPECT_NEAR(receptance(w).gamma / exact::tapered_receptance(w), 1.0, 1e-9)
      << "w = " << w;
}

TEST(Receptance, DerivativeMatchesFiniteDifferenceOfExact)
{
  // dgamma/d(w^2) = h^T M h against a centred difference of the exact gamma
  // (step 1e-4 in w^2: truncation ~ 1e-8 relative).
  const Model model("1.5 - x", 8, 40);
  const auto receptance = model.receptance(nsm::ReceptanceMethod::direct);
  for (const double w : {0.5, 1.5, 2.5, 4.0, 6.0})
    {
      const double s = w * w, ds = 1e-4;
      const double fd = (exact::tapered_receptance(std::sqrt(s + ds)) -
                         exact::tapered_receptance(std::sqrt(s - ds))) / (2 * ds);
      EXPECT_NEAR(receptance(w).dgamma_domega2 / fd, 1.0, 1e-6) << "w = " << w;
    }
}

TEST(Receptance, UniformBarIsTanOverOmega)
{
  // Uniform bar: gamma = tan(w) / w; FE_Q(8) on 20 cells, same reasoning.
  const Model model("1", 8, 20);
  const auto receptance = model.receptance(nsm::ReceptanceMethod::direct);
  for (const double w : {0.0, 0.3, 1.0, 1.5, 1.6, 3.0, 4.6, 4.8, 7.0})
    EXPECT_NEAR(receptance(w).gamma / exact::uniform_receptance(w), 1.0, 1e-9)
      << "w = " << w;
}

TEST(Receptance, DirectAndModalAgree)
{
  // Full modal basis: the same discrete gamma, to 1e-10 relative away from
  // poles (at least 1 % away here), for linear and high-order elements.
  // Round-off floor eps L / h_min < 1e-13 on these meshes.
  for (const auto &[degree, cells] : std::vector<std::pair<unsigned, unsigned>>{
         {1, 400}, {2, 100}, {5, 20}, {10, 4}})
    {
      const Model model("1.5 - x", degree, cells);
      const auto direct = model.receptance(nsm::ReceptanceMethod::direct);
      const auto modal = model.receptance(nsm::ReceptanceMethod::modal);
      for (const double w : tapered_frequencies)
        {
          const auto d = direct(w), m = modal(w);
          // Near a zero of gamma (w = 3.1 is 0.1 % above the clamped-clamped
          // w1) the modal terms, of the size of gamma(0), cancel: the rounding
          // of their sum is relative to gamma(0), not to gamma(w).
          const double scale = std::max(std::abs(d.gamma), direct(0.0).gamma);
          EXPECT_NEAR(m.gamma, d.gamma, 1e-10 * scale) << "p " << degree << ", w = " << w;
          EXPECT_NEAR(m.dgamma_domega2 / d.dgamma_domega2, 1.0, 1e-10)
            << "p " << degree << ", w = " << w;
        }
    }
}

TEST(Receptance, TruncatedModalBasisWithStaticCorrectionConverges)
{
  // With the static and first dynamic corrections, the modes left out above
  // w_m contribute w^4 sum_{j>m} r_j / w_j^6 ~ m^-5 (r_j bounded, w_j ~ j):
  // each doubling of the basis must divide the error by at least 16 (32
  // expected), and gamma(0) stays exact.
  const Model model("1.5 - x", 2, 100);
  const auto  direct = model.receptance(nsm::ReceptanceMethod::direct);
  double      previous = 0;
  for (const unsigned int modes : {5u, 10u, 20u, 40u})
    {
      const auto modal = model.receptance(nsm::ReceptanceMethod::modal, modes);
      EXPECT_NEAR(modal(0.0).gamma / direct(0.0).gamma, 1.0, 1e-12);
      double error = 0;
      for (const double w : {0.5, 2.5, 4.0, 6.0})
        error = std::max(error, std::abs(modal(w).gamma - direct(w).gamma));
      if (previous > 0)
        {
          EXPECT_LT(error, previous / 16) << modes << " modes";
        }
      previous = error;
    }
}

TEST(Receptance, FarModesAsASeriesKeepGammaInTheBand)
{
  // The paper's mesh (FE_Q(1), 4000 cells) and band (M = 40, W <= 2.2): only
  // the modes below 4 x 88 are computed, the others summed as a series. The
  // reference is gamma of the same pencil in long double: a direct solve in
  // double is not one here, its rounding eps cond(K) reaches 1e-10 at w = 0.
  // At every k W at least 1 % (in w^2) from a pole, gamma agrees to 1e-10;
  // gamma' = sum_j r_j / (w_j^2 - w^2)^2 to 1e-10 plus twice the eigenvalues'
  // relative error (1e-11, tested in NearModes) times w_j^2 / |w_j^2 - w^2|.
  const Model             model("1.5 - x", 1, 4000);
  const double            band = 40 * 2.2;
  const nsm::Receptance   split(model.discretisation, {nsm::ReceptanceMethod::modal, 0}, band);
  const nsm::BandedPencil pencil(model.discretisation, nsm::EndCondition::clamped_free);
  ASSERT_EQ(pencil.contact_row, pencil.n - 1);
  unsigned int checked = 0;
  for (const double omega : {1.92, 1.95, 2.2})
    for (unsigned int k = 0; k <= 40; ++k)
      {
        const double w2            = k * omega * k * omega;
        double       amplification = 1;
        for (const double l : split.poles())
          amplification = std::max(amplification, l / std::abs(l - w2));
        if (amplification > 100)
          continue;
        ++checked;
        const auto a                = split(k * omega);
        const auto [gamma, dgamma]  = extended::gamma(pencil, w2);
        EXPECT_NEAR(a.gamma, gamma, 1e-10 * std::max(1.0L, std::abs(gamma))) << k * omega;
        EXPECT_NEAR(a.dgamma_domega2 / dgamma, 1.0, 1e-10 + 2e-11 * amplification) << k * omega;
      }
  EXPECT_GT(checked, 80u);
  // Beyond the band only the direct solve holds every mode.
  const nsm::Receptance direct(model.discretisation, {nsm::ReceptanceMethod::direct, 0}, band);
  EXPECT_EQ(split(100.0).gamma, direct(100.0).gamma);
}

TEST(Receptance, PolesCountedFromTheSpectrum)
{
  const Model model("1.5 - x", 4, 40);
  const auto  receptance = model.receptance(nsm::ReceptanceMethod::direct);
  const auto  w = exact::roots(exact::tapered_clamped_free, 3);
  EXPECT_EQ(receptance.poles_below(w[0] * 0.99), 0u);
  EXPECT_EQ(receptance.poles_below(w[0] * 1.01), 1u);
  EXPECT_EQ(receptance.poles_below(w[2] * 1.01), 3u);
}

TEST(Receptance, TruncatedModalGammaHasOnlyItsBasisPoles)
{
  // The phase angle theta = atan(gamma) + pi #poles is continuous only if the
  // poles counted are those of the gamma evaluated.
  const Model model("1.5 - x", 2, 100);
  const auto  modal = model.receptance(nsm::ReceptanceMethod::modal, 5);
  EXPECT_EQ(modal.poles().size(), 5u);
  const double above = std::sqrt(modal.poles().back()) * 1.5;
  EXPECT_EQ(modal.poles_below(above), 5u);
  // gamma has no pole between: it stays finite and increasing in w^2.
  double previous = modal(std::sqrt(modal.poles().back()) * 1.01).gamma;
  for (double w = std::sqrt(modal.poles().back()) * 1.02; w < above; w *= 1.01)
    {
      const double g = modal(w).gamma;
      EXPECT_GT(g, previous) << "w = " << w;
      previous = g;
    }
}

namespace
{
  /// Direct and modal (full basis) gamma and d gamma / d w^2 agree to 1e-10
  /// of max(|gamma(w)|, gamma(0)) at frequencies at least 15 % from a pole:
  /// nearer, both inherit the eigenvalue's round-off, amplified by
  /// w^2 / |w_j^2 - w^2|.
  void expect_direct_and_modal_agree(const nsm::Discretisation &d, const std::string &mesh)
  {
    const std::vector<double> away_from_poles = {0.0, 0.5, 1.5, 2.5, 3.0, 3.1, 4.0, 6.0};
    const nsm::Receptance direct(d, {nsm::ReceptanceMethod::direct, 0}, 40.0);
    const nsm::Receptance modal(d, {nsm::ReceptanceMethod::modal, 0}, 40.0);
    const double          static_value = direct(0.0).gamma;
    for (const double w : away_from_poles)
      {
        const auto a = direct(w), b = modal(w);
        EXPECT_NEAR(b.gamma, a.gamma, 1e-10 * std::max(std::abs(a.gamma), static_value))
          << mesh << ", w = " << w;
        EXPECT_NEAR(b.dgamma_domega2 / a.dgamma_domega2, 1.0, 1e-10) << mesh << ", w = " << w;
      }
  }
} // namespace

TEST(Receptance, DirectAndModalAgreeOnGradedAndAdaptiveMeshes)
{
  // Meshes whose cells are not ordered left to right (adaptive) and whose
  // smallest cell is 1e-2 to 1e-3 of the largest: the round-off floor
  // eps p^2 L / h_min stays below 1e-11, so the two methods must agree to 1e-10. The
  // modal basis of these meshes has pairs of nearly equal eigenvalues (two
  // equal small cells): each mode of a pair must count once.
  nsm::Scene graded = testing_helpers::bar_scene("1.5 - x", 3, 40);
  graded.discretisation.refinement    = nsm::Refinement::graded;
  graded.discretisation.graded_ratio  = 0.7;
  graded.discretisation.graded_layers = 12;
  const nsm::BarModel       graded_bar(graded.bar);
  const nsm::Discretisation graded_mesh(graded_bar, graded.discretisation);
  expect_direct_and_modal_agree(graded_mesh, "graded");

  nsm::Scene adaptive = testing_helpers::bar_scene("1.5 - x", 1, 40);
  adaptive.discretisation.refinement         = nsm::Refinement::adaptive;
  adaptive.discretisation.adaptive_steps     = 10;
  adaptive.discretisation.adaptive_tolerance = 1e-14;
  const nsm::BarModel adaptive_bar(adaptive.bar);
  nsm::Discretisation adaptive_mesh(adaptive_bar, adaptive.discretisation);
  nsm::refine_adaptively(adaptive_mesh, adaptive.discretisation, 8.0);
  ASSERT_LT(adaptive_mesh.min_cell_size(), adaptive_mesh.max_cell_size() / 100);
  expect_direct_and_modal_agree(adaptive_mesh, "adaptive");
}
