// Floquet multipliers of the forced response on the compliant wall, by
// shooting to the stepped model's orbit: against the trapezoidal rule's
// exact multipliers off the wall, the steps' tangents against differences,
// and the fold test's parity along a curve in contact.
#include <nsm/continuation/forced_response.h>
#include <nsm/model/damped_receptance.h>
#include <nsm/verification/forced_floquet.h>
#include <nsm/verification/forced_modal_steps.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "forced_helpers.h"

namespace
{
  using Model   = testing_helpers::ForcedModel;
  using complex = std::complex<double>;

  /// The seed bar (FE_Q(10) x 10, M = 8, zeta = 0.002) on a compliant wall
  /// (k = 100), and its curve F = 4e-5 from 1.85 to 2.1.
  struct CompliantCurve
  {
    CompliantCurve()
      : model("1.5 - x", 10, 10, 8 * 2.2)
      , damped(model.receptance, damping())
      , hb(params(), contact(), damped)
      , curve(nsm::trace_forced_curve(hb, params(), nsm::ContinuationParameters(), 1.85, 2.1, 4e-5))
    {}
    static nsm::DampingParameters damping()
    {
      nsm::DampingParameters d;
      d.modal_ratio = 0.002;
      return d;
    }
    static nsm::HarmonicBalanceParameters params()
    {
      nsm::HarmonicBalanceParameters p;
      p.harmonics = 8;
      return p;
    }
    static nsm::ContactParameters contact()
    {
      nsm::ContactParameters c;
      c.wall      = nsm::Wall::compliant;
      c.stiffness = 100;
      return c;
    }
    Model                      model;
    nsm::DampedReceptance      damped;
    nsm::ForcedHarmonicBalance hb;
    nsm::ForcedCurve           curve;
  };
} // namespace

TEST(Floquet, OffTheWallEachModeDecaysAsTheTrapezoidalRuleSays)
{
  // Far from the wall the stepped model is each mode's damped oscillator
  // under Newmark's average acceleration, the trapezoidal rule on (q, v):
  // per step s -> (1 + s dt / 2) / (1 - s dt / 2), s = -c_j / 2 +- i (w_j^2
  // - c_j^2 / 4)^(1/2), and over the period its power `steps`. Every
  // computed multiplier is one of these to 1e-9, and the shooting, on a
  // linear map, ends within one Newton step.
  const Model            model("1", 4, 10, 1e4);
  nsm::DampingParameters damping;
  damping.modal_ratio = 0.01;
  const nsm::DampedReceptance    damped(model.receptance, damping);
  nsm::HarmonicBalanceParameters params;
  params.harmonics = 3;
  nsm::ContactParameters contact;
  contact.wall = nsm::Wall::compliant;
  contact.gap  = 1e3;
  nsm::ForcedHarmonicBalance hb(params, contact, damped);
  hb.set_forcing(1.0);
  hb.set_omega(1.3);
  const unsigned int            steps = 500;
  const nsm::FloquetMultipliers f     = nsm::floquet_multipliers(hb, std::vector<double>(hb.n_unknowns(), 0.0), steps);
  ASSERT_TRUE(f.converged());
  EXPECT_LE(f.newton_steps, 1u);
  const nsm::ModalData &modes = model.receptance.modes();
  ASSERT_EQ(f.values.size(), 2 * modes.eigenvalues.size());
  const double dt = 2 * M_PI / 1.3 / steps;
  for (std::size_t j = 0; j < modes.eigenvalues.size(); ++j)
    for (const double sign : {1.0, -1.0})
      {
        const double  c = damped.coefficients()[j];
        const complex s(-c / 2, sign * std::sqrt(modes.eigenvalues[j] - c * c / 4));
        const complex expected = std::pow((1.0 + s * dt / 2.0) / (1.0 - s * dt / 2.0), double(steps));
        double        nearest  = 1e300;
        for (const complex &m : f.values)
          nearest = std::min(nearest, std::abs(m - expected));
        EXPECT_LE(nearest, 1e-9) << "mode " << j + 1;
      }
  EXPECT_LT(f.largest(), 1);
  EXPECT_EQ(f.instability(), "");
}

