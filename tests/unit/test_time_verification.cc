// Verification in time: the integrator against the uniform bar's exact
// nonsmooth mode, and backbone points against their own time integration.
#include <nsm/verification/time_verification.h>

#include <gtest/gtest.h>

#include <cmath>

#include "hb_model.h"
#include "uniform_tent.h"

namespace
{
  using testing_helpers::tent_gap;

  /// The uniform bar's exact mode on a mesh of FE_Q(1) (uniform_tent.h), and
  /// the integration of its period. The impulse per period is 2 (u* - g0).
  struct ExactMode : testing_helpers::UniformTent
  {
    ExactMode(unsigned int cells, double period, unsigned int steps)
      : UniformTent(period, 1, cells)
      , integrator(discretisation, testing_helpers::tent_wall(), period, steps)
      , u(tent)
      , v(discretisation.n_dofs())
      , exact_impulse(2 * (exact.peak - tent_gap))
    {
      result = integrator.run(u, v, 2);
    }

    nsm::ContactTimeIntegrator integrator;
    dealii::Vector<double>     u, v;
    double                     exact_impulse;
    nsm::TimeVerification      result{};
  };
} // namespace

TEST(TimeVerification, ExactUniformModeComesBackWithItsEnergyContactAndImpulse)
{
  // T = 3.5, time step h (Courant number 1). An independent implementation
  // measured one-period defects of 0.53 %, 0.35 % and 0.22 % with 1000, 2000
  // and 4000 cells (the kinks of the exact motion converge slowly); this one
  // 0.73 %, 0.47 %, 0.30 %: both must fall with h, within a factor 1.5 of it.
  const double period = 3.5;
  const double independent[] = {0.0053, 0.0035, 0.0022};
  double       previous      = 1;
  for (unsigned int i = 0; i < 3; ++i)
    {
      const unsigned int cells = 1000 << i;
      const ExactMode    mode(cells, period, std::lround(period * cells));
      // The mesh holds the tent exactly (x* = 3/4 is a node): its energy is.
      EXPECT_NEAR(mode.integrator.energy(mode.u, mode.v) / mode.exact.energy, 1.0, 1e-10);
      EXPECT_NEAR(mode.exact.peak / tent_gap, 1.5, 1e-12);
      const nsm::TimeVerification &r = mode.result;
      EXPECT_LT(r.periodicity_defect, 1.5 * independent[i]);
      EXPECT_GT(r.periodicity_defect, independent[i] / 1.5);
      EXPECT_LT(r.periodicity_defect, previous);
      previous = r.periodicity_defect;
      // Contact fraction (4 - T) / T = 1/7 to a few steps; impulse 2 (u* - g0) = g0 to 2 %.
      EXPECT_NEAR(r.contact_fraction, (4 - period) / period, 1e-3);
      EXPECT_NEAR(r.impulse / mode.exact_impulse, 1.0, 0.02);
      EXPECT_NEAR(mode.exact_impulse, tent_gap, 1e-15);
      // Energy-conserving scheme: the drift is the impacts' O(dt) loss.
      EXPECT_LT(std::abs(r.energy_drift), 1e-3);
    }
}

TEST(TimeVerification, ExactUniformModeDwellsFourMinusTOnTheWall)
{
  // At T = 3.5 the dwell 4 - T equals T - 3; periods on both sides of it tell
  // the exact dwell from that coincidence (time step h). The impulse and the
  // one-period defect converge with h (measured with 1000 and 2000 cells:
  // impulse 0.9 % and 0.5 % low at T = 3.25, 2.6 % and 1.7 % at T = 3.8,
  // where the dwell is 200 steps; defects 1.6 % and 1.0 %, 0.40 % and 0.26 %).
  for (const double period : {3.25, 3.8})
    {
      double impulse_error = 1, defect = 1;
      for (const unsigned int cells : {1000u, 2000u})
        {
          const ExactMode mode(cells, period, std::lround(period * cells));
          const nsm::TimeVerification &r = mode.result;
          EXPECT_NEAR(r.contact_fraction, (4 - period) / period, 1e-3);
          EXPECT_LT(std::abs(r.impulse / mode.exact_impulse - 1), impulse_error);
          EXPECT_LT(r.periodicity_defect, defect);
          impulse_error = std::abs(r.impulse / mode.exact_impulse - 1);
          defect        = r.periodicity_defect;
        }
      EXPECT_LT(impulse_error, 0.02);
      EXPECT_LT(defect, 0.011);
    }
}

TEST(TimeVerification, PenetrationIsRemovedWithTheStaticShape)
{
  const ExactMode        mode(100, 3.5, 100);
  dealii::Vector<double> u(mode.u);
  u *= 1.1; // u(L) = 1.1 g0: 10 % into the wall
  mode.integrator.make_admissible(u);
  const unsigned int n = mode.discretisation.contact_dof();
  EXPECT_EQ(u[n], tent_gap);
  // The static shape of the uniform bar clamped at 0 is x: the whole tent
  // is lowered by 0.1 g0 x, not the contact DoF alone.
  const auto x = mode.discretisation.support_points();
  for (unsigned int i = 0; i < x.size(); ++i)
    EXPECT_NEAR(u[i], 1.1 * mode.u[i] - 0.1 * tent_gap * x[i], 1e-15);
}

