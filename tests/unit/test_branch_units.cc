// The stages of tracing one branch, each on its own (branch_context.h): the
// start at grazing, sequential steps, arclength steps with their guards, and
// the leap over a fold; on the uniform bar (w1 = pi / 2 exactly) and the seed
// bar (w1 from method.md).
#include <nsm/continuation/arclength_steps.h>
#include <nsm/continuation/grazing_start.h>
#include <nsm/continuation/leap.h>
#include <nsm/continuation/sequential_steps.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <cstdio>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "exact_bar.h"
#include "hb_model.h"

namespace
{
  using testing_helpers::HbModel;
  using testing_helpers::w1_seed;

  nsm::Scene seed(nsm::ForceSign sign, nsm::ContinuationMethod method, double omega_max)
  {
    auto scene                = testing_helpers::seed_scene(sign, 1.5, omega_max);
    scene.continuation.method = method;
    return scene;
  }

  /// A model, a context on it, and a backbone holding the start point.
  struct Tracing
  {
    explicit Tracing(const nsm::Scene &scene)
      : model(scene)
      , context(model.hb, model.branch, model.resonances)
    {
      backbone.points.push_back(nsm::start_at_grazing(context, backbone));
    }

    HbModel            model;
    nsm::BranchContext context;
    nsm::Backbone      backbone;
  };
} // namespace

TEST(GrazingStart, FirstPointLiesJustBeyondGrazingInTheBranchDirection)
{
  for (const auto sign : {nsm::ForceSign::physical, nsm::ForceSign::seed_eq5})
    {
      Tracing      t(seed(sign, nsm::ContinuationMethod::sequential, 2.2));
      const auto  &start    = t.backbone.points.front();
      const double relative = start.omega / w1_seed - 1;
      // Grazing offset 1e-5 of w1: above w1 with the physical sign, below
      // with eq. (5); w1 itself is known to 6 digits.
      EXPECT_NEAR(relative, 1e-5 * t.context.direction, 1e-6) << start.omega;
      EXPECT_EQ(start.segment, 0u);
      // The energy is the linear mode's at grazing, u(L) = g0.
      EXPECT_NEAR(start.measures.energy / t.model.grazing(1).second, 1.0, 0.05);
      // The range is covered from the start to its far end.
      EXPECT_DOUBLE_EQ(t.context.span, sign == nsm::ForceSign::physical ? 2.2 - start.omega :
                                                                            start.omega - 1.5);
      ASSERT_EQ(t.backbone.events.size(), 1u);
      EXPECT_NE(t.backbone.events[0].find("start at grazing"), std::string::npos);
    }
}

// What any solve (sequential, arclength, leap) must be to become a point: the
// equations solved to Tolerance, contact, and in the full basis an unfolding
// parameter mu no larger than Tolerance (it enters a residual row). Each
// bound from both sides, on the start point of the full basis.
TEST(BranchContext, APointIsAContactMotionThatSolvesTheEquations)
{
  auto scene                       = seed(nsm::ForceSign::physical, nsm::ContinuationMethod::arclength, 2.2);
  scene.harmonic_balance.basis     = nsm::HarmonicBasis::full;
  Tracing                  t(scene);
  const nsm::BackbonePoint start = t.backbone.points.front();
  const double             tol   = scene.harmonic_balance.tolerance;
  const auto point_from = [&](std::vector<double> x, const double residual) {
    nsm::BackbonePoint point;
    return t.context.make_point(x, start.omega, residual, 3, 0, point);
  };
  ASSERT_LE(std::abs(start.x[1]), 1e-12);
  EXPECT_TRUE(point_from(start.x, 0.5 * tol));
  EXPECT_FALSE(point_from(start.x, 2 * tol));
  // The trivial solution solves the equations but touches nothing.
  EXPECT_FALSE(point_from(std::vector<double>(start.x.size(), 0.0), 0.0));
  auto forced = start.x;
  forced[1]   = 0.5 * tol;
  EXPECT_TRUE(point_from(forced, 0.5 * tol));
  forced[1] = -2 * tol;
  EXPECT_FALSE(point_from(forced, 0.5 * tol));
}

