// Backbones against exact and independent references (method.md section 4):
// the uniform bar's exact energy, the seed bar's grazing and sign, scale
// invariance, Signorini conditions, and the continuation methods.
#include <gtest/gtest.h>

#include <cmath>

#include "hb_model.h"

namespace
{
  using testing_helpers::HbModel;
  using testing_helpers::seed_scene;
  using testing_helpers::w1_seed;

  nsm::Scene uniform_scene(unsigned int harmonics)
  {
    auto scene = testing_helpers::hb_scene("1", harmonics);
    scene.continuation.omega_max  = 1.85;
    scene.continuation.max_step   = 0.005;
    scene.continuation.energy_max = 1e-5; // 10 g0^2: the tongues rise above it
    return scene;
  }

  /// Uniform bar, L = c = EA = 1: E = g0^2 / (2 (T - 3)^2), T = 2 pi / W.
  double exact_uniform_energy(double omega, double gap)
  {
    const double period = 2 * M_PI / omega;
    return gap * gap / (2 * (period - 3) * (period - 3));
  }

  double relative_energy_error(unsigned int harmonics, double omega)
  {
    HbModel    model(uniform_scene(harmonics));
    const auto backbone = model.backbone();
    const auto point    = nsm::solve_on_branch(model.hb, model.branch, backbone, omega);
    return point.measures.energy / exact_uniform_energy(omega, model.scene.contact.gap) - 1;
  }
} // namespace

TEST(Backbone, UniformBarApproachesTheExactEnergy)
{
  // Measured truncation errors (exact integration): W = 1.6: 6.0 % (M = 10),
  // 1.0 % (M = 20); W = 1.8: 12.9 %, 2.7 %. Tolerances: 1.5 x these.
  const double e10_low = relative_energy_error(10, 1.6), e20_low = relative_energy_error(20, 1.6);
  const double e10_high = relative_energy_error(10, 1.8), e20_high = relative_energy_error(20, 1.8);
  EXPECT_LT(std::abs(e10_low), 0.09);
  EXPECT_LT(std::abs(e20_low), 0.015);
  EXPECT_LT(std::abs(e10_high), 0.20);
  EXPECT_LT(std::abs(e20_high), 0.04);
  EXPECT_LT(std::abs(e20_low), std::abs(e10_low));
  EXPECT_LT(std::abs(e20_high), std::abs(e10_high));
}

TEST(Backbone, SignoriniViolationShrinksWithHarmonics)
{
  // Sampled lambda >= 0, g >= 0, lambda g = 0 hold up to the truncation's
  // Gibbs oscillations, which shrink with M. Measured at W = 1.6 on the
  // uniform bar (M = 10, 20, 40): min g / g0 = -0.038, -0.020, -0.008;
  // min lambda / max lambda = -0.11, -0.068, -0.034; max |lambda g| / (max
  // lambda g0) = 0.052, 0.020, 0.0078.
  // Tolerances: 1.5 x the measured values.
  struct Bound
  {
    unsigned int m;
    double       gap, force, complementarity;
  };
  double previous_gap = 1, previous_complementarity = 1;
  for (const Bound &b : {Bound{10, 0.057, 0.17, 0.078}, Bound{20, 0.030, 0.10, 0.030},
                         Bound{40, 0.012, 0.051, 0.012}})
    {
      HbModel    model(uniform_scene(b.m));
      const auto backbone = model.backbone();
      const auto p = nsm::solve_on_branch(model.hb, model.branch, backbone, 1.6).measures;
      EXPECT_GT(p.min_gap, -b.gap) << "M = " << b.m;
      EXPECT_GT(p.min_force, -b.force) << "M = " << b.m;
      EXPECT_LT(p.max_complementarity, b.complementarity) << "M = " << b.m;
      EXPECT_LT(-p.min_gap, previous_gap);
      EXPECT_LT(p.max_complementarity, previous_complementarity);
      previous_gap = -p.min_gap, previous_complementarity = p.max_complementarity;
    }
}

