// The closed-form references that studies measure errors against: equal to
// the tests' own Bessel and tan formulas on the unit bars, and, on bars with
// other L, E, rho and tapers (where those formulas do not apply), to a
// converged FE_Q(10) solution of the same bar.
#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/exact_references.h>
#include <nsm/model/receptance.h>
#include <nsm/model/spectrum.h>

#include <gtest/gtest.h>

#include <cmath>

#include "exact_bar.h"
#include "scene_helpers.h"

namespace
{
  std::optional<nsm::ExactBar> exact_of(const nsm::BarParameters &bar)
  {
    return nsm::ExactBar::of(nsm::BarModel(bar));
  }

  nsm::BarParameters bar(const std::string &section, double length = 1, double young = 1, double density = 1)
  {
    nsm::BarParameters b;
    b.cross_section = section;
    b.length        = length;
    b.young_modulus = young;
    b.density       = density;
    return b;
  }
} // namespace

TEST(ExactReferences, OnlyConstantAndLinearSectionsHaveOne)
{
  EXPECT_EQ(exact_of(bar("1"))->name(), "uniform (tan)");
  EXPECT_EQ(exact_of(bar("1.5 - x"))->name(), "linear taper (Bessel)");
  EXPECT_FALSE(exact_of(bar("1.5 - x^2")));
  EXPECT_FALSE(exact_of(bar("1 + 1e-6 * x"))); // the Bessel form would lose digits
}

TEST(ExactReferences, UnitBarsMatchTheTestFormulas)
{
  const auto taper = exact_of(bar("1.5 - x"));
  const auto roots = exact::roots(exact::tapered_clamped_free, 6);
  const auto w     = taper->clamped_free_frequencies(6);
  for (std::size_t j = 0; j < roots.size(); ++j)
    EXPECT_NEAR(w[j], roots[j], 4e-15 * roots[j]);
  for (const double omega : {0.0, 0.3, 1.0, 2.5, 7.0})
    EXPECT_NEAR(taper->receptance(omega), exact::tapered_receptance(omega), 1e-13 * std::abs(exact::tapered_receptance(omega)));

  const auto uniform = exact_of(bar("1"));
  nsm::ContactParameters contact;
  contact.gap = 1e-3;
  const nsm::ContactLaw rigid_wall(contact);
  for (const double omega : {0.0, 0.3, 1.0, 2.5, 7.0})
    EXPECT_NEAR(uniform->receptance(omega), exact::uniform_receptance(omega), 1e-14 * std::abs(exact::uniform_receptance(omega)));
  for (const double omega : {1.6, 1.8, 2.05})
    EXPECT_NEAR(*uniform->first_mode_energy(omega, rigid_wall), exact::UniformMode(2 * M_PI / omega, 1e-3).energy,
                1e-15);
  EXPECT_FALSE(uniform->first_mode_energy(1.5, rigid_wall)); // below w1: no mode
  EXPECT_FALSE(taper->first_mode_energy(1.95, rigid_wall));
  // The tent is the rigid wall's mode with the physical sign only.
  contact.wall = nsm::Wall::compliant;
  EXPECT_FALSE(uniform->first_mode_energy(1.8, nsm::ContactLaw(contact)));
  contact.wall = nsm::Wall::rigid;
  contact.sign = nsm::ForceSign::seed_eq5;
  EXPECT_FALSE(uniform->first_mode_energy(1.8, nsm::ContactLaw(contact)));
}

TEST(ExactReferences, ScaledBarsMatchAConvergedDiscretisation)
{
  // Increasing and decreasing tapers, and a uniform bar, with L, E, rho != 1.
  for (const auto &b : {bar("0.5 + x", 2, 3, 0.5), bar("2 - 0.4 * x", 3, 0.5, 2), bar("0.7", 0.8, 5, 3)})
    {
      nsm::Scene scene = testing_helpers::bar_scene(b.cross_section, 10, 40);
      scene.bar        = b;
      const nsm::BarModel       model(b);
      const nsm::Discretisation d(model, scene.discretisation);
      const auto                exact = nsm::ExactBar::of(model);
      ASSERT_TRUE(exact);
      const auto fe = nsm::compute_spectrum(d, nsm::EndCondition::clamped_free, 5, false).eigenvalues;
      const auto w  = exact->clamped_free_frequencies(5);
      for (std::size_t j = 0; j < w.size(); ++j)
        EXPECT_NEAR(w[j], std::sqrt(fe[j]), 1e-10 * w[j]) << b.cross_section << " mode " << j + 1;
      const nsm::Receptance r(d, {nsm::ReceptanceMethod::direct, 0}, 0.0);
      for (const double f : {0.0, 0.5, 1.3})
        {
          const double omega = f * w[1];
          EXPECT_NEAR(exact->receptance(omega), r(omega).gamma, 1e-9 * std::abs(exact->receptance(omega)))
            << b.cross_section << " at " << omega;
        }
    }
}