TEST(SequentialSteps, StaysOnBranchBoundsTheChangeOfTheSolutionAndOfTheContact)
{
  nsm::ContinuationParameters c; // a fifth of the solution, 0.01 of the contact fraction
  nsm::BackbonePoint       from{}, to{};
  from.x = {3, 4}; // norm 5: a change of norm up to 1 stays
  to.x   = {3, 4.99};
  EXPECT_TRUE(nsm::stays_on_branch(from, to, c));
  to.x = {3, 5.01};
  EXPECT_FALSE(nsm::stays_on_branch(from, to, c));
  to.x = {3.01, 4};
  EXPECT_TRUE(nsm::stays_on_branch(from, to, c));
  // The contact fraction may change by at most the bound, either way.
  from.measures.contact_fraction = 0.10;
  to.measures.contact_fraction   = 0.109;
  EXPECT_TRUE(nsm::stays_on_branch(from, to, c));
  to.measures.contact_fraction = 0.111;
  EXPECT_FALSE(nsm::stays_on_branch(from, to, c));
  to.measures.contact_fraction = 0.089;
  EXPECT_FALSE(nsm::stays_on_branch(from, to, c));
  c.max_contact_change = 0.02;
  EXPECT_TRUE(nsm::stays_on_branch(from, to, c));
  // A tighter bound on the solution refuses what a fifth allowed.
  to.measures.contact_fraction = 0.10;
  to.x                         = {3, 4.99};
  c.max_solution_change        = 0.1;
  EXPECT_FALSE(nsm::stays_on_branch(from, to, c));
}

TEST(SequentialSteps, UniformSegmentEndsExactlyAtOmegaMaxOnOneBranch)
{
  auto scene = testing_helpers::hb_scene("1", 10);
  scene.continuation.omega_max  = 1.6;
  scene.continuation.energy_max = 1e-5;
  Tracing t(scene);
  EXPECT_EQ(nsm::sequential_segment(t.context, t.backbone, 0), nsm::SegmentEnd::range);
  const auto &p = t.backbone.points;
  ASSERT_GT(p.size(), 5u);
  EXPECT_EQ(p.back().omega, 1.6);
  for (std::size_t i = 1; i < p.size(); ++i)
    {
      EXPECT_EQ(p[i].segment, 0u);
      EXPECT_GT(p[i].omega, p[i - 1].omega);
      EXPECT_LE(p[i].omega - p[i - 1].omega, t.context.max_step() * (1 + 1e-12));
      EXPECT_TRUE(nsm::stays_on_branch(p[i - 1], p[i], scene.continuation)) << p[i].omega;
      // The branch hardens: the energy rises with Omega.
      EXPECT_GT(p[i].measures.energy, p[i - 1].measures.energy) << p[i].omega;
    }
}

namespace
{
  /// What a traced-whole run and one stopped at Max steps leave.
  struct StoppedRun
  {
    std::vector<nsm::BackbonePoint> whole;   ///< the points of the run traced whole
    std::optional<double>           carried; ///< the step the stopped run kept
    double                          max_step; ///< the context's largest step
  };