TEST(Backbone, PhysicalSeedBranchLeavesGrazingUpwards)
{
  HbModel    model(seed_scene(nsm::ForceSign::physical, 1.5, 2.2));
  const auto backbone = model.backbone();
  ASSERT_GT(backbone.points.size(), 50u);
  const double linear = backbone.points.front().measures.energy;
  // Independent of the contact law: at grazing the motion is the first linear
  // mode with u(L) = g0, of energy w1^2 g0^2 / (2 phi_1(L)^2). The start lies
  // 1e-5 relative above w1 with a brief impact (contact fraction 1.4 %):
  // measured 1.1e-3 above the linear energy, so 1 % bounds it, while a wrong
  // gap or residue is off by tens of per cent (a wall at g0 / 2: by 75 %).
  EXPECT_NEAR(linear / model.grazing(1).second, 1.0, 1e-2);
  for (const auto &p : backbone.points)
    {
      EXPECT_GT(p.omega, w1_seed) << "energy " << p.measures.energy;
      EXPECT_GT(p.measures.energy, 0.98 * linear) << "W = " << p.omega;
      EXPECT_LE(p.residual, model.scene.harmonic_balance.tolerance);
      EXPECT_GT(p.measures.contact_fraction, 0);
    }
  // Hardening: at the end of the range the energy is several times the
  // grazing value (measured: 6.8e-7 at grazing, ~1e-5 at W = 2.2).
  EXPECT_GT(backbone.points.back().measures.energy, 5 * linear);
  EXPECT_GT(backbone.points.back().omega, 2.15);
}

TEST(Backbone, SeedEq5BranchPassesThePapersFrequencyBelowW1)
{
  HbModel    model(seed_scene(nsm::ForceSign::seed_eq5, 1.85, 1.95));
  const auto backbone = model.backbone();
  for (const auto &p : backbone.points)
    EXPECT_LT(p.omega, w1_seed);
  // Independent of the sign of the law: the branch leaves grazing (just below
  // w1 here) with the first linear mode at u(L) = g0, of energy
  // w1^2 g0^2 / (2 phi_1(L)^2), to 1 % as on the physical side.
  EXPECT_NEAR(backbone.points.front().measures.energy / model.grazing(1).second, 1.0, 1e-2);
  const auto at_figure = nsm::solve_on_branch(model.hb, model.branch, backbone, 1.907);
  // 0.6 % below w1 the eq. (5) motion is still the first linear mode with
  // u(L) = g0, whose energy g0^2 (w1^2 + W^2) / (4 phi_1(L)^2) is the grazing
  // energy to 0.6 %: within 10 % of it (measured 4 % above, 0.69 g0^2).
  EXPECT_NEAR(at_figure.measures.energy / model.grazing(1).second, 1.0, 0.1);
  // The branch goes down in Omega: it reaches Omega min, its lowest point.
  EXPECT_EQ(backbone.end, nsm::BackboneEnd::range);
  EXPECT_EQ(backbone.omega_reached(nsm::branch_direction(model.scene.contact)), model.scene.continuation.omega_min);
}

TEST(Backbone, DoublingTheGapMultipliesEnergiesByFour)
{
  auto scene = seed_scene(nsm::ForceSign::physical, 1.5, 2.0);
  HbModel    small(scene);
  scene.contact.gap *= 2;
  HbModel    large(scene);
  const auto a = small.backbone(), b = large.backbone();
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i)
    {
      ASSERT_EQ(a.points[i].omega, b.points[i].omega);
      EXPECT_NEAR(b.points[i].measures.energy / a.points[i].measures.energy, 4.0, 4e-8);
    }
}

