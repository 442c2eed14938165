// The climb into the accumulation point W_acc: its truncated top named a
// tongue of the accumulation point from the per-point estimate
// |E(M/2) / E(M) - 1| (doc/method.md, "The accumulation point"), on planted
// climbs. Against an independent reference (M = 160) the scene test
// scene.accumulation_tongue judges the same rule on 1 + 0.2 x.
#include <nsm/continuation/accumulation_tongue.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hb_model.h"

namespace
{
  const double no_estimate = std::numeric_limits<double>::quiet_NaN();

  struct Climb
  {
    nsm::Backbone         backbone;
    std::vector<double>   estimates;
    nsm::BranchParameters params;
  };

  /// W_acc = pi / 2, M = 40, Tongue share 0.02; each point at W_acc (1 + r /
  /// M^2) for its offset r, with its label and estimate.
  Climb planted(const nsm::ForceSign sign, const std::vector<std::tuple<unsigned int, double, nsm::Branch, double>> &rows)
  {
    nsm::Scene scene                  = testing_helpers::seed_scene(sign, 1.5, 2.2);
    scene.harmonic_balance.harmonics  = 40;
    scene.continuation.tongue_share   = 0.02;
    Climb climb{{}, {}, nsm::BranchParameters(scene)};
    climb.params.accumulation_omega = M_PI / 2;
    for (const auto &[segment, r, branch, estimate] : rows)
      {
        nsm::BackbonePoint p{};
        p.segment         = segment;
        p.omega           = M_PI / 2 * (1 + r / 1600);
        p.measures.energy = 1 + r;
        p.branch          = branch;
        climb.backbone.points.push_back(p);
        climb.estimates.push_back(estimate);
      }
    return climb;
  }

  const auto on_main = nsm::Branch::main, tongue = nsm::Branch::tongue, other = nsm::Branch::other;

  /// The climb (segment 0) from grazing 6 / M^2 below W_acc to its top 0.3 / M^2
  /// beyond it, a leap's landing on another family (segment 1) and the main
  /// branch beyond the passing point W_acc (1 + 4 / M^2) (segment 2). Down
  /// from the top the estimate exceeds 0.02 to 0.8 / M^2 below W_acc: M's
  /// own truncated zone starts a quarter as far below, at 0.2 / M^2.
  std::vector<std::tuple<unsigned int, double, nsm::Branch, double>> climb_rows(const double top_estimate)
  {
    return {{0, -6.0, on_main, 0.001}, {0, -3.0, on_main, 0.001},   {0, -1.0, on_main, 0.01},  {0, -0.8, on_main, 0.05},
            {0, -0.4, on_main, 0.2},     {0, -0.15, on_main, 0.3},  {0, -0.1, tongue, 0.4},
            {0, 0.3, on_main, top_estimate}, {1, 0.2, other, 0.01}, {2, 5.0, on_main, 0.01}};
  }
} // namespace

TEST(AccumulationTongue, TheClimbsTruncatedTopIsATongueOfTheAccumulationPoint)
{
  Climb c = planted(nsm::ForceSign::physical, climb_rows(0.6));
  EXPECT_EQ(nsm::name_accumulation_tongue(c.backbone, c.estimates, c.params), 3u);
  const std::vector<nsm::Branch> expected{on_main, on_main, on_main, on_main, on_main,
                                          tongue,  tongue,  tongue,  other,   on_main};
  for (std::size_t i = 0; i < expected.size(); ++i)
    {
      EXPECT_EQ(c.backbone.points[i].branch, expected[i]) << i;
      EXPECT_EQ(nsm::at_accumulation_point(c.backbone.points[i].resonance), expected[i] == tongue) << i;
    }
  // One tongue, its feet the main points on either side of it.
  ASSERT_EQ(c.backbone.tongues.size(), 1u);
  const nsm::Tongue &t = c.backbone.tongues[0];
  EXPECT_STREQ(nsm::resonance_kind(t.resonance), "accumulation");
  EXPECT_EQ(t.resonance.omega, M_PI / 2);
  EXPECT_EQ(t.points, 3u);
  EXPECT_EQ(t.foot_begin, c.backbone.points[4].omega);
  EXPECT_EQ(t.foot_end, c.backbone.points[9].omega);
  EXPECT_EQ(t.max_energy, c.backbone.points[7].measures.energy);
  // Called again (a resumed run), it names nothing more and keeps the labels.
  EXPECT_EQ(nsm::name_accumulation_tongue(c.backbone, c.estimates, c.params), 0u);
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(c.backbone.points[i].branch, expected[i]) << i;
}

// The top's energy unchanged by halving the harmonics (or not estimated):
// the truncation does not set it, and the climb stays main.
TEST(AccumulationTongue, AClimbConvergedToItsTopStaysMain)
{
  for (const double top : {0.01, no_estimate})
    {
      Climb c = planted(nsm::ForceSign::physical, climb_rows(top));
      EXPECT_EQ(nsm::name_accumulation_tongue(c.backbone, c.estimates, c.params), 0u) << top;
      EXPECT_EQ(c.backbone.points[7].branch, on_main) << top;
      EXPECT_EQ(c.backbone.points[6].branch, tongue) << top;
      EXPECT_FALSE(nsm::at_accumulation_point(c.backbone.points[6].resonance)) << top;
    }
}

// Eq. (5)'s sign softens: its branch is not taken across W_acc
// (accumulation_passed), and nothing is named; neither without estimates,
// nor on a branch that starts within 4 / M^2 of W_acc (the uniform bar's
// starts at it: it does not climb into it).
TEST(AccumulationTongue, NothingIsNamedWithoutACrossingOrEstimates)
{
  Climb soft = planted(nsm::ForceSign::seed_eq5, climb_rows(0.6));
  EXPECT_EQ(nsm::name_accumulation_tongue(soft.backbone, soft.estimates, soft.params), 0u);
  Climb bare = planted(nsm::ForceSign::physical, climb_rows(0.6));
  EXPECT_EQ(nsm::name_accumulation_tongue(bare.backbone, {}, bare.params), 0u);
  auto rows = climb_rows(0.6);
  rows.erase(rows.begin());
  Climb at_w_acc = planted(nsm::ForceSign::physical, rows);
  EXPECT_EQ(nsm::name_accumulation_tongue(at_w_acc.backbone, at_w_acc.estimates, at_w_acc.params), 0u);
  for (const Climb *c : {&soft, &bare})
    EXPECT_EQ(c->backbone.points[7].branch, on_main);
  EXPECT_EQ(at_w_acc.backbone.points[6].branch, on_main);
}