  /// `scene` traced whole by a Method, and again in two runs: the first ends
  /// at Max steps = `stop_at` points, the second (a fresh tracer, as a
  /// resumed run has) goes on from its points with the step the first kept.
  /// Every point must be the whole run's, bit for bit. Without the kept step
  /// a third run starts again from Initial step: its point `stop_at` must
  /// differ from the whole run's.
  template <typename Method>
  StoppedRun expect_resumed_as_whole(nsm::Scene scene, const unsigned int stop_at)
  {
    Tracing whole(scene);
    Method  whole_method;
    EXPECT_EQ(whole_method.trace(whole.context, whole.backbone, 0), nsm::SegmentEnd::range);
    EXPECT_FALSE(whole_method.resume_step().has_value()); // nothing to go on with after the range
    const auto &q = whole.backbone.points;
    EXPECT_GT(q.size(), stop_at + 4u);

    scene.continuation.max_steps = stop_at;
    Tracing first(scene);
    Method  first_method;
    EXPECT_EQ(first_method.trace(first.context, first.backbone, 0), nsm::SegmentEnd::max_steps);
    EXPECT_EQ(first.backbone.points.size(), stop_at);
    EXPECT_TRUE(first_method.resume_step().has_value());

    scene.continuation.max_steps = 2000;
    Tracing second(scene);
    second.backbone.points = first.backbone.points;
    Method second_method;
    second_method.resume_with(first_method.resume_step());
    EXPECT_EQ(second_method.trace(second.context, second.backbone, 0), nsm::SegmentEnd::range);
    const auto &p = second.backbone.points;
    EXPECT_EQ(p.size(), q.size());
    for (std::size_t i = 0; i < std::min(p.size(), q.size()); ++i)
      {
        EXPECT_EQ(p[i].omega, q[i].omega) << i;
        EXPECT_EQ(p[i].x, q[i].x) << i;
      }

    Tracing third(scene);
    third.backbone.points = first.backbone.points;
    Method third_method;
    EXPECT_EQ(third_method.trace(third.context, third.backbone, 0), nsm::SegmentEnd::range);
    if (third.backbone.points.size() > stop_at && q.size() > stop_at)
      {
        EXPECT_NE(third.backbone.points[stop_at].omega, q[stop_at].omega);
      }
    return {q, first_method.resume_step(), first.context.max_step()};
  }
} // namespace

TEST(SequentialSteps, ATracerCarriesItsStepOverMaxStepsAndGoesOnAsIfUninterrupted)
{
  // The uniform branch of the test above, stopped after 8 points.
  auto scene = testing_helpers::hb_scene("1", 10);
  scene.continuation.omega_max  = 1.6;
  scene.continuation.energy_max = 1e-5;
  const StoppedRun run = expect_resumed_as_whole<nsm::SequentialSteps>(scene, 8);
  // A step the whole run took next: at least Min step, at most max_step().
  ASSERT_TRUE(run.carried.has_value());
  EXPECT_GE(*run.carried, scene.continuation.min_step);
  EXPECT_LE(*run.carried, run.max_step);
}

TEST(ArclengthSteps, ATracerCarriesItsApproachStepOverMaxStepsAndGoesOnAsIfUninterrupted)
{
  // The uniform bar from grazing (pi / 2) to a range that starts above it:
  // sequential steps approach Omega min = 1.62, then arclength goes on to
  // 1.7. Stopped after 5 points, within the approach.
  auto scene = testing_helpers::hb_scene("1", 10);
  scene.continuation.method     = nsm::ContinuationMethod::arclength;
  scene.continuation.omega_min  = 1.62;
  scene.continuation.omega_max  = 1.7;
  scene.continuation.energy_max = 1e-3;
  const StoppedRun run = expect_resumed_as_whole<nsm::ArclengthSteps>(scene, 5);
  const auto approach = std::find_if(run.whole.begin(), run.whole.end(),
                                     [](const nsm::BackbonePoint &p) { return p.omega >= 1.62; }) -
                        run.whole.begin();
  EXPECT_GT(approach, 6); // the approach takes more points than the stopped run
  EXPECT_GT(run.whole.size(), static_cast<std::size_t>(approach) + 3);
}