TEST(Backbone, SequentialAndArclengthAgree)
{
  // Where both converge they are on the same branch: the solution at a W
  // reached by both is the same to the Newton tolerance.
  auto scene = uniform_scene(10);
  scene.continuation.omega_max = 1.7;
  HbModel sequential(scene);
  scene.continuation.method = nsm::ContinuationMethod::arclength;
  HbModel    arclength(scene);
  const auto bs = sequential.backbone(), ba = arclength.backbone();
  ASSERT_GT(ba.points.size(), 10u);
  for (const double omega : {1.6, 1.65})
    {
      const auto ps = nsm::solve_on_branch(sequential.hb, nsm::BranchParameters(scene), bs, omega);
      const auto pa = nsm::solve_on_branch(arclength.hb, nsm::BranchParameters(scene), ba, omega);
      EXPECT_NEAR(pa.measures.energy / ps.measures.energy, 1.0, 1e-9) << "W = " << omega;
    }
  // LOCA's own points, as it wrote them: each is the sequential branch's
  // solution at its W. Both meet the residual tolerance 1e-10 with a Jacobian
  // of order 1, so their energies agree to 1e-8.
  unsigned int compared = 0;
  for (const auto &pa : ba.points)
    if (pa.segment == 0 && pa.omega > bs.points.front().omega && pa.omega < 1.69)
      {
        const auto ps = nsm::solve_on_branch(sequential.hb, nsm::BranchParameters(scene), bs, pa.omega);
        EXPECT_NEAR(pa.measures.energy / ps.measures.energy, 1.0, 1e-8) << "W = " << pa.omega;
        ++compared;
      }
  EXPECT_GT(compared, 10u);
}

namespace
{
  /// The largest change from one point of a segment to the next, of the
  /// contact fraction and of Omega, each with the Omega where it ends.
  struct LargestSteps
  {
    double contact = 0, contact_at = 0, omega = 0, omega_at = 0;
  };

  LargestSteps largest_steps(const nsm::Backbone &b)
  {
    LargestSteps largest;
    for (std::size_t i = 1; i < b.points.size(); ++i)
      {
        const auto &from = b.points[i - 1], &to = b.points[i];
        if (from.segment != to.segment)
          continue;
        const double contact = std::abs(to.measures.contact_fraction - from.measures.contact_fraction);
        const double omega   = std::abs(to.omega - from.omega);
        if (contact > largest.contact)
          {
            largest.contact    = contact;
            largest.contact_at = to.omega;
          }
        if (omega > largest.omega)
          {
            largest.omega    = omega;
            largest.omega_at = to.omega;
          }
      }
    return largest;
  }

  /// The energies of b's main branch at omega: linear between consecutive
  /// main points of one segment that bracket it (scripts/compare_backbones.py).
  std::vector<double> main_energies_at(const nsm::Backbone &b, const double omega)
  {
    std::vector<double> energies;
    const auto         &p = b.points;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
      if (p[i].segment == p[i + 1].segment && p[i].branch == nsm::Branch::main &&
          p[i + 1].branch == nsm::Branch::main && p[i].omega != p[i + 1].omega &&
          (p[i].omega - omega) * (p[i + 1].omega - omega) <= 0)
        energies.push_back(p[i].measures.energy + (p[i + 1].measures.energy - p[i].measures.energy) *
                                                    (omega - p[i].omega) / (p[i + 1].omega - p[i].omega));
    return energies;
  }

  struct Agreement
  {
    unsigned int compared = 0, agree = 0;
  };

  /// a's main points inside a main piece of b, and how many of them agree
  /// with b's energy there to 1e-3 relative (the closest piece).
  Agreement main_points_agreement(const nsm::Backbone &a, const nsm::Backbone &b)
  {
    Agreement result;
    for (const auto &p : a.points)
      {
        const auto energies = main_energies_at(b, p.omega);
        if (p.branch != nsm::Branch::main || energies.empty())
          continue;
        ++result.compared;
        double closest = INFINITY;
        for (const double e : energies)
          closest = std::min(closest, std::abs(e / p.measures.energy - 1));
        result.agree += closest <= 1e-3;
      }
    return result;
  }
} // namespace

