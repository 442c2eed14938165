// Filling the main branch's gaps from the branch with half the harmonics
// (continuation/gap_filling.h), on the seed bar at M = 80 (FE_Q(10) x 20),
// where the plain sequential run leaves main gaps up to 0.06 wide
// (tests/benchmarks/study_coverage: Newton finds main solutions in all of them).
#include <nsm/app/run_result.h>
#include <nsm/base/checkpoint_reader.h>
#include <nsm/continuation/branch_context.h>
#include <nsm/continuation/checkpoint.h>
#include <nsm/continuation/main_branch.h>
#include <nsm/continuation/search_memory.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "hb_model.h"

namespace
{
  constexpr double fill_width = 0.01;

  nsm::Scene seed_with_fill(const unsigned int harmonics, const double fill)
  {
    nsm::Scene scene = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
    scene.discretisation.cells              = 20;
    scene.harmonic_balance.harmonics        = harmonics;
    scene.continuation.fill_gaps_wider_than = fill;
    return scene;
  }

  /// The gaps between main points wider than `width`, the range's end included.
  std::vector<std::pair<double, double>> main_gaps(const nsm::Backbone &b, const double width)
  {
    std::vector<double> main;
    for (const nsm::BackbonePoint &p : b.points)
      if (p.branch == nsm::Branch::main)
        main.push_back(p.omega);
    std::sort(main.begin(), main.end());
    main.push_back(2.2);
    std::vector<std::pair<double, double>> gaps;
    for (std::size_t i = 1; i < main.size(); ++i)
      if (main[i] - main[i - 1] > width)
        gaps.emplace_back(main[i - 1], main[i]);
    return gaps;
  }

  double widest(const std::vector<std::pair<double, double>> &gaps)
  {
    double w = 0;
    for (const auto &g : gaps)
      w = std::max(w, g.second - g.first);
    return w;
  }
} // namespace

TEST(GapFilling, FillsTheMainBranchWhereNewtonFindsItAndKeepsTheTracedPoints)
{
  testing_helpers::HbModel plain_model(seed_with_fill(80, 0)), filled_model(seed_with_fill(80, fill_width));
  const nsm::Backbone      plain = plain_model.backbone(), filled = filled_model.backbone();

  // The filling comes after the trace: the plain run's points come first, unchanged.
  ASSERT_GT(filled.points.size(), plain.points.size());
  for (std::size_t i = 0; i < plain.points.size(); ++i)
    {
      ASSERT_EQ(filled.points[i].omega, plain.points[i].omega) << i;
      ASSERT_EQ(filled.points[i].measures.energy, plain.points[i].measures.energy) << i;
    }
  // Every point added lies inside the plain run's range, and some inside its
  // gaps (later passes search the gaps of the relabelled points, which can lie
  // outside the plain run's).
  const auto   plain_gaps = main_gaps(plain, fill_width);
  const double reached    = *plain.omega_reached(1.0);
  unsigned int inside     = 0;
  for (std::size_t i = plain.points.size(); i < filled.points.size(); ++i)
    {
      const nsm::BackbonePoint &q = filled.points[i];
      EXPECT_TRUE(q.omega > plain.points.front().omega && q.omega < reached) << q.omega;
      inside += std::any_of(plain_gaps.begin(), plain_gaps.end(),
                            [&](const auto &g) { return g.first < q.omega && q.omega < g.second; });
    }
  EXPECT_GT(inside, 0u);
  // More of the range is main, and the widest gap narrows.
  EXPECT_GT(filled.main_points(), plain.main_points());
  const auto filled_gaps = main_gaps(filled, fill_width);
  EXPECT_LT(widest(filled_gaps), widest(plain_gaps));

  // Its work is counted apart: at least one Newton solve per start it
  // records, and at most what the run solved beyond the plain run (the trace
  // before it is the same; the rest is the branch with fewer harmonics traced
  // for its guesses); the plain run did none.
  const nsm::NewtonCost &search = filled.gap_search_cost;
  unsigned long          starts = 0;
  for (const nsm::GapSearch &g : filled.gap_searches)
    starts += g.starts;
  const auto solves = [](const nsm::NewtonCost &c) { return c.converged_solves + c.failed_solves; };
  EXPECT_GE(solves(search), starts);
  EXPECT_LE(solves(search), solves(filled.newton_cost) - solves(plain.newton_cost));
  EXPECT_GT(filled.gap_search_seconds, 0);
  EXPECT_EQ(solves(plain.gap_search_cost), 0u);

  // What is left: Newton at M = 80 from every point of the M = 40 branch
  // inside a remaining gap finds no solution the labels put on the main branch.
  nsm::FewerHarmonicsBranch half(filled_model.hb, filled_model.branch, filled_model.resonances);
  nsm::BranchContext        run(filled_model.hb, filled_model.branch, filled_model.resonances, &half);
  const nsm::Backbone &fewer = *run.fewer_harmonics(); // the guesses the filling had
  unsigned int         tried = 0, converged = 0;
  for (const auto &g : filled_gaps)
    for (const nsm::BackbonePoint &q : fewer.points)
      if (g.first < q.omega && q.omega < g.second)
        {
          nsm::BackbonePoint point;
          ++tried;
          if (!run.solve(q.omega, run.guess_from_fewer_harmonics(q), 0, point, nsm::BranchContext::Newton::both))
            continue;
          ++converged;
          nsm::label_point(filled_model.hb, filled_model.branch, filled.points, point);
          EXPECT_NE(point.branch, nsm::Branch::main) << "a main solution in a remaining gap at " << q.omega;
        }
  // The search is not empty: the remaining gaps hold guesses, and some converge (on tongues).
  EXPECT_GT(tried, 0u);
  EXPECT_GT(converged, 0u);
}

