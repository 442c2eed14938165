// The climb into the accumulation point W_acc: its truncated top named a
// tongue of the accumulation point from the per-point estimate
// |E(M/2) / E(M) - 1| (doc/method.md, "The accumulation point"), on planted
// climbs. Against an independent reference (M = 160) the scene test
// scene.accumulation_tongue judges the same rule on 1 + 0.2 x.
#include <nsm/continuation/accumulation_tongue.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

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

  /// The climb (segment 0) from grazing 6 / M^2 below W_acc to its top 0.3 /
  /// M^2 beyond it; a leap's landing on another family (segment 1); the
  /// family beyond W_acc (segment 2), once inside the passing point W_acc (1 +
  /// 4 / M^2) and once beyond it. Down from the climb's last main point at or
  /// below W_acc (its estimate `top_estimate`) the estimate exceeds 0.02 to
  /// 0.8 / M^2 below W_acc, past a point without one, and stops at 1 / M^2
  /// (the estimate at 2 / M^2 is not reached): M's own truncated zone starts a
  /// quarter as deep, at 0.2 / M^2.
  std::vector<std::tuple<unsigned int, double, nsm::Branch, double>> climb_rows(const double top_estimate)
  {
    return {{0, -6.0, on_main, 0.001}, {0, -3.0, on_main, 0.001}, {0, -2.0, on_main, 0.5},
            {0, -1.0, on_main, 0.01},  {0, -0.8, on_main, 0.05},  {0, -0.6, on_main, no_estimate},
            {0, -0.4, on_main, 0.2},   {0, -0.15, on_main, top_estimate}, {0, -0.1, tongue, 0.4},
            {0, 0.3, on_main, 0.6},    {1, 0.2, other, 0.01},     {2, 2.0, on_main, 0.001},
            {2, 5.0, on_main, 0.01}};
  }
} // namespace

TEST(AccumulationTongue, TheClimbsTruncatedTopIsATongueOfTheAccumulationPoint)
{
  Climb c = planted(nsm::ForceSign::physical, climb_rows(0.3));
  EXPECT_EQ(nsm::name_accumulation_tongue(c.backbone, c.estimates, c.params), 4u);
  const std::vector<nsm::Branch> expected{on_main, on_main, on_main, on_main, on_main, on_main, on_main,
                                          tongue,  tongue,  tongue,  other,   tongue,  on_main};
  for (std::size_t i = 0; i < expected.size(); ++i)
    {
      EXPECT_EQ(c.backbone.points[i].branch, expected[i]) << i;
      EXPECT_EQ(nsm::at_accumulation_point(c.backbone.points[i].resonance), expected[i] == tongue) << i;
    }
  // One tongue over two segments, its feet the main points on either side.
  ASSERT_EQ(c.backbone.tongues.size(), 1u);
  const nsm::Tongue &t = c.backbone.tongues[0];
  EXPECT_STREQ(nsm::resonance_kind(t.resonance), "accumulation");
  EXPECT_EQ(t.resonance.omega, M_PI / 2);
  EXPECT_EQ(t.points, 4u);
  EXPECT_EQ(t.foot_begin, c.backbone.points[6].omega);
  EXPECT_EQ(t.foot_end, c.backbone.points[12].omega);
  EXPECT_EQ(t.max_energy, c.backbone.points[11].measures.energy);
  EXPECT_EQ(nsm::accumulation_span(c.backbone.points),
            std::make_pair(c.backbone.points[7].omega, c.backbone.points[11].omega));
  // Called again (a resumed run), it names nothing more and keeps the labels.
  EXPECT_EQ(nsm::name_accumulation_tongue(c.backbone, c.estimates, c.params), 0u);
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(c.backbone.points[i].branch, expected[i]) << i;
  ASSERT_EQ(c.backbone.tongues.size(), 1u);
}

// The top's energy unchanged by halving the harmonics: the truncation does
// not set it, and the climb stays main.
TEST(AccumulationTongue, AClimbConvergedToItsTopStaysMain)
{
  Climb c = planted(nsm::ForceSign::physical, climb_rows(0.01));
  EXPECT_EQ(nsm::name_accumulation_tongue(c.backbone, c.estimates, c.params), 0u);
  EXPECT_EQ(c.backbone.points[7].branch, on_main);
  EXPECT_EQ(c.backbone.points[8].branch, tongue);
  EXPECT_FALSE(nsm::at_accumulation_point(c.backbone.points[8].resonance));
}

// Eq. (5)'s sign softens: its branch is not taken across W_acc
// (accumulation_passed), and nothing is named; neither without estimates,
// nor on a branch that starts within 4 / M^2 of W_acc (the uniform bar's
// starts at it: it does not climb into it).
TEST(AccumulationTongue, NothingIsNamedWithoutACrossingOrEstimates)
{
  Climb soft = planted(nsm::ForceSign::seed_eq5, climb_rows(0.3));
  EXPECT_EQ(nsm::name_accumulation_tongue(soft.backbone, soft.estimates, soft.params), 0u);
  Climb bare = planted(nsm::ForceSign::physical, climb_rows(0.3));
  EXPECT_EQ(nsm::name_accumulation_tongue(bare.backbone, {}, bare.params), 0u);
  auto rows = climb_rows(0.3);
  rows.erase(rows.begin());
  Climb at_w_acc = planted(nsm::ForceSign::physical, rows);
  EXPECT_EQ(nsm::name_accumulation_tongue(at_w_acc.backbone, at_w_acc.estimates, at_w_acc.params), 0u);
  for (const Climb *c : {&soft, &bare})
    EXPECT_EQ(c->backbone.points[9].branch, on_main);
  EXPECT_EQ(at_w_acc.backbone.points[8].branch, on_main);
}