TEST(Backbone, SequentialMainBranchDoesNotDependOnTheStepSize)
{
  // Seed bar to W = 2 with the default steps (up to 1e-2) and with steps of
  // 1e-4. Measured: 115 of the 116 coarse main points inside a fine main
  // piece agree to 1e-3 (the other is the last, at 2.0, where the fine run
  // ends on a tongue's flank). Without the contact guard on sequential steps,
  // 55 of 68 (81 %), and steps changed the contact fraction by up to 0.05.
  auto coarse = seed_scene(nsm::ForceSign::physical, 1.5, 2.0);
  auto fine   = coarse;
  fine.continuation.initial_step = fine.continuation.max_step = 1e-4;
  fine.continuation.max_steps = 10000;
  HbModel    coarse_model(coarse), fine_model(fine);
  const auto a = coarse_model.backbone(), b = fine_model.backbone();
  for (const auto *backbone : {&a, &b})
    {
      const LargestSteps largest = largest_steps(*backbone);
      EXPECT_LE(largest.contact, coarse.continuation.max_contact_change) << "W = " << largest.contact_at;
    }
  const auto [compared, agree] = main_points_agreement(a, b);
  ASSERT_GE(compared, 100u);
  EXPECT_GE(agree, 0.95 * compared) << agree << " of " << compared;
}

TEST(Backbone, ArclengthMainPointsLieOnTheBranchSmallStepsFind)
{
  // prm/seed-high-order.prm with arclength, against sequential steps of 1e-4
  // (which agree with the default steps at 98 %). Measured: 135 of the 148
  // arclength main points inside a fine main piece agree to 1e-3 (91 %); 177
  // of 229 (77 %) while a point that came back over a fold could be main.
  auto fine                      = seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
  fine.discretisation.cells      = 7;
  auto coarse                    = fine;
  coarse.continuation.method     = nsm::ContinuationMethod::arclength;
  coarse.continuation.max_steps  = 5000;
  fine.continuation.initial_step = fine.continuation.max_step = 1e-4;
  fine.continuation.max_steps    = 10000;
  HbModel    coarse_model(coarse), fine_model(fine);
  const auto a = coarse_model.backbone(), b = fine_model.backbone();
  const auto [compared, agree] = main_points_agreement(a, b);
  ASSERT_GE(compared, 100u);
  EXPECT_GE(agree, 0.9 * compared) << agree << " of " << compared;
}

namespace
{
  /// Runs the seed bar to W = 2.2 with `coarse` steps and with steps of 1e-4,
  /// which end on a tongue's flank; checks that the fine run looked below the
  /// flank at 2.2 and found the coarse run's end (one branch whatever the
  /// path, to the Newton tolerance). The fine run's points go to `p`.
  void check_branch_found_below_the_end(const nsm::Scene &coarse, std::vector<nsm::BackbonePoint> &p)
  {
    auto fine                      = coarse;
    fine.continuation.initial_step = fine.continuation.max_step = 1e-4;
    fine.continuation.max_steps    = 10000;
    HbModel    coarse_model(coarse), fine_model(fine);
    const auto a = coarse_model.backbone();
    p            = fine_model.backbone().points;
    ASSERT_GE(p.size(), 3u);
    const auto &end = p.back(), &flank = p[p.size() - 2];
    ASSERT_EQ(end.omega, 2.2);
    ASSERT_EQ(flank.omega, 2.2) << "the run did not look below the flank it ended on";
    EXPECT_EQ(end.branch, nsm::Branch::main);
    EXPECT_EQ(flank.branch, nsm::Branch::tongue);
    EXPECT_GT(flank.measures.energy, (1 + fine.continuation.tongue_share) * end.measures.energy);
    ASSERT_EQ(a.points.back().omega, 2.2);
    EXPECT_EQ(a.points.back().branch, nsm::Branch::main);
    EXPECT_NEAR(end.measures.energy / a.points.back().measures.energy, 1, 1e-8);
  }
} // namespace

