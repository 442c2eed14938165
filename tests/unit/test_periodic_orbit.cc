// The FE model's exact flow against the wall (modal_flow.h) and its
// periodic orbits found by shooting (periodic_orbit.h).
#include <nsm/verification/fields.h>
#include <nsm/verification/modal_flow.h>
#include <nsm/verification/orbit_refinement.h>
#include <nsm/verification/periodic_orbit.h>

#include <gtest/gtest.h>

#include <cmath>

#include "hb_model.h"
#include "uniform_tent.h"

namespace
{
  using testing_helpers::tent_gap;
  using testing_helpers::tent_wall;
  using UniformBar = testing_helpers::UniformTent;

  nsm::ModalState state_of(const nsm::ModalFlow &flow, const dealii::Vector<double> &u)
  {
    nsm::ModalState s{dealii::Vector<double>(flow.dofs().size()), dealii::Vector<double>(flow.dofs().size())};
    for (std::size_t i = 0; i < flow.dofs().size(); ++i)
      s.u[i] = u[flow.dofs()[i]];
    return s;
  }
} // namespace

TEST(ModalFlow, ConservesEnergyAndKeepsTheWallThroughItsSwitches)
{
  // The flow is exact: the energy of the redistributed-mass model is
  // conserved to round-off through every switch, if the switches happen
  // where both sides agree (a wall moved in the switch test alone, or a
  // wrong static offset, breaks it). The contact DoF never passes g0.
  const UniformBar     uniform(3.5, 2, 50);
  const nsm::ModalFlow flow(uniform.discretisation, tent_wall());
  nsm::ModalState      s  = state_of(flow, uniform.tent);
  const double         e0 = flow.strain_energy(s.u);
  unsigned int         switches = 0;
  for (unsigned int k = 0; k < 16; ++k)
    {
      switches += flow.advance(s, 3.5 / 8, nullptr).switches;
      EXPECT_NEAR((flow.strain_energy(s.u) + flow.kinetic_energy(s.v)) / e0, 1.0, 1e-9);
      EXPECT_LE(flow.contact_displacement(s.u), tent_gap);
    }
  EXPECT_GE(switches, 4u); // two periods, each with a landing and a release
}

TEST(PeriodicOrbit, MonodromyIsTheFlowsDerivativeAndPreservesVolume)
{
  // The tangent carried through the switches (saltation = identity) must
  // equal central differences of the flow; a conservative flow's monodromy
  // has determinant 1, its multipliers come in pairs mu, 1 / mu, and the
  // time shift and the family direction give a Jordan pair at 1.
  const UniformBar         uniform(3.5, 2, 40);
  const nsm::PeriodicOrbit orbit =
    nsm::find_periodic_orbit(uniform.discretisation, tent_wall(), 2 * M_PI / 3.5, uniform.tent, {1e-10, 1e-4, true});
  ASSERT_TRUE(orbit.converged);
  EXPECT_LT(orbit.periodicity, 1e-9);
  EXPECT_NEAR(std::abs(orbit.multipliers[0] - 1.0), 0.0, 1e-4);
  EXPECT_NEAR(std::abs(orbit.multipliers[1] - 1.0), 0.0, 1e-4);
  std::complex<double> determinant = 1;
  for (const auto &m : orbit.multipliers)
    {
      determinant *= m;
      double nearest = 1e300;
      for (const auto &n : orbit.multipliers)
        nearest = std::min(nearest, std::abs(n - 1.0 / m));
      EXPECT_LT(nearest, 1e-6 * std::max(1.0, std::abs(1.0 / m)));
    }
  EXPECT_NEAR(determinant.real(), 1.0, 1e-8);
  EXPECT_NEAR(determinant.imag(), 0.0, 1e-8);

  // Finite differences of one period against the tangent, for a few DoFs.
  const nsm::ModalFlow flow(uniform.discretisation, tent_wall());
  const std::size_t    k = flow.dofs().size();
  nsm::ModalState      s = state_of(flow, orbit.displacement);
  nsm::ModalTangents   t{dealii::LAPACKFullMatrix<double>(k, k), dealii::LAPACKFullMatrix<double>(k, k)};
  for (std::size_t i = 0; i < k; ++i)
    t.du(i, i) = 1;
  flow.advance(s, 3.5, &t);
  const double delta = 1e-6 * tent_gap;
  for (const std::size_t column : {std::size_t(3), k / 2, k - 2})
    {
      nsm::ModalState plus = state_of(flow, orbit.displacement), minus = plus;
      plus.u[column] += delta;
      minus.u[column] -= delta;
      flow.advance(plus, 3.5, nullptr);
      flow.advance(minus, 3.5, nullptr);
      double scale = 0, error = 0;
      for (std::size_t i = 0; i < k; ++i)
        {
          const double fd = (plus.v[i] - minus.v[i]) / (2 * delta);
          scale           = std::max(scale, std::abs(t.dv(i, column)));
          error           = std::max(error, std::abs(fd - t.dv(i, column)));
        }
      EXPECT_LT(error, 1e-5 * scale) << "column " << column;
    }
}

TEST(PeriodicOrbit, UniformBarOrbitHasTheTentsContactFraction)
{
  // From the tent, shooting lands on an orbit of the FE model whose contact
  // lasts (4 - T) / T of the period, within the time a wave takes to cross
  // two cells (the kink's position is known to a cell at each end), and
  // whose displacement at t = 0 holds the contact DoF on the wall.
  for (const double period : {3.2, 3.5, 3.8})
    {
      const unsigned int       cells = 50;
      const UniformBar         uniform(period, 2, cells);
      const nsm::PeriodicOrbit orbit = nsm::find_periodic_orbit(uniform.discretisation, tent_wall(), 2 * M_PI / period,
                                                                uniform.tent, {1e-10, 1e-4, false});
      ASSERT_TRUE(orbit.converged) << "T = " << period;
      EXPECT_NEAR(orbit.contact_fraction, (4 - period) / period, 2.0 / cells / period) << "T = " << period;
      EXPECT_DOUBLE_EQ(orbit.displacement[uniform.discretisation.contact_dof()], tent_gap);
      // Energy bound: u(L) = g0 at rest implies E >= g0^2 / 2 (method.md), and
      // the tent is the least-energy member of the family.
      EXPECT_GE(orbit.energy, tent_gap * tent_gap / 2);
      EXPECT_GE(orbit.energy, uniform.exact.energy * (1 - 0.02));
    }
}