// A gap search's record goes through an interrupted run's checkpoint whole,
// the other families led by a harmonic k > 1 counted apart from those of less
// contact, and a gap from the range's near end without the mode's contact
// before it (written '-': the reader takes no non-finite number).
TEST(GapFilling, ASearchsRecordGoesThroughTheCheckpoint)
{
  testing_helpers::HbModel model(testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2));
  nsm::ContinuationCheckpoint written;
  written.points       = {model.backbone().points.front()};
  // The third: a gap from the range's near end, with no contact of the mode before it.
  written.gap_searches = {{2.06, 2.11, 51, 7, 3, 2, 1, 0.14, 0.24, 2.0875}, {2.15, 2.2, 9, 2, 2, 0, 0, 0, 0.3, {}},
                          {1.5, 1.52, 0, 0, 0, 0, 0, 0, -std::numeric_limits<double>::infinity(), 1.51}};
  const std::string path = ::testing::TempDir() + "gap_search.resume";
  nsm::write_checksummed(path, [&](std::ostream &out) {
    nsm::write_checkpoint(out, written, model.branch.computation_entries, model.hb);
  });
  const nsm::ContinuationCheckpoint read = nsm::read_checkpoint(path, model.branch, model.hb);
  ASSERT_EQ(read.gap_searches.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    {
      const nsm::GapSearch &a = written.gap_searches[i], &b = read.gap_searches[i];
      EXPECT_EQ(std::vector<double>({a.from, a.to, a.most_contact, a.contact_before}),
                std::vector<double>({b.from, b.to, b.most_contact, b.contact_before}));
      EXPECT_EQ(std::vector<unsigned int>({a.starts, a.other_family, a.other_harmonic, a.tongue, a.above_energy_max}),
                std::vector<unsigned int>({b.starts, b.other_family, b.other_harmonic, b.tongue, b.above_energy_max}));
      EXPECT_EQ(a.landed, b.landed);
    }
  std::remove(path.c_str());
}

// The Result block names a gap with what its search found: the other families
// led by the fundamental with their most contact, those led by a higher
// harmonic counted apart, in every combination.
TEST(GapFilling, TheResultBlockCountsTheLandingsLedByAHigherHarmonicApart)
{
  nsm::Scene scene                        = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
  scene.continuation.fill_gaps_wider_than = 0.02;
  const nsm::BarModel bar(scene.bar);
  nsm::Backbone       backbone = testing_helpers::two_point_backbone();
  backbone.end                 = nsm::BackboneEnd::lost;
  const auto gap_line = [&](const unsigned int other, const unsigned int led) {
    backbone.gap_searches = {{1.6, 1.7, 10, other, led, 1, 0, 0.12, 0.3, {}}};
    for (const std::string &line : nsm::backbone_result(backbone, bar, scene.contact, scene.continuation))
      if (line.find("no main point from Omega = 1.6 to 1.7: ") != std::string::npos)
        return line.substr(line.find(": ") + 2);
    return std::string("no line");
  };
  const std::string found = "10 Newton starts from the predicted mode: ";
  EXPECT_EQ(gap_line(0, 0), found + "0 converged on other families, 1 on tongues, 9 did not converge");
  EXPECT_EQ(gap_line(3, 0), found + "3 converged on other families (contact fraction at most 0.12, the mode's 0.3 "
                                    "before the gap), 1 on tongues, 6 did not converge");
  EXPECT_EQ(gap_line(3, 3), found + "3 converged on other families (3 led by a harmonic k > 1), 1 on tongues, "
                                    "6 did not converge");
  EXPECT_EQ(gap_line(5, 2), found + "5 converged on other families (3 of contact fraction at most 0.12, the "
                                    "mode's 0.3 before the gap; 2 led by a harmonic k > 1), 1 on tongues, 4 did "
                                    "not converge");
}