TEST(TimeVerification, RedistributedMassKeepsTheBarsMassAndLeavesTheContactDofWithout)
{
  for (const unsigned int degree : {1u, 4u})
    {
      auto                      scene = testing_helpers::bar_scene("1.5 - x", degree, 20);
      const nsm::BarModel       bar(scene.bar);
      const nsm::Discretisation d(bar, scene.discretisation);
      const nsm::ContactTimeIntegrator integrator(d, testing_helpers::tent_wall(), 3.5, 100);
      dealii::Vector<double>    zero(d.n_dofs()), ones(d.n_dofs()), contact(d.n_dofs());
      ones = 1;
      ones[d.clamped_dof()] = 0;
      // Uniform unit velocity: kinetic energy m / 2 with the full and the
      // redistributed mass alike (m = 1.5 - 1/2 = 1, minus the clamped DoF's share).
      EXPECT_NEAR(integrator.energy(zero, ones), d.mass().matrix_norm_square(ones) / 2, 1e-14);
      EXPECT_NEAR(integrator.energy(zero, ones), 0.5, 0.5 / 20);
      contact[d.contact_dof()] = 1;
      EXPECT_EQ(integrator.energy(zero, contact), 0.0);
    }
}

namespace
{
  /// The verification of the seed bar's physical point at Omega on a mesh
  /// of 40 FE_Q(10) cells.
  nsm::PointVerification seed_point(unsigned int harmonics, double omega, unsigned int steps,
                                    nsm::ForceSign sign = nsm::ForceSign::physical)
  {
    auto scene = testing_helpers::hb_scene("1.5 - x", harmonics);
    scene.discretisation.cells     = 40;
    scene.contact.sign             = sign;
    scene.continuation.omega_min   = sign == nsm::ForceSign::physical ? 1.5 : 1.85;
    scene.continuation.omega_max   = sign == nsm::ForceSign::physical ? omega + 0.01 : 1.95;
    scene.continuation.energy_max  = 1e-3;
    scene.output.verify_steps      = steps;
    scene.output.verify_periods    = 1;
    testing_helpers::HbModel  model(scene);
    const auto                backbone = model.backbone();
    const nsm::PeriodicField field(model.hb, model.discretisation,
                                    nsm::solve_on_branch(model.hb, nsm::BranchParameters(scene), backbone, omega));
    return nsm::verify_in_time(field, model.discretisation, model.hb.law(), scene.output);
  }
} // namespace

TEST(TimeVerification, SeedPointBecomesPeriodicAsHarmonicsGrow)
{
  // Omega = 1.924, on a smooth piece of the physical branch. An independent
  // integration measured one-period defects of 0.27 %, 0.09 % and 0.05 % at
  // M = 20, 40, 80; here 0.27 %, 0.08 %, 0.07 %: within a factor 1.5, falling.
  const double independent[] = {0.0027, 0.0009, 0.0005};
  double       previous      = 1;
  for (unsigned int i = 0; i < 3; ++i)
    {
      const nsm::PointVerification v = seed_point(20 << i, 1.924, 8000);
      EXPECT_LT(v.time.periodicity_defect, 1.5 * independent[i]);
      EXPECT_GT(v.time.periodicity_defect, independent[i] / 1.5);
      EXPECT_LT(v.time.periodicity_defect, previous);
      previous = v.time.periodicity_defect;
      EXPECT_TRUE(v.verified);
      // The wall's impulse is the harmonic balance's to within 10 %.
      EXPECT_NEAR(v.impulse_ratio, 1.0, 0.1);
      EXPECT_LT(std::abs(v.time.energy_drift), 1e-5);
    }
}

TEST(TimeVerification, TimeStepIsConverged)
{
  // Doubling the default 4000 steps per period moves the defect by less than
  // a tenth of itself.
  const double coarse = seed_point(40, 1.924, 4000).time.periodicity_defect;
  const double fine   = seed_point(40, 1.924, 8000).time.periodicity_defect;
  EXPECT_NEAR(coarse / fine, 1.0, 0.1);
}

TEST(TimeVerification, Eq5PointsAreNotMotionsOfThePhysicalBar)
{
  // The paper's eq. (5) sign: the bar integrated against the real wall
  // barely touches it (measured impulse ratios 0 and 1.7 %).
  for (const double omega : {1.88, 1.907})
    {
      const nsm::PointVerification v = seed_point(40, omega, 4000, nsm::ForceSign::seed_eq5);
      EXPECT_LT(v.impulse_ratio, 0.05);
      EXPECT_GT(v.time.periodicity_defect, 10 * seed_point(40, 1.924, 4000).time.periodicity_defect);
      EXPECT_FALSE(v.verified);
    }
}