TEST(Backbone, ARunEndingOnATonguesFlankFindsTheBranchBelowAtOmegaMax)
{
  // The seed bar on FE_Q(10) x 7 (prm/seed-high-order.prm) to W = 2.2. With
  // the default steps a leap lands at 2.2 on the branch; with steps of 1e-4
  // the run reaches 2.2 on the descending flank of a tongue, 33 % above it,
  // which the labels called main with nothing written beyond. Measured: the
  // branch found below the flank equals the default run's end to 1.4e-14
  // (8 % above it when only the segments' first points were guesses).
  auto coarse                 = seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
  coarse.discretisation.cells = 7;
  std::vector<nsm::BackbonePoint> p;
  check_branch_found_below_the_end(coarse, p);
}

TEST(Backbone, ARunEndingWhileClimbingATongueFindsTheBranchBelowWithMoreContact)
{
  // The seed bar on FE_Q(10) x 10 to W = 2.2. With steps of 1e-4 the run
  // reaches 2.2 climbing a tongue (w_27 / 38), 3.7 times above the branch,
  // which the labels called main; steps of 1e-3 end on the branch. Searching
  // every end without a contact condition puts the uniform bar's ends on
  // branches 38 to 80 % below its exact energy (MainBranch.UniformBar* fail);
  // those have a third of the end's contact fraction. Measured here: flank
  // 0.208, branch below 0.341.
  auto coarse                      = seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
  coarse.continuation.initial_step = coarse.continuation.max_step = 1e-3;
  std::vector<nsm::BackbonePoint> p;
  check_branch_found_below_the_end(coarse, p);
  if (HasFatalFailure())
    return;
  const auto &end = p.back(), &flank = p[p.size() - 2];
  // The flank climbed to the end: its segment's points before it lie lower.
  const auto before = std::find_if(p.rbegin() + 2, p.rend(), [&](const auto &q) { return q.segment != flank.segment; });
  const auto least  = std::min_element(before.base(), p.end() - 1, [](const auto &x, const auto &y) {
    return x.measures.energy < y.measures.energy;
  });
  EXPECT_GT(flank.measures.energy, (1 + coarse.continuation.tongue_share) * least->measures.energy);
  EXPECT_GT(end.measures.contact_fraction, flank.measures.contact_fraction);
}

TEST(Backbone, ArclengthGoesRoundAFoldAtAnInternalResonance)
{
  auto scene = seed_scene(nsm::ForceSign::physical, 1.5, 1.93);
  scene.continuation.method = nsm::ContinuationMethod::arclength;
  HbModel    model(scene);
  const auto backbone = model.backbone();
  ASSERT_FALSE(backbone.folds.empty());
  // W turns back within a segment, next to a listed resonance w_j / k.
  bool turned = false;
  for (std::size_t i = 1; i + 1 < backbone.points.size(); ++i)
    {
      const auto &a = backbone.points[i - 1], &b = backbone.points[i], &c = backbone.points[i + 1];
      if (a.segment == c.segment && (b.omega - a.omega) * (c.omega - b.omega) < 0)
        {
          const auto &r = nsm::nearest_resonance(model.resonances, b.omega);
          turned = turned || std::abs(r.omega - b.omega) < 2e-3;
        }
    }
  EXPECT_TRUE(turned);
}

