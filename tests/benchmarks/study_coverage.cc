// Study: is a gap in the main branch a gap of the solutions or of the
// continuation? The seed bar (FE_Q(10) x 20, modal, exact integration,
// sequential, grazing to Omega = 2.2, Energy max 1e-3) at M harmonics: every
// gap between main points wider than `width`, and inside each, Newton at M
// (line search, as a leap) from every point there of the branches with M / 2
// and 2 M harmonics, padded with zeros or truncated. A converged solution
// labelled main against the M branch's envelope is a main solution the
// continuation missed. As a control, the same search from the M / 2 branch's
// main points outside the gaps says how often it finds the main branch where
// the continuation did.
//   study_coverage M [width [fill]]   (exit 1 if a gap holds a main solution;
//   fill: the M branch's Continuation/Fill gaps wider than, 0 by default)
#include <nsm/base/threads.h>
#include <nsm/continuation/branch_context.h>
#include <nsm/continuation/main_branch.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "hb_model.h"

namespace
{
  constexpr double omega_end = 2.2;

  using Gap = std::pair<double, double>; // (from, to)

  struct Tally
  {
    unsigned int guesses = 0, converged = 0, main = 0;
    double       lowest_ratio = 0; ///< least energy found over the envelope at its Omega
  };

  nsm::Scene coverage_scene(const unsigned int harmonics)
  {
    nsm::Scene scene = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, omega_end);
    scene.discretisation.cells       = 20;
    scene.harmonic_balance.harmonics = harmonics;
    return scene;
  }

  std::vector<Gap> wide_gaps(const nsm::Backbone &b, const double width)
  {
    std::vector<Gap> gaps;
    for (const Gap &g : nsm::main_gaps(b.points, 1, omega_end))
      if (g.second - g.first > width)
        gaps.push_back(g);
    return gaps;
  }

  /// Newton at M from the point q of another branch, at q's Omega.
  void search_from(testing_helpers::HbModel &model, const nsm::Backbone &b, const nsm::BackbonePoint &q,
                   Tally &tally, std::vector<double> &found)
  {
    nsm::BranchContext context(model.hb, model.branch, {});
    nsm::BackbonePoint point;
    ++tally.guesses;
    if (!context.solve(q.omega, context.guess_from_fewer_harmonics(q), 0, point, nsm::BranchContext::Newton::both))
      return;
    ++tally.converged;
    nsm::label_point(model.hb, model.branch, b.points, point);
    const double ratio = point.measures.energy / nsm::envelope_at(b.points, point.omega, 1);
    tally.lowest_ratio = tally.converged == 1 ? ratio : std::min(tally.lowest_ratio, ratio);
    if (point.branch == nsm::Branch::main)
      ++tally.main, found.push_back(point.omega);
  }

  bool inside(const std::vector<Gap> &gaps, const double omega)
  {
    return std::any_of(gaps.begin(), gaps.end(), [&](const Gap &g) { return g.first < omega && omega < g.second; });
  }
} // namespace

int main(int argc, char **argv)
{
  nsm::use_one_thread(); // as nsm-bar: the same results
  if (argc < 2)
    {
      std::fprintf(stderr, "usage: study_coverage M [width [fill]]\n");
      return 2;
    }
  const unsigned int harmonics = static_cast<unsigned int>(std::atoi(argv[1]));
  const double       width     = argc > 2 ? std::atof(argv[2]) : 0.01;
  const double       fill      = argc > 3 ? std::atof(argv[3]) : 0.0;
  const auto         start     = std::chrono::steady_clock::now();

  nsm::Scene scene                         = coverage_scene(harmonics);
  scene.continuation.fill_gaps_wider_than = fill;
  testing_helpers::HbModel model(scene);
  const nsm::Backbone      b    = model.backbone();
  const std::vector<Gap>   gaps = wide_gaps(b, width);

  // The neighbouring branches. At 2 M the default Max iterations lose the
  // seed branch at M = 320 (doc/accuracy-and-cost.md); 20 carry it to 2.2.
  nsm::Scene half = coverage_scene(harmonics / 2), twice = coverage_scene(2 * harmonics);
  if (2 * harmonics > 160)
    twice.harmonic_balance.max_iterations = 20;
  const nsm::Backbone b_half  = testing_helpers::HbModel(half).backbone();
  const nsm::Backbone b_twice = testing_helpers::HbModel(twice).backbone();

  std::printf("M = %u: %zu points, %u main, %zu main gaps wider than %g in [%.4f, %.1f]\n", harmonics,
              b.points.size(), b.main_points(), gaps.size(), width, b.points.front().omega, omega_end);
  std::printf("| gap from | to | width | guesses M/2 (main) | guesses 2M (main) | converged | main found (from M/2) | "
              "least E / envelope |\n|---|---|---|---|---|---|---|---|\n");
  unsigned int missed = 0;
  for (const Gap &g : gaps)
    {
      Tally               tally;
      std::vector<double> found;
      unsigned int        counts[2][2] = {{0, 0}, {0, 0}}, main_from[2] = {0, 0};
      for (int k = 0; k < 2; ++k)
        for (const nsm::BackbonePoint &q : (k == 0 ? b_half : b_twice).points)
          if (g.first < q.omega && q.omega < g.second)
            {
              ++counts[k][0];
              counts[k][1] += q.branch == nsm::Branch::main;
              const unsigned int before = tally.main;
              search_from(model, b, q, tally, found);
              main_from[k] += tally.main - before;
            }
      missed += tally.main;
      std::printf("| %.4f | %.4f | %.4f | %u (%u) | %u (%u) | %u | %u (%u from M/2)", g.first, g.second, g.second - g.first,
                  counts[0][0], counts[0][1], counts[1][0], counts[1][1], tally.converged, tally.main,
                  main_from[0]);
      for (std::size_t i = 0; i < std::min<std::size_t>(found.size(), 6); ++i)
        std::printf(" %.4f", found[i]);
      std::printf(" | %.3g |\n", tally.converged ? tally.lowest_ratio : 0.0);
    }

  // Control: where the M branch has main points, does the same search find them?
  Tally               control;
  std::vector<double> found;
  for (const nsm::BackbonePoint &q : b_half.points)
    if (q.branch == nsm::Branch::main && q.omega > b.points.front().omega && !inside(gaps, q.omega))
      search_from(model, b, q, control, found);
  std::printf("control (M/2 main points outside the gaps): %u guesses, %u converged, %u main\n", control.guesses,
              control.converged, control.main);
  std::printf("main solutions found in the gaps: %u; %.1f s\n", missed,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return missed ? 1 : 0;
}
