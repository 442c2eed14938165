// Discretisation/Contact mass = redistributed: no inertia at the contact DoF,
// the model of the periodic orbits in time, and harmonic balance on it.
#include <nsm/model/banded_pencil.h>
#include <nsm/model/mass_redistribution.h>
#include <nsm/model/spectrum.h>
#include <nsm/verification/fields.h>
#include <nsm/verification/orbit_refinement.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "hb_model.h"

namespace
{
  nsm::Scene redistributed_scene(const unsigned int degree, const unsigned int cells)
  {
    nsm::Scene scene                  = testing_helpers::bar_scene("1.5 - x", degree, cells);
    scene.discretisation.contact_mass = nsm::ContactMass::redistributed;
    return scene;
  }

  double total(const dealii::SparseMatrix<double> &m)
  {
    double sum = 0;
    for (const auto &e : m)
      sum += e.value();
    return sum;
  }

  /// K or M on the clamped-free DoFs, dense.
  dealii::FullMatrix<double> dense(const dealii::SparseMatrix<double> &a, const std::vector<unsigned int> &dofs)
  {
    dealii::FullMatrix<double> d(dofs.size(), dofs.size());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      for (unsigned int j = 0; j < dofs.size(); ++j)
        d(i, j) = a.el(dofs[i], dofs[j]);
    return d;
  }
} // namespace

TEST(ContactMass, RedistributionKeepsTheMassAndLeavesNoneAtTheContactDof)
{
  // The bar's total mass 1^T M 1 is unchanged, the contact DoF's row and
  // column are zero, and the clamped-free pencil has one finite eigenvalue
  // fewer than DoFs (the massless row's is infinite).
  const nsm::Scene     consistent = testing_helpers::bar_scene("1.5 - x", 3, 5);
  const nsm::Scene     moved      = redistributed_scene(3, 5);
  const nsm::BarModel  bar(consistent.bar);
  const nsm::Discretisation a(bar, consistent.discretisation), b(bar, moved.discretisation);
  EXPECT_NEAR(total(b.mass()), total(a.mass()), 1e-14 * total(a.mass()));
  EXPECT_GT(a.mass().diag_element(a.contact_dof()), 0);
  for (auto e = b.mass().begin(b.contact_dof()); e != b.mass().end(b.contact_dof()); ++e)
    {
      EXPECT_EQ(e->value(), 0.0);
      EXPECT_EQ(b.mass().el(e->column(), b.contact_dof()), 0.0);
    }
  const nsm::BandedPencil p(a, nsm::EndCondition::clamped_free), q(b, nsm::EndCondition::clamped_free);
  EXPECT_EQ(p.finite, p.n);
  EXPECT_EQ(q.finite, q.n - 1);
  // Applied again, it changes nothing.
  dealii::SparseMatrix<double> again(b.mass().get_sparsity_pattern());
  again.copy_from(b.mass());
  nsm::redistribute_contact_mass(again, b.contact_dof());
  for (const auto &e : again)
    EXPECT_EQ(e.value(), b.mass().el(e.row(), e.column()));
}

TEST(ContactMass, ReceptanceIsTheInverseOfTheCondensedDynamicStiffness)
{
  // Without inertia at the contact DoF, gamma(w) = 1 / (K_NN - k^T (K_II -
  // w^2 M_II)^{-1} k), k = K_IN: a dense inverse, independent of the band
  // LU and of the modal sums. Both receptances agree with it to 1e-9, and
  // at high frequency gamma tends to 1 / K_NN (the contact DoF alone, its
  // neighbours held by their inertia), where a consistent mass gives 0.
  const nsm::Scene          scene = redistributed_scene(4, 6);
  const nsm::BarModel       bar(scene.bar);
  const nsm::Discretisation d(bar, scene.discretisation);
  std::vector<unsigned int> inner;
  for (const unsigned int dof : d.free_dofs(true))
    inner.push_back(dof);
  const dealii::FullMatrix<double> k_ii = dense(d.stiffness(), inner), m_ii = dense(d.mass(), inner);
  dealii::Vector<double>           k(inner.size());
  for (unsigned int i = 0; i < inner.size(); ++i)
    k[i] = d.stiffness().el(inner[i], d.contact_dof());
  const double k_nn      = d.stiffness().diag_element(d.contact_dof());
  const auto   condensed = [&](const double w) {
    dealii::FullMatrix<double> a(k_ii);
    a.add(-w * w, m_ii);
    dealii::FullMatrix<double> inverse(a.m());
    inverse.invert(a);
    dealii::Vector<double> x(k.size());
    inverse.vmult(x, k);
    return 1 / (k_nn - (k * x));
  };
  // The modal receptance with a band (far modes split off) and without one
  // (every finite mode, and gamma's limit at infinity as a constant).
  for (const auto &[method, band] : {std::pair{nsm::ReceptanceMethod::direct, 10.0},
                                     std::pair{nsm::ReceptanceMethod::modal, 10.0},
                                     std::pair{nsm::ReceptanceMethod::modal, 0.0}})
    {
      nsm::ReceptanceParameters params;
      params.method = method;
      const nsm::Receptance gamma(d, params, band);
      for (const double w : {0.0, 0.7, 1.9, 2.6, 5.3, 9.1})
        {
          const double exact = condensed(w);
          EXPECT_NEAR(gamma(w).gamma, exact, 1e-9 * std::max(1.0, std::abs(exact))) << "w = " << w << ", band " << band;
        }
      EXPECT_NEAR(gamma(1e5).gamma * k_nn, 1.0, 1e-6) << "band " << band;
    }
  // The residues of gamma from the spectra (contact_residues: the last
  // pole is infinite) against (lambda_j - w^2) gamma(w) at w^2 = lambda_j
  // (1 -+ 1e-6), averaged: the smooth part of gamma cancels to first order
  // and an error e in lambda_j enters as (e / 1e-6 lambda_j)^2.
  nsm::ReceptanceParameters params;
  params.method = nsm::ReceptanceMethod::direct;
  const nsm::Receptance direct(d, params, 10.0);
  const nsm::ModalData  modes = nsm::compute_spectrum(d, nsm::EndCondition::clamped_free, 0, true);
  ASSERT_EQ(modes.eigenvalues.size(), d.n_dofs() - 2);
  for (const unsigned int j : {0u, 3u, unsigned(modes.eigenvalues.size() - 1)})
    {
      const double l = modes.eigenvalues[j], below = l * (1 - 1e-6), above = l * (1 + 1e-6);
      const double residue =
        ((l - below) * direct(std::sqrt(below)).gamma + (l - above) * direct(std::sqrt(above)).gamma) / 2;
      EXPECT_NEAR(modes.contact_residues[j] / residue, 1.0, 1e-6) << "mode " << j;
    }
  const nsm::Scene          with_mass = testing_helpers::bar_scene("1.5 - x", 4, 6);
  const nsm::Discretisation c(bar, with_mass.discretisation);
  EXPECT_LT(std::abs(nsm::Receptance(c, params, 10.0)(1e5).gamma * k_nn), 1e-3);
}