TEST(Backbone, ArclengthCrossesTheTonguesToTheEndOfTheRange)
{
  // Seed bar to W = 2: 21 resonance tongues on the way (before the jump guard
  // and the tongue cap, arclength was lost at W = 1.9287 in the first one).
  auto scene = seed_scene(nsm::ForceSign::physical, 1.5, 2.0);
  scene.continuation.method = nsm::ContinuationMethod::arclength;
  HbModel    model(scene);
  const auto backbone = model.backbone();
  ASSERT_GT(backbone.points.size(), 10u);
  EXPECT_EQ(backbone.points.back().omega, 2.0);
  EXPECT_GT(backbone.leaps, 0u);
  const auto &c = scene.continuation;
  for (const auto &p : backbone.points)
    EXPECT_LE(p.omega, c.omega_max);
  // No jump to another branch within a segment, and no step longer than Max
  // step in Omega.
  const LargestSteps largest = largest_steps(backbone);
  EXPECT_LE(largest.contact, c.max_contact_change) << "W = " << largest.contact_at;
  EXPECT_LE(largest.omega, c.max_step) << "W = " << largest.omega_at;
  // Each segment climbs a tongue to at most Tongue energy ratio times the
  // energy where it first turned back.
  for (std::size_t first = 0; first < backbone.points.size();)
    {
      std::size_t end = first;
      while (end < backbone.points.size() && backbone.points[end].segment == backbone.points[first].segment)
        ++end;
      for (std::size_t i = first + 1; i + 1 < end; ++i)
        if ((backbone.points[i].omega - backbone.points[i - 1].omega) *
              (backbone.points[i + 1].omega - backbone.points[i].omega) < 0)
          {
            for (std::size_t j = i; j < end; ++j)
              EXPECT_LE(backbone.points[j].measures.energy,
                        c.tongue_energy_ratio * backbone.points[i].measures.energy);
            break;
          }
      first = end;
    }
}

TEST(Backbone, ArclengthComesBackDownFromATongueToTheEndOfTheRange)
{
  // prm/seed-high-order.prm's mesh, FE_Q(10) x 7, to W = 2.2: the leap past
  // the fold at 2.1923 lands on the tongue of w_27 / 38, and from that
  // tongue's fold at 2.1946 no guess lands; the leap's last resort, from the
  // fold at 2.1923, comes back onto the main branch (without it the run ends
  // at 2.19278 on the tongue). The end must be where sequential continuation
  // ends, an independent path, to its solves' tolerance (measured: 1e-11).
  auto scene                      = seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
  scene.discretisation.cells      = 7;
  scene.continuation.method       = nsm::ContinuationMethod::arclength;
  HbModel    arclength(scene);
  const auto backbone = arclength.backbone();
  const auto end      = backbone.points.back();
  // No step moves Omega by more than Max step: on this mesh LOCA's corrector
  // slid from 1.9222 to 1.9477, and from 1.9823 to 1.9989, before such steps
  // were refused.
  const LargestSteps largest = largest_steps(backbone);
  EXPECT_LE(largest.omega, scene.continuation.max_step) << "W = " << largest.omega_at;
  scene.continuation.method = nsm::ContinuationMethod::sequential;
  HbModel sequential(scene);
  const auto reference = sequential.backbone().points.back();
  ASSERT_EQ(reference.omega, 2.2);
  EXPECT_EQ(end.omega, 2.2);
  EXPECT_EQ(end.branch, nsm::Branch::main);
  EXPECT_NEAR(end.measures.energy / reference.measures.energy, 1, 1e-8);
}

TEST(Backbone, SampledApproachesExactIntegrationAsSamplesGrow)
{
  auto scene = uniform_scene(10);
  HbModel    exact(scene);
  const auto reference =
    nsm::solve_on_branch(exact.hb, nsm::BranchParameters(scene), exact.backbone(), 1.6).measures.energy;
  // The sampled rule's error falls like Nt^-2 in envelope (measured: 4.8e-3,
  // 4.2e-4, 8.6e-6, 5.0e-8 for Nt = 32, 128, 1024, 8192); some Nt in between
  // land closer by symmetry of the samples with the contact interval.
  double previous = 1;
  for (const unsigned int samples : {32u, 128u, 1024u, 8192u})
    {
      scene.harmonic_balance.integration  = nsm::Integration::sampled;
      scene.harmonic_balance.time_samples = samples;
      HbModel    model(scene);
      const auto energy =
        nsm::solve_on_branch(model.hb, nsm::BranchParameters(scene), model.backbone(), 1.6).measures.energy;
      const double difference = std::abs(energy / reference - 1);
      EXPECT_LT(difference, previous / 8) << samples << " samples";
      previous = difference;
    }
  EXPECT_LT(previous, 1e-6);
}

