// Benchmark (not a test): the seed bar at high M (FE_Q(10) x 20, modal,
// exact integration, grazing to Omega = 2.2, Energy max 1e-3), sequential or
// arclength: whole-run time, where the harmonic-balance time goes (converged
// and failed Newton solves, residuals, Jacobians, linear solves), and the
// widest gaps between main points in [w1, 2.2].
//   benchmark_high_harmonics [sequential|arclength] [fill=WIDTH] M...
// (fill=WIDTH: Continuation/Fill gaps wider than, 0 by default)
#include <nsm/base/threads.h>
#include <nsm/continuation/main_branch.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "hb_model.h"

namespace
{
  void run(const unsigned int harmonics, const nsm::ContinuationMethod method, const double fill)
  {
    nsm::Scene scene = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
    scene.discretisation.cells       = 20;
    scene.harmonic_balance.harmonics = harmonics;
    scene.continuation.method        = method;
    scene.continuation.fill_gaps_wider_than = fill;
    const auto               start = std::chrono::steady_clock::now();
    testing_helpers::HbModel model(scene);
    const nsm::Backbone      b       = model.backbone();
    const double             seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto              &hb = model.hb.cost();
    const auto              &n  = b.newton_cost;

    std::vector<std::pair<double, double>> gaps; // (width, from), widest first
    for (const auto &[from, to] : nsm::main_gaps(b.points, 1, 2.2))
      gaps.emplace_back(to - from, from);
    std::sort(gaps.rbegin(), gaps.rend());

    std::printf("| %u | %s | %.2f | %zu | %u | %u | %.6f | %lu (%.1f it) %.2f s | %lu (%.1f it) %.2f s | %.0f %% "
                "| %.2f / %.2f / %.2f s | %.1f us |",
                harmonics, method == nsm::ContinuationMethod::sequential ? "sequential" : "arclength", seconds,
                b.points.size(), b.main_points(), b.leaps, b.points.empty() ? 0.0 : *b.omega_reached(1),
                n.converged_solves, n.converged_solves ? double(n.converged_iterations) / n.converged_solves : 0.0,
                n.converged_seconds, n.failed_solves,
                n.failed_solves ? double(n.failed_iterations) / n.failed_solves : 0.0, n.failed_seconds,
                100 * n.failed_seconds / seconds, hb.residual_seconds, hb.jacobian_seconds, hb.linear_solve_seconds,
                hb.linear_solves ? 1e6 * hb.linear_solve_seconds / hb.linear_solves : 0.0);
    for (std::size_t i = 0; i < std::min<std::size_t>(3, gaps.size()); ++i)
      std::printf(" %.4f at %.4f", gaps[i].first, gaps[i].second);
    std::printf(" |\n");
    std::fflush(stdout);
  }
} // namespace

int main(int argc, char **argv)
{
  nsm::use_one_thread(); // as nsm-bar: the same results
  nsm::ContinuationMethod method = nsm::ContinuationMethod::sequential;
  int                     first  = 1;
  if (argc > 1 && std::strcmp(argv[1], "arclength") == 0)
    method = nsm::ContinuationMethod::arclength, first = 2;
  else if (argc > 1 && std::strcmp(argv[1], "sequential") == 0)
    first = 2;
  std::printf("| M | method | run [s] | points | main | leaps | Omega reached | converged solves | failed solves "
              "| failed share | residuals / Jacobians / linear solves | per linear solve | widest main gaps |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  double fill = 0;
  if (first < argc && std::strncmp(argv[first], "fill=", 5) == 0)
    fill = std::atof(argv[first++] + 5);
  for (int a = first; a < argc; ++a)
    run(static_cast<unsigned int>(std::atoi(argv[a])), method, fill);
}
