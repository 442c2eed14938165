// Refinement towards the contact end pays where the section thins there:
// for A(x) = 1.02 - x (A(L) = A(0) / 51) over the band [0, 2], graded and
// adaptive meshes reach 1e-7 relative accuracy of gamma (against the exact
// Bessel receptance) with fewer DoFs than uniform meshes.
#include <gtest/gtest.h>

#include "refinement_study.h"

TEST(Refinement, GradedAndAdaptiveNeedFewerDofsThanUniform)
{
  const study::Case strong_taper{1.02, 2, 2.0, 1e-7};
  const auto uniform  = study::uniform_or_graded(strong_taper, false);
  const auto graded   = study::uniform_or_graded(strong_taper, true);
  const auto adaptive = study::adaptive(strong_taper);
  ASSERT_LT(uniform.dofs, 100000u);
  // Measured: uniform 687, graded 133, adaptive 209 DoFs.
  EXPECT_LT(graded.dofs, uniform.dofs / 2) << graded.mesh << " vs " << uniform.mesh;
  EXPECT_LT(adaptive.dofs, uniform.dofs / 2) << adaptive.mesh << " vs " << uniform.mesh;
}

TEST(Refinement, GradedMeshShrinksTowardsTheContactEnd)
{
  nsm::Scene scene = testing_helpers::bar_scene("1", 1, 10);
  scene.discretisation.refinement    = nsm::Refinement::graded;
  scene.discretisation.graded_ratio  = 0.5;
  scene.discretisation.graded_layers = 3;
  const nsm::BarModel       bar(scene.bar);
  const nsm::Discretisation d(bar, scene.discretisation);
  // 7 cells of size s, then s/2, s/4, s/8: 7s + 7s/8 = 1.
  const double s = 1.0 / (7 + 0.875);
  EXPECT_NEAR(d.max_cell_size(), s, 1e-14);
  EXPECT_NEAR(d.min_cell_size(), s / 8, 1e-14);
  EXPECT_EQ(d.n_dofs(), 11u);
  // Where: the cell at the contact end x = L is the smallest, the one at
  // the clamp x = 0 the largest.
  for (const auto &cell : d.dof_handler().active_cell_iterators())
    {
      if (std::abs(cell->vertex(1)[0] - 1.0) < 1e-14)
        {
          EXPECT_NEAR(cell->diameter(), s / 8, 1e-14);
        }
      if (std::abs(cell->vertex(0)[0]) < 1e-14)
        {
          EXPECT_NEAR(cell->diameter(), s, 1e-14);
        }
    }
}

TEST(Refinement, AdaptiveRefinementStopsAtTheRoundOffLimit)
{
  // Round-off limit 1e-12 with p = 1: no cell below eps / 1e-12 = 2.2e-4 L.
  // The tolerance 1e-14 is out of reach, so only the limit stops the
  // refinement before its 30 steps: halving 0.025 six times gives 3.9e-4,
  // once more 2e-4. With the limit 1e-7 the same run refines further.
  for (const double limit : {1e-12, 1e-7})
    {
      nsm::Scene scene = testing_helpers::bar_scene("1.5 - x", 1, 40);
      scene.discretisation.refinement         = nsm::Refinement::adaptive;
      scene.discretisation.adaptive_steps     = 30;
      scene.discretisation.adaptive_tolerance = 1e-14;
      scene.discretisation.roundoff_limit     = limit;
      const nsm::BarModel bar(scene.bar);
      nsm::Discretisation d(bar, scene.discretisation);
      const auto notes = nsm::refine_adaptively(d, scene.discretisation, 2.0);
      const bool stopped = notes.back().find("stops") != std::string::npos;
      if (limit == 1e-12)
        {
          EXPECT_TRUE(stopped) << notes.back();
          EXPECT_GE(d.min_cell_size(), scene.discretisation.smallest_cell());
          EXPECT_LT(d.min_cell_size() / 2, scene.discretisation.smallest_cell());
        }
      else
        EXPECT_LT(d.min_cell_size(), 1e-4);
    }
}