TEST(Backbone, HigherModesStartAtTheirOwnGrazing)
{
  // Continuation/Mode = 2: the branch starts just above w2 with the energy of
  // the second linear mode at u(L) = g0, w2^2 g0^2 / (2 phi_2(L)^2) (to 2 %,
  // as for mode 1), and hardens.
  auto scene = testing_helpers::hb_scene("1.5 - x", 20);
  scene.continuation.mode       = 2;
  scene.continuation.omega_min  = 4.5;
  scene.continuation.omega_max  = 5.0;
  scene.continuation.energy_max = 1e-3;
  HbModel    model(scene);
  const auto backbone = model.backbone();
  const auto [l2, linear] = model.grazing(2);
  const double w2 = std::sqrt(l2);
  ASSERT_GT(backbone.points.size(), 20u);
  EXPECT_GT(backbone.points.front().omega, w2);
  EXPECT_LT(backbone.points.front().omega, w2 + 0.01);
  EXPECT_NEAR(backbone.points.front().measures.energy / linear, 1.0, 0.02);
  for (const auto &p : backbone.points)
    EXPECT_GT(p.omega, w2);
  EXPECT_GT(backbone.points.back().measures.energy, 1.5 * linear);
}

TEST(Backbone, StartsWithin1e4OfGrazingAndEndsExactlyAtOmegaMax)
{
  // Uniform bar: w1 = pi / 2 exactly.
  auto scene = uniform_scene(20);
  HbModel    model(scene);
  const auto backbone = model.backbone();
  const double w1 = M_PI / 2;
  ASSERT_GT(backbone.points.size(), 3u);
  EXPECT_GT(backbone.points.front().omega, w1);
  EXPECT_LT(backbone.points.front().omega / w1 - 1, 1e-4);
  EXPECT_EQ(backbone.points.back().omega, scene.continuation.omega_max);
  EXPECT_EQ(backbone.end, nsm::BackboneEnd::range);
  EXPECT_EQ(backbone.omega_reached(nsm::branch_direction(scene.contact)), scene.continuation.omega_max);
  for (const auto &p : backbone.points)
    EXPECT_LE(p.measures.energy, scene.continuation.energy_max);
}

TEST(Backbone, SaysItStoppedAtMaxStepsShortOfTheRange)
{
  auto scene                   = uniform_scene(20);
  scene.continuation.max_steps = 5;
  HbModel    model(scene);
  const auto backbone = model.backbone();
  ASSERT_EQ(backbone.points.size(), 5u);
  EXPECT_EQ(backbone.end, nsm::BackboneEnd::max_steps);
  EXPECT_STREQ(nsm::backbone_end_name(backbone.end), "max_steps");
  EXPECT_EQ(backbone.omega_reached(nsm::branch_direction(scene.contact)), backbone.points.back().omega);
  EXPECT_LT(backbone.points.back().omega, scene.continuation.omega_max);
}

TEST(Backbone, NarrowRangeJustAboveGrazingGetsPointsUpToItsEnd)
{
  // Omega max = w1 + 5e-4 on the seed bar (w1 from method.md), both methods.
  for (const auto method : {nsm::ContinuationMethod::sequential, nsm::ContinuationMethod::arclength})
    {
      auto scene                = seed_scene(nsm::ForceSign::physical, 1.5, w1_seed + 5e-4);
      scene.continuation.method = method;
      HbModel    model(scene);
      const auto backbone = model.backbone();
      ASSERT_GE(backbone.points.size(), 3u);
      EXPECT_EQ(backbone.points.back().omega, scene.continuation.omega_max);
      for (const auto &p : backbone.points)
        EXPECT_GT(p.omega, w1_seed - 1e-6);
    }
}

