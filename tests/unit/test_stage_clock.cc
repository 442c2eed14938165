// The stages' clock (base/stage_clock.h): what a run's summary and a study's
// row read of it. Times themselves are not compared: only what the clock
// lists, in which order, and that it keeps a stage whose work throws.
#include <nsm/base/stage_clock.h>

#include <gtest/gtest.h>

#include <stdexcept>

TEST(StageClock, ListsEachStageOnceInTheOrderOfItsFirstEntry)
{
  nsm::StageClock clock;
  EXPECT_EQ(clock.timed("mesh", [] { return 3; }), 3); // the work's value passes through
  clock.timed("harmonic balance", [] {});
  clock.timed("mesh", [] {});
  const std::vector<nsm::StageTiming> t = clock.timings();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].name, "mesh");
  EXPECT_EQ(t[1].name, "harmonic balance");
  for (const nsm::StageTiming &s : t)
    {
      EXPECT_GE(s.wall_seconds, 0.0) << s.name;
      EXPECT_GE(s.cpu_seconds, 0.0) << s.name;
    }
}

TEST(StageClock, KeepsAStageWhoseWorkThrows)
{
  nsm::StageClock clock;
  EXPECT_THROW(clock.timed("plots", []() -> int { throw std::runtime_error("no display"); }), std::runtime_error);
  clock.timed("output", [] {});
  const std::vector<nsm::StageTiming> t = clock.timings();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].name, "plots");
  EXPECT_EQ(t[1].name, "output");
}