TEST(SequentialSteps, AFillingSegmentEndsBeforeItsFarSideAndBelowItsTongueThreshold)
{
  // The uniform branch of the test above, with the limits of a gap being
  // filled (gap_filling.h): the far side at 1.58, then an energy bound.
  auto scene = testing_helpers::hb_scene("1", 10);
  scene.continuation.omega_max  = 1.6;
  scene.continuation.energy_max = 1e-5;
  Tracing t(scene);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(nsm::sequential_segment(t.context, t.backbone, 0, nsm::StepLimits{1.58, inf}), nsm::SegmentEnd::joined);
  const auto &p = t.backbone.points;
  ASSERT_GT(p.size(), 5u);
  EXPECT_LT(p.back().omega, 1.58);
  EXPECT_GT(p.back().omega, 1.58 - t.context.max_step() * (1 + 1e-12)); // the next step would reach it

  // The branch hardens: with that last point's energy as the threshold, the
  // segment ends (tongue) on the step that climbs above it, and keeps no point above.
  const double threshold = p.back().measures.energy;
  Tracing      again(scene);
  EXPECT_EQ(nsm::sequential_segment(again.context, again.backbone, 0, nsm::StepLimits{inf, threshold}),
            nsm::SegmentEnd::tongue);
  ASSERT_GT(again.backbone.points.size(), 1u);
  for (const auto &q : again.backbone.points)
    EXPECT_LE(q.measures.energy, threshold) << q.omega;
}

TEST(ArclengthSteps, SeedSegmentTurnsAFoldAndStopsHighOnTheTongue)
{
  Tracing     t(seed(nsm::ForceSign::physical, nsm::ContinuationMethod::arclength, 2.0));
  std::optional<std::size_t> first_fold;
  const auto  end = nsm::arclength_segment(t.context, t.backbone, 0, first_fold);
  const auto &c   = t.model.scene.continuation;
  const auto &p   = t.backbone.points;
  EXPECT_EQ(end, nsm::SegmentEnd::tongue);
  ASSERT_TRUE(first_fold.has_value());
  const std::size_t fold = *first_fold;
  ASSERT_GT(fold, 0u);
  ASSERT_LT(fold + 1, p.size());
  // Omega turns back at the first fold, next to a listed resonance w_j / k.
  EXPECT_LT((p[fold].omega - p[fold - 1].omega) * (p[fold + 1].omega - p[fold].omega), 0);
  EXPECT_LT(std::abs(nsm::nearest_resonance(t.model.resonances, p[fold].omega).omega - p[fold].omega), 2e-3);
  for (std::size_t i = 1; i < p.size(); ++i)
    {
      EXPECT_LE(std::abs(p[i].measures.contact_fraction - p[i - 1].measures.contact_fraction),
                c.max_contact_change);
      EXPECT_LE(std::abs(p[i].omega - p[i - 1].omega), c.max_step);
      EXPECT_LE(p[i].measures.energy, c.tongue_energy_ratio * p[fold].measures.energy);
    }
}

TEST(Leap, LandsBeyondTheFoldNearTheFrontsEnergy)
{
  Tracing t(seed(nsm::ForceSign::physical, nsm::ContinuationMethod::sequential, 2.0));
  ASSERT_EQ(nsm::sequential_segment(t.context, t.backbone, 0), nsm::SegmentEnd::fold);
  const nsm::BackbonePoint front = t.backbone.points.back();
  ASSERT_TRUE(nsm::leap(t.context, t.backbone, 1));
  const auto &landing = t.backbone.points.back();
  EXPECT_EQ(landing.segment, 1u);
  EXPECT_EQ(t.backbone.leaps, 1u);
  // At least Initial step beyond the front, at most 5 % of Omega.
  EXPECT_GE(landing.omega - front.omega, t.model.scene.continuation.initial_step * (1 - 1e-12));
  EXPECT_LE(landing.omega - front.omega, 0.05 * front.omega);
  EXPECT_GT(landing.measures.energy, front.measures.energy / 4);
  EXPECT_LT(landing.measures.energy, front.measures.energy * 4);
}