TEST(ContactMass, HarmonicBalanceApproachesThePeriodicOrbitOfItsOwnModel)
{
  // On one FE model (the seed bar, FE_Q(10) x 2, no inertia at the contact
  // DoF) the periodic orbit shot in time (exact flow, no truncation) is the
  // limit of harmonic balance as M grows. At four Omega of the main branch,
  // the solution at M = 20 followed to 40, 80 and 160: its energy error
  // against the orbit shot from the M = 160 point falls at each doubling and
  // is within 0.1 % at 160, and M = 20 is truncated (off by more than 1e-4),
  // so the reference is not the HB point itself. With a consistent mass HB
  // solves another model and the errors stall (0.3 % to 2.3 % at M = 40 to
  // 160, study_truncation): the mutation that keeps the contact DoF's mass
  // makes this test fail.
  nsm::Scene scene = testing_helpers::orbit_model_scene(2, 20);
  testing_helpers::HbModel  first(scene);
  const nsm::Backbone       backbone = first.backbone();
  // The main points nearest these Omega (none from 2.082 to 2.11: the points
  // at M = 20 there are another family, contact 0.07 to 0.12 after the
  // mode's 0.22).
  std::vector<double>              omegas = {1.9628, 2.1154, 2.1302, 2.1581};
  std::vector<std::vector<double>> energies(omegas.size());
  std::vector<nsm::BackbonePoint>  last;
  for (double &omega : omegas)
    {
      const nsm::BackbonePoint *nearest = nullptr;
      for (const nsm::BackbonePoint &p : backbone.points)
        if (p.branch == nsm::Branch::main && (!nearest || std::abs(p.omega - omega) < std::abs(nearest->omega - omega)))
          nearest = &p;
      ASSERT_TRUE(nearest != nullptr);
      omega = nearest->omega;
      last.push_back(*nearest);
      energies[last.size() - 1].push_back(nearest->measures.energy);
    }
  for (const unsigned int m : {40u, 80u, 160u})
    {
      scene.harmonic_balance.harmonics = m;
      testing_helpers::HbModel model(scene);
      for (std::size_t i = 0; i < omegas.size(); ++i)
        {
          const auto point = testing_helpers::with_more_harmonics(model, last[i]);
          ASSERT_TRUE(point) << "M = " << m << ", Omega = " << omegas[i];
          last[i] = *point;
          energies[i].push_back(point->measures.energy);
          if (m < 160)
            continue;
          const nsm::PeriodicField field(model.hb, model.discretisation, *point);
          const nsm::PeriodicOrbit orbit =
            nsm::refine_point(field, model.discretisation, model.hb.law(), model.scene.output, {});
          ASSERT_TRUE(orbit.converged) << "Omega = " << omegas[i];
          std::vector<double> errors;
          for (const double e : energies[i])
            errors.push_back(std::abs(e / orbit.energy - 1));
          EXPECT_GT(errors[0], 1e-4) << "Omega = " << omegas[i];
          for (std::size_t j = 1; j < errors.size(); ++j)
            EXPECT_LT(errors[j], errors[j - 1]) << "Omega = " << omegas[i] << ", M = " << (20u << j);
          EXPECT_LT(errors.back(), 1e-3) << "Omega = " << omegas[i];
        }
    }
}
