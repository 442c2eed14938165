// The rebuilt fields against the harmonic balance: the contact DoF carries
// the HB displacement, and the energy of the field vectors themselves,
// u'^T M u' / 2 + u^T K u / 2, matches the HB energy formula (which never
// forms a field).
#include <nsm/verification/fields.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hb_model.h"

TEST(Fields, FieldEnergyAndContactDisplacementMatchTheHarmonicBalance)
{
  for (const auto sign : {nsm::ForceSign::physical, nsm::ForceSign::seed_eq5})
    {
      auto scene = testing_helpers::hb_scene("1.5 - x", 20);
      scene.contact.sign              = sign;
      scene.continuation.omega_min    = 1.85;
      scene.continuation.omega_max    = 1.99;
      scene.continuation.energy_max   = 1e-3;
      scene.continuation.max_steps    = 30;
      testing_helpers::HbModel model(scene);
      const auto               backbone = model.backbone();
      const auto              &point    = backbone.points.back();
      const nsm::PeriodicField field(model.hb, model.discretisation, point);

      const auto        &k = model.discretisation.stiffness(), &m = model.discretisation.mass();
      const unsigned int samples = 200;
      double             mean = 0, low = 1e300, high = 0;
      for (unsigned int j = 0; j < samples; ++j)
        {
          const double t = field.period() * j / samples;
          const auto   u = field.displacement(t), v = field.velocity(t);
          EXPECT_NEAR(u[model.discretisation.contact_dof()], field.contact_displacement(t),
                      1e-12 * scene.contact.gap);
          const double energy = 0.5 * m.matrix_norm_square(v) + 0.5 * k.matrix_norm_square(u);
          mean += energy / samples;
          low = std::min(low, energy), high = std::max(high, energy);
        }
      // 200 samples integrate the degree-40 trigonometric energy exactly.
      EXPECT_NEAR(mean / point.measures.energy, 1.0, 1e-9);
      // The spread from 200 samples against the HB's 4 (2M + 1) = 164.
      EXPECT_NEAR((high - low) / mean, point.measures.energy_spread, 0.1 * point.measures.energy_spread);
    }
}