TEST(Floquet, StepTangentsMatchDifferences)
{
  // At a point in contact of the compliant curve, the tangents that one and
  // twenty steps carry against central differences of the stepped map, step
  // 1e-6 of the state's size: the map is piecewise linear in the state, and
  // no contact start or end moves across a step boundary within +-h there,
  // so the two agree to the differences' rounding, 1e-16 / 1e-6 of the
  // entries (checked: 1e-7 of the largest).
  CompliantCurve c;
  const auto     in_contact = std::find_if(c.curve.points.begin(), c.curve.points.end(),
                                       [](const nsm::ForcedPoint &p) { return p.measures.contact_fraction > 0.1; });
  ASSERT_NE(in_contact, c.curve.points.end());
  nsm::ForcedHarmonicBalance &hb = c.hb;
  hb.set_omega(in_contact->omega);
  for (const unsigned int steps : {1u, 20u})
    {
      nsm::ForcedModalSteps     model(hb, in_contact->x, 1000);
      const std::vector<double> z = model.state();
      const unsigned int        n = model.modes();
      model.restart(z);
      std::vector<nsm::ForcedModalSteps::Tangent> tangents;
      for (const bool velocity : {false, true})
        for (unsigned int j = 0; j < n; ++j)
          tangents.push_back(model.start_tangent(j, velocity));
      for (unsigned int s = 0; s < steps; ++s)
        model.step(&tangents);
      const auto image = [&](const std::vector<double> &start) {
        nsm::ForcedModalSteps m(hb, in_contact->x, 1000);
        m.restart(start);
        for (unsigned int s = 0; s < steps; ++s)
          m.step();
        return m.state();
      };
      double size = 0;
      for (const double v : z)
        size = std::max(size, std::abs(v));
      double worst = 0, largest = 0;
      for (unsigned int column = 0; column < 2 * n; column += 3)
        {
          const double        h  = 1e-6 * size;
          std::vector<double> zp = z, zm = z;
          zp[column] += h;
          zm[column] -= h;
          const std::vector<double> plus = image(zp), minus = image(zm);
          for (unsigned int i = 0; i < 2 * n; ++i)
            {
              const double difference = (plus[i] - minus[i]) / (2 * h);
              const double tangent    = i < n ? tangents[column].q[i] : tangents[column].v[i - n];
              worst                   = std::max(worst, std::abs(difference - tangent));
              largest                 = std::max(largest, std::abs(difference));
            }
        }
      EXPECT_LE(worst, 1e-7 * largest) << steps << " steps";
    }
}

TEST(Floquet, TheFoldTestCountsTheRealMultipliersBeyondOne)
{
  // det J < 0 (the fold test's unstable) is an odd number of real
  // multipliers beyond +1: at every 6th point in contact of the compliant
  // curve where the shooting converges (13 of 27 measured), the parity
  // agrees; both verdicts occur among them, and some stable points lie
  // beyond the unit circle by a complex pair (Neimark-Sacker), which the
  // fold test cannot see.
  CompliantCurve              c;
  nsm::ForcedHarmonicBalance &hb = c.hb;
  unsigned int               converged = 0, unstable = 0, stable = 0;
  for (std::size_t i = 0; i < c.curve.points.size(); i += 6)
    {
      const nsm::ForcedPoint &p = c.curve.points[i];
      if (p.measures.contact_fraction == 0)
        continue;
      hb.set_omega(p.omega);
      const nsm::FloquetMultipliers f = nsm::floquet_multipliers(hb, p.x, 1000);
      if (!f.converged())
        continue;
      ++converged;
      (p.stable ? stable : unstable) += 1;
      EXPECT_LE(f.residual, nsm::floquet_constants::orbit_tolerance);
      EXPECT_EQ(f.beyond_plus_one() % 2 == 1, !p.stable) << "W = " << p.omega;
    }
  EXPECT_GE(converged, 10u);
  EXPECT_GE(unstable, 3u);
  EXPECT_GE(stable, 3u);
}

TEST(Floquet, TheLargestMultiplierSaysHowThePointIsUnstable)
{
  // Largest first, as floquet_multipliers sorts them.
  const auto of = [](std::vector<complex> values) {
    nsm::FloquetMultipliers f;
    f.values = std::move(values);
    return f;
  };
  EXPECT_EQ(of({{0.99, 0.0}, {0.5, 0.1}, {0.5, -0.1}}).instability(), "");
  EXPECT_EQ(of({{1.2, 0.0}, {1.1, 0.0}, {0.5, 0.0}}).instability(), "fold");
  EXPECT_EQ(of({{1.2, 0.0}, {1.1, 0.0}, {0.5, 0.0}}).beyond_plus_one(), 2u);
  EXPECT_EQ(of({{-1.3, 0.0}, {1.1, 0.0}}).instability(), "period doubling");
  EXPECT_EQ(of({{-1.3, 0.0}, {1.1, 0.0}}).beyond_plus_one(), 1u);
  EXPECT_EQ(of({{0.3, 1.02}, {0.3, -1.02}}).instability(), "Neimark-Sacker");
  EXPECT_EQ(of({{0.3, 1.02}, {0.3, -1.02}}).beyond_plus_one(), 0u);
  EXPECT_FALSE(of({}).converged());
}