namespace
{
  /// The seed bar at M = 160 on FE_Q(10) x 40 (2874 internal resonances in
  /// [1.5, 2.2]), with Max iterations Newton steps, for at most 300 points,
  /// its leaps from their own guesses only.
  nsm::Backbone seed_at_m160(const unsigned int max_iterations)
  {
    auto scene                            = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
    scene.discretisation.cells            = 40;
    scene.harmonic_balance.harmonics      = 160;
    scene.harmonic_balance.max_iterations = max_iterations;
    scene.continuation.max_steps          = 300;
    scene.continuation.leap_from_fewer_harmonics = false;
    HbModel model(scene);
    return model.backbone();
  }
} // namespace

// With the default 12 iterations the leap after the fold at 1.9511 finds no
// landing: 24 of its 27 solves stop at Max iterations and 3 converge on
// tongues outside the landing energies. The message says so, its counts add
// up, and the remedy it points to works: with 40 iterations the branch goes
// on past that fold (to 1.962 in 300 points, and to 2.1485 in all).
TEST(Leap, ALostBranchSaysWhatItsNewtonSolvesEndedIn)
{
  const nsm::Backbone lost = seed_at_m160(12);
  ASSERT_FALSE(lost.events.empty());
  const std::string &message = lost.events.back();
  std::smatch        m;
  ASSERT_TRUE(std::regex_search(message, m,
                                std::regex("branch lost after the fold at Omega = ([0-9.]+): no landing from ([0-9]+) "
                                           "Newton solves up to Omega = ([0-9.]+) \\((.*)\\)$")))
    << message;
  const double front = std::stod(m[1]), furthest = std::stod(m[3]);
  EXPECT_LT(lost.points.size(), 300u);
  EXPECT_NEAR(lost.points.back().omega, front, 1e-7);
  // The leap tried up to Search reach (5 %) beyond the front.
  EXPECT_GT(furthest, front);
  EXPECT_LE(furthest, front * 1.05);
  // Every solve is counted once, and most stopped at the iteration limit.
  std::istringstream parts(m[4].str());
  unsigned int       counted = 0, at_limit = 0;
  for (std::string part; std::getline(parts >> std::ws, part, ',');)
    {
      const unsigned long n = std::stoul(part);
      counted += n;
      if (part.find("stopped at Max iterations") != std::string::npos)
        at_limit = n;
    }
  EXPECT_EQ(counted, std::stoul(m[2])) << message;
  EXPECT_GT(2 * at_limit, counted) << message;
  EXPECT_NE(message.find("stopped at Max iterations = 12"), std::string::npos) << message;
  EXPECT_EQ(lost.end, nsm::BackboneEnd::lost);

  const nsm::Backbone reached = seed_at_m160(40);
  EXPECT_EQ(reached.points.size(), 300u);
  EXPECT_GT(reached.points.back().omega, front);
  for (const std::string &event : reached.events)
    EXPECT_EQ(event.find("branch lost"), std::string::npos) << event;
}

namespace
{
  /// The seed bar on FE_Q(10) x 20 (gamma resolved to k W = 320) at M
  /// harmonics.
  nsm::Scene seed_at(const unsigned int harmonics, const bool leap_from_fewer_harmonics)
  {
    auto scene                                   = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
    scene.discretisation.cells                   = 20;
    scene.harmonic_balance.harmonics             = harmonics;
    scene.continuation.leap_from_fewer_harmonics = leap_from_fewer_harmonics;
    return scene;
  }

  /// |E / E_low - 1| at the main points of `high` beyond `omega`, where the
  /// main branch of `low` (solved at exactly their Omega, between two of its
  /// main points) has them too; sorted.
  std::vector<double> energy_moves(const nsm::Backbone &high, HbModel &low, const nsm::Backbone &low_backbone,
                                   const double omega)
  {
    std::vector<double> moves;
    for (const nsm::BackbonePoint &p : high.points)
      if (p.branch == nsm::Branch::main && p.omega > omega)
        try
          {
            const nsm::BackbonePoint q = nsm::solve_on_branch(low.hb, low.branch, low_backbone, p.omega, true);
            moves.push_back(std::abs(p.measures.energy / q.measures.energy - 1));
          }
        catch (const nsm::NumericalError &)
          {}
    std::sort(moves.begin(), moves.end());
    return moves;
  }
} // namespace

