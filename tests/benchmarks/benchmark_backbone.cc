// Benchmark (not a test): the seed scene's backbone from grazing to
// W = 2.2 with sequential and arclength continuation, on the paper's mesh
// (FE_Q(1), 4000 cells) and on the FE_Q(10), 7-cell mesh of the same
// receptance accuracy (benchmark_receptance); then, on the latter, how the
// cost of a converged Newton solve and of its parts grows with the harmonics
// M (sequential). Ratios are from this one run.
#include <nsm/model/bar_model.h>
#include <nsm/continuation/continuation.h>
#include <nsm/model/discretisation.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/base/threads.h>
#include <nsm/model/receptance.h>

#include <chrono>
#include <cstdio>

#include "scene_helpers.h"

namespace
{
  double since(std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  void run(const char *name, unsigned int degree, unsigned int cells, nsm::ContinuationMethod method)
  {
    nsm::Scene scene = testing_helpers::bar_scene("1.5 - x", degree, cells);
    scene.receptance.method        = nsm::ReceptanceMethod::modal;
    scene.continuation.method      = method;
    scene.continuation.omega_min   = 1.5;
    scene.continuation.energy_max  = 1e-3;
    const auto start = std::chrono::steady_clock::now();
    const nsm::BarModel       bar(scene.bar);
    const nsm::Discretisation d(bar, scene.discretisation);
    const nsm::Receptance     r(d, scene.receptance, 40 * scene.continuation.omega_max);
    const double              setup = since(start);
    nsm::HarmonicBalance      hb(scene.harmonic_balance, scene.contact, r);
    const auto                resonances = nsm::internal_resonances(r, nsm::BranchParameters(scene));
    const auto                traced = std::chrono::steady_clock::now();
    const nsm::Backbone       backbone = nsm::compute_backbone(hb, nsm::BranchParameters(scene), resonances);
    const double              tracing = since(traced), total = since(start);
    const auto               &cost = hb.cost();
    const double other = tracing - cost.receptance_seconds - cost.residual_seconds -
                         cost.jacobian_seconds - cost.linear_solve_seconds;
    const auto &newton = backbone.newton_cost;
    std::printf("| %s | %s | %zu | %u | %zu | %u | %zu | %.3f | %.3f | %.3f | %.1f %% | %.1f %% | %.1f %% | %.1f %% | %.1f %% | %.2f | %.2f | %.4f | %.3f (%.1f it) | %lu solves, %.2f s |\n",
                name, method == nsm::ContinuationMethod::sequential ? "sequential" : "arclength",
                backbone.points.size(), backbone.main_points(), backbone.tongues.size(),
                backbone.leaps, backbone.folds.size(), setup, tracing, total,
                100 * cost.receptance_seconds / tracing, 100 * cost.residual_seconds / tracing,
                100 * cost.jacobian_seconds / tracing, 100 * cost.linear_solve_seconds / tracing,
                100 * other / tracing,
                1e3 * tracing / backbone.points.size(),
                backbone.main_points() ? 1e3 * tracing / backbone.main_points() : 0.0, backbone.points.back().omega,
                newton.converged_solves ? 1e3 * newton.converged_seconds / newton.converged_solves : 0.0,
                newton.converged_solves ? double(newton.converged_iterations) / newton.converged_solves : 0.0,
                newton.failed_solves, newton.failed_seconds);
  }
  double per_call_us(double seconds, unsigned long calls) { return calls ? 1e6 * seconds / calls : 0.0; }

  void scaling(unsigned int harmonics)
  {
    nsm::Scene scene = testing_helpers::bar_scene("1.5 - x", 10, 7);
    scene.receptance.method         = nsm::ReceptanceMethod::modal;
    scene.harmonic_balance.harmonics = harmonics;
    scene.continuation.omega_min    = 1.5;
    scene.continuation.energy_max   = 1e-3;
    const nsm::BarModel       bar(scene.bar);
    const nsm::Discretisation d(bar, scene.discretisation);
    const nsm::Receptance     r(d, scene.receptance, harmonics * scene.continuation.omega_max);
    nsm::HarmonicBalance      hb(scene.harmonic_balance, scene.contact, r);
    const auto                start    = std::chrono::steady_clock::now();
    const nsm::Backbone       backbone = nsm::compute_backbone(hb, nsm::BranchParameters(scene), nsm::internal_resonances(r, nsm::BranchParameters(scene)));
    const double              tracing  = since(start);
    const auto               &cost     = hb.cost();
    const auto               &newton   = backbone.newton_cost;
    std::printf("| %u | %u | %zu | %.3f | %.3f (%.1f it) | %.1f | %.1f | %.1f | %.4f |\n", harmonics, hb.n_unknowns(),
                backbone.points.size(), tracing,
                newton.converged_solves ? 1e3 * newton.converged_seconds / newton.converged_solves : 0.0,
                newton.converged_solves ? double(newton.converged_iterations) / newton.converged_solves : 0.0,
                per_call_us(cost.residual_seconds, cost.residuals), per_call_us(cost.jacobian_seconds, cost.jacobians),
                per_call_us(cost.linear_solve_seconds, cost.linear_solves), backbone.points.back().omega);
  }
} // namespace

int main()
{
  nsm::use_one_thread(); // as nsm-bar: the same results
  std::printf("| mesh | method | points | main points | tongues | leaps | folds | set-up [s] | backbone [s] | total [s] | receptance | residual | Jacobian (+dR/dW) | linear solves | NOX/LOCA, predictors, measures | ms per point (all) | ms per main point | last Omega | ms per converged Newton solve | failed solves (folds, leaps) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto method : {nsm::ContinuationMethod::sequential, nsm::ContinuationMethod::arclength})
    {
      run("FE_Q(1), 4000 cells", 1, 4000, method);
      run("FE_Q(10), 7 cells", 10, 7, method);
    }
  std::printf("\nFE_Q(10), 7 cells, sequential, by harmonics M:\n\n");
  std::printf("| M | unknowns | points | backbone [s] | ms per converged Newton solve | residual [us] | Jacobian [us] | linear solve [us] | last Omega |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const unsigned int harmonics : {20u, 40u, 80u})
    scaling(harmonics);
}