TEST(Backbone, RangeAboveGrazingIsReachedFromGrazing)
{
  // Omega min above w1: the branch is traced from grazing, and only points in
  // [Omega min, Omega max] are written, the first exactly at Omega min; its
  // energy is the one the full branch has there.
  auto scene = uniform_scene(20);
  scene.continuation.omega_max = 1.7;
  HbModel    full(scene);
  const auto reference = nsm::solve_on_branch(full.hb, nsm::BranchParameters(scene), full.backbone(), 1.65);
  scene.continuation.omega_min = 1.65;
  HbModel    part(scene);
  const auto backbone = part.backbone();
  ASSERT_GT(backbone.points.size(), 3u);
  EXPECT_EQ(backbone.points.front().omega, 1.65);
  for (const auto &p : backbone.points)
    EXPECT_TRUE(p.omega >= 1.65 && p.omega <= 1.7) << p.omega;
  EXPECT_NEAR(backbone.points.front().measures.energy / reference.measures.energy, 1.0, 1e-9);
}

TEST(Backbone, EnergyMaxBelowTheGrazingEnergyIsAnInputError)
{
  auto scene = uniform_scene(20);
  scene.continuation.energy_max = 1e-8; // grazing: about 0.5 g0^2 = 5e-7
  HbModel model(scene);
  EXPECT_THROW(model.backbone(), nsm::InputError);
}

TEST(Backbone, SolvesInTheGapALeapLeft)
{
  // Sequential stepping leaps over a fold: no two points of one segment
  // bracket the Omega between the fold and the landing. A field asked for
  // there is solved from the nearest point, as the leap did (before, an
  // error: "no converged solution on the computed branch").
  HbModel    model(seed_scene(nsm::ForceSign::physical, 1.5, 1.96));
  const auto backbone = model.backbone();
  const auto &p       = backbone.points;
  std::size_t landing = 1;
  while (landing < p.size() && p[landing].segment == p[landing - 1].segment)
    ++landing;
  ASSERT_LT(landing, p.size());
  const double omega = (p[landing - 1].omega + p[landing].omega) / 2;
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    ASSERT_FALSE(p[i].segment == p[i + 1].segment && (p[i].omega - omega) * (p[i + 1].omega - omega) <= 0)
      << "a segment brackets the gap";
  const auto point = nsm::solve_on_branch(model.hb, model.branch, backbone, omega);
  EXPECT_EQ(point.omega, omega);
  EXPECT_LE(point.residual, model.scene.harmonic_balance.tolerance);
  // Between the fold and the landing, at the energies on either side.
  const auto [low, high] = std::minmax(p[landing - 1].measures.energy, p[landing].measures.energy);
  EXPECT_GT(point.measures.energy, low / 4);
  EXPECT_LT(point.measures.energy, high * 4);
  // Studies ask for the main branch between main points only.
  EXPECT_THROW(nsm::solve_on_branch(model.hb, model.branch, backbone, omega, true), nsm::NumericalError);
}

// A point solved beside a backbone point goes where it lies along the
// segment's direction of continuation: rising Omega (the physical sign), or
// falling (eq. (5)), so that it is neither behind its segment's front nor
// puts the point it continues behind it.
TEST(Backbone, APointSolvedBesideAnotherGoesWhereItLiesAlongTheSegment)
{
  const auto at = [](std::vector<double> omegas) {
    std::vector<nsm::BackbonePoint> points(omegas.size());
    for (std::size_t i = 0; i < omegas.size(); ++i)
      points[i].omega = omegas[i];
    return points;
  };
  const auto rising = at({1.98, 1.99, 2.00}), falling = at({2.00, 1.99, 1.98});
  EXPECT_EQ(nsm::position_beside(rising, 1, 1.995, 1.0), 2u);  // after 1.99
  EXPECT_EQ(nsm::position_beside(rising, 2, 1.995, 1.0), 2u);  // before 2.00
  EXPECT_EQ(nsm::position_beside(falling, 1, 1.995, -1.0), 1u); // before 1.99
  EXPECT_EQ(nsm::position_beside(falling, 0, 1.995, -1.0), 1u); // after 2.00
  EXPECT_EQ(nsm::position_beside(falling, 2, 1.975, -1.0), 3u); // beyond the segment's end
}