// At M = 160 the seed bar's branch is lost after the fold near 1.964 when a
// leap has only its own guesses: Newton stalls at minima of the residual that
// are not solutions (doc/accuracy-and-cost.md). From the main points of the
// same branch at M = 80 it converges and the run reaches Omega max, every such
// landing on the main branch. The branch it then writes beyond the fold is
// the M = 160 branch, not the M = 80 one carried over: it moves from the
// M = 80 branch less than the M = 80 branch moves from the M = 40 one, there
// (a truncation that converges; measured beyond 1.964 to 2.2: median 8.6e-3
// against 1.9e-2, 90th percentile 3.6e-2 against 6.5e-2).
TEST(Leap, ALostBranchGoesOnFromTheBranchWithHalfTheHarmonics)
{
  HbModel             alone(seed_at(160, false));
  const nsm::Backbone lost = alone.backbone();
  ASSERT_EQ(lost.end, nsm::BackboneEnd::lost);
  const double fold = *lost.omega_reached(1);
  EXPECT_LT(fold, 1.97);

  HbModel             model(seed_at(160, true));
  const nsm::Backbone carried = model.backbone();
  EXPECT_EQ(carried.end, nsm::BackboneEnd::range);
  EXPECT_EQ(*carried.omega_reached(1), 2.2);
  unsigned int landings = 0;
  for (const std::string &event : carried.events)
    {
      std::smatch m;
      if (!std::regex_search(event, m, std::regex("leapt.* from the branch with half the harmonics at Omega = ([0-9.]+)")))
        continue;
      ++landings;
      const double omega   = std::stod(m[1]);
      const auto   landing = std::min_element(carried.points.begin(), carried.points.end(), [&](auto &a, auto &b) {
        return std::abs(a.omega - omega) < std::abs(b.omega - omega);
      });
      EXPECT_NEAR(landing->omega, omega, 1e-7 * omega);
      EXPECT_EQ(landing->branch, nsm::Branch::main) << event;
    }
  EXPECT_GT(landings, 0u);

  HbModel                   m80(seed_at(80, true)), m40(seed_at(40, true));
  const nsm::Backbone       b80 = m80.backbone(), b40 = m40.backbone();
  const std::vector<double> from80 = energy_moves(carried, m80, b80, fold);
  const std::vector<double> from40 = energy_moves(b80, m40, b40, fold);
  ASSERT_GE(from80.size(), 10u);
  ASSERT_GE(from40.size(), 10u);
  const auto quantile = [](const std::vector<double> &v, const double q) { return v[std::size_t(q * (v.size() - 1))]; };
  EXPECT_LT(quantile(from80, 0.5), quantile(from40, 0.5));
  EXPECT_LT(quantile(from80, 0.9), quantile(from40, 0.9));
  std::printf("beyond %.6f: %u landings; |E160 / E80 - 1| median %.2e q90 %.2e max %.2e (%zu points), "
              "|E80 / E40 - 1| median %.2e q90 %.2e max %.2e (%zu)\n",
              fold, landings, quantile(from80, 0.5), quantile(from80, 0.9), from80.back(), from80.size(),
              quantile(from40, 0.5), quantile(from40, 0.9), from40.back(), from40.size());
}