// The search's memory solves a start once: asked again, it returns the same
// solution without a Newton solve; another start at the same Omega (another
// guess) is solved on its own. The solution is the one BranchContext::solve
// gives from that guess, converged or not.
TEST(GapFilling, TheSearchSolvesEachStartOnce)
{
  testing_helpers::HbModel model(seed_with_fill(20, 0));
  const nsm::Backbone      backbone = model.backbone();
  nsm::BranchContext       run(model.hb, model.branch, model.resonances, nullptr);
  const auto               solves = [&] {
    const nsm::NewtonCost c = run.newton_cost();
    return c.converged_solves + c.failed_solves;
  };
  // A main point's own unknowns at its own Omega converge; all zeros (no
  // contact) do not give a point.
  const nsm::BackbonePoint &p = backbone.points[backbone.points.size() / 2];
  nsm::SearchMemory         memory;
  const auto                before = solves();
  const auto               &first  = memory.solve(run, p.omega, {p.omega, 1, 1}, p.x);
  const auto                once   = solves();
  ASSERT_TRUE(first.has_value());
  EXPECT_GT(once, before);
  EXPECT_NEAR(first->measures.energy, p.measures.energy, 1e-9 * p.measures.energy);
  const auto &again = memory.solve(run, p.omega, {p.omega, 1, 1}, std::vector<double>(p.x.size(), 0.0));
  EXPECT_EQ(&again, &first);
  EXPECT_EQ(solves(), once);
  const auto &other = memory.solve(run, p.omega, {p.omega, 1, 2}, std::vector<double>(p.x.size(), 0.0));
  EXPECT_GT(solves(), once);
  EXPECT_FALSE(other.has_value());
}

// A branch traced from grazing below Omega min enters the range where a
// leap happened to land: the stretch from Omega min to the first main point
// is a gap like any other, searched (back from its far side, or from the
// branch with half the harmonics) and, if left, named. On the seed bar from
// Omega min = 2.0 (grazing at 1.919) the first written points are another
// family's (contact fraction 0.04); the whole range's run finds the mode
// there. Without the search of that stretch the first main point is at
// 2.0201, 7 % below the whole run's main branch (another family's).
TEST(GapFilling, TheStretchFromTheRangesNearEndIsAGapWhereTheBranchEntersFromOutside)
{
  nsm::Scene scene = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
  scene.discretisation.cells              = 7;
  scene.continuation.fill_gaps_wider_than = nsm::ContinuationParameters().fill_gaps_wider_than;
  testing_helpers::HbModel whole_model(scene);
  const nsm::Backbone      whole = whole_model.backbone();
  scene.continuation.omega_min = 2.0;
  testing_helpers::HbModel entered_model(scene);
  const nsm::Backbone      entered = entered_model.backbone();
  ASSERT_TRUE(entered.traced_start.has_value());
  ASSERT_LT(*entered.traced_start, 2.0);
  double first = std::numeric_limits<double>::infinity();
  const nsm::BackbonePoint *first_point = nullptr;
  for (const nsm::BackbonePoint &p : entered.points)
    if (p.branch == nsm::Branch::main && p.omega < first)
      first = p.omega, first_point = &p;
  ASSERT_NE(first_point, nullptr);
  // Within the search's width of Omega min, on the whole run's main branch
  // there (its main points on both sides, linear between them, within the
  // Tongue share).
  EXPECT_LE(first, 2.0 + scene.continuation.fill_gaps_wider_than);
  const nsm::BackbonePoint *below = nullptr, *above = nullptr;
  for (const nsm::BackbonePoint &p : whole.points)
    if (p.branch == nsm::Branch::main)
      {
        if (p.omega <= first && (!below || p.omega > below->omega))
          below = &p;
        if (p.omega >= first && (!above || p.omega < above->omega))
          above = &p;
      }
  ASSERT_TRUE(below && above);
  const double t    = above->omega == below->omega ? 0 : (first - below->omega) / (above->omega - below->omega);
  const double main = below->measures.energy + t * (above->measures.energy - below->measures.energy);
  EXPECT_NEAR(first_point->measures.energy / main, 1, scene.continuation.tongue_share) << first;
}