// With a short Search reach (0.005 of Omega) the seed bar at M = 80 meets a
// fold beyond which nothing within reach lands, not even the M = 40 branch's
// main points: the branch is lost there without the M = 40 branch, and goes
// on with it from a main point beyond the reach.
TEST(Leap, BeyondSearchReachTheBranchWithHalfTheHarmonicsCarriesALostBranchOn)
{
  const auto short_reach = [](const bool fewer) {
    nsm::Scene scene                   = seed_at(80, fewer);
    scene.continuation.search_reach   = 0.005;
    scene.continuation.grazing_offset = 1e-6;
    return scene;
  };
  HbModel             model(short_reach(true));
  const nsm::Backbone carried = model.backbone();
  EXPECT_EQ(carried.end, nsm::BackboneEnd::range);
  EXPECT_EQ(*carried.omega_reached(1), 2.2);
  std::vector<double> beyond;
  for (const std::string &event : carried.events)
    {
      std::smatch m;
      if (std::regex_search(event, m, std::regex("leapt beyond Search reach .* at Omega = ([0-9.]+)")))
        beyond.push_back(std::stod(m[1]));
    }
  ASSERT_FALSE(beyond.empty());
  for (const double omega : beyond)
    {
      // The fold it leapt from lies more than the reach behind the landing.
      double fold = 0;
      for (const double f : carried.folds)
        if (f < omega)
          fold = std::max(fold, f);
      EXPECT_GT(omega - fold, 0.005 * fold) << omega;
      const auto landing = std::min_element(carried.points.begin(), carried.points.end(), [&](auto &a, auto &b) {
        return std::abs(a.omega - omega) < std::abs(b.omega - omega);
      });
      EXPECT_EQ(landing->branch, nsm::Branch::main) << omega;
    }
  // The backbone says which branch it traced for those guesses: M = 40.
  ASSERT_FALSE(carried.fewer_harmonics_traced.empty());
  EXPECT_EQ(carried.fewer_harmonics_traced.front().first, 40u);
  EXPECT_GT(carried.fewer_harmonics_traced.front().second, 0u);
  // Without the M = 40 branch the run is lost before the first such landing,
  // and traces none.
  const nsm::Backbone lost = HbModel(short_reach(false)).backbone();
  EXPECT_EQ(lost.end, nsm::BackboneEnd::lost);
  EXPECT_LT(*lost.omega_reached(1), beyond.front());
  EXPECT_TRUE(lost.fewer_harmonics_traced.empty());
}

// The uniform bar's first nonsmooth mode has the energy g0^2 / (2 (T - 3)^2),
// which crosses 1e-3 at Omega = 2.0789 (T = 3.0224). Run to 2.08 with that
// Energy max, the branch is not lost: the leap beyond the last fold lands
// only above Energy max, and the run says so. With Energy max 1e-2 it reaches
// 2.08.
TEST(Leap, ABranchThatRisesAboveEnergyMaxIsNotCalledLost)
{
  auto scene                    = testing_helpers::hb_scene("1", 40);
  scene.continuation.omega_max  = 2.08;
  scene.continuation.energy_max = 1e-3;
  HbModel             model(scene);
  const nsm::Backbone above = model.backbone();
  EXPECT_EQ(above.end, nsm::BackboneEnd::energy_max);
  const std::string &message = above.events.back();
  std::smatch        m;
  ASSERT_TRUE(std::regex_search(message, m,
                                std::regex("branch goes on only above Energy max after the fold at Omega = ([0-9.]+): "
                                           "no landing from [0-9]+ Newton solves up to Omega = ([0-9.]+) "
                                           "\\(([0-9]+) converged above Energy max = 0.001 only")))
    << message;
  const auto exact_energy = [&](const double omega) {
    return exact::UniformMode(2 * M_PI / omega, scene.contact.gap).energy;
  };
  // The exact mode crosses Energy max between the front and the furthest try.
  EXPECT_LT(exact_energy(std::stod(m[1])), scene.continuation.energy_max) << message;
  EXPECT_GT(exact_energy(std::stod(m[2])), scene.continuation.energy_max) << message;
  EXPECT_GT(std::stoul(m[3]), 0u);

  scene.continuation.energy_max = 1e-2;
  HbModel             higher(scene);
  const nsm::Backbone reached = higher.backbone();
  EXPECT_EQ(reached.end, nsm::BackboneEnd::range);
  EXPECT_EQ(reached.points.back().omega, 2.08);
  EXPECT_GT(reached.points.back().measures.energy, 1e-3);
}
