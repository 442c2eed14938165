// Benchmark (not a test): gamma at the 41 frequencies k W (k = 0..40,
// W = 2) with the seed discretisation (p = 1, 4000 cells) against the
// cheapest FE_Q(p >= 4) mesh that is at least as accurate (against the exact
// Bessel receptance). Ratios are measured in this one run.
#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/base/threads.h>
#include <nsm/model/receptance.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "exact_bar.h"
#include "scene_helpers.h"

namespace
{
  constexpr double       omega     = 2.0;
  constexpr unsigned int harmonics = 40;

  struct Model
  {
    Model(unsigned int p, unsigned int cells)
      : scene(testing_helpers::bar_scene("1.5 - x", p, cells))
      , bar(scene.bar)
      , discretisation(bar, scene.discretisation)
    {}
    nsm::Scene          scene;
    nsm::BarModel       bar;
    nsm::Discretisation discretisation;
  };

  double error(const nsm::Receptance &r)
  {
    double e = 0, scale = 0;
    for (unsigned int k = 0; k <= harmonics; ++k)
      {
        const double exact = exact::tapered_receptance(k * omega);
        e     = std::max(e, std::abs(r(k * omega).gamma - exact));
        scale = std::max(scale, std::abs(exact));
      }
    return e / scale;
  }

  /// Seconds per evaluation of the 41 values (set-up included), best of 5.
  double seconds(const nsm::Discretisation &d, nsm::ReceptanceMethod method)
  {
    double best = 1e300;
    for (int repeat = 0; repeat < 5; ++repeat)
      {
        const auto start = std::chrono::steady_clock::now();
        const nsm::Receptance r(d, {method, 0}, harmonics * omega);
        double sum = 0;
        for (unsigned int k = 0; k <= harmonics; ++k)
          sum += r(k * omega).gamma;
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = std::min(best, t + 0 * sum);
      }
    return best;
  }
} // namespace

int main()
{
  nsm::use_one_thread(); // as nsm-bar: the same results
  const Model seed(1, 4000);
  const double seed_error =
    error(nsm::Receptance(seed.discretisation, {nsm::ReceptanceMethod::direct, 0}, 0.0));

  std::unique_ptr<Model> best;
  for (unsigned int p = 4; p <= 10; ++p)
    for (unsigned int cells = 1; cells <= 400; ++cells)
      {
        auto candidate = std::make_unique<Model>(p, cells);
        if (best && candidate->discretisation.n_dofs() >= best->discretisation.n_dofs())
          break;
        if (error(nsm::Receptance(candidate->discretisation, {nsm::ReceptanceMethod::direct, 0}, 0.0)) <= seed_error)
          {
            best = std::move(candidate);
            break;
          }
      }
  const double best_error =
    error(nsm::Receptance(best->discretisation, {nsm::ReceptanceMethod::direct, 0}, 0.0));

  std::printf("gamma at k W, k = 0..%u, W = %g; error = max_k |gamma_h - gamma| / max_k |gamma|\n",
              harmonics, omega);
  std::printf("%-28s %8s %12s %14s %14s\n", "discretisation", "DoFs", "error", "direct [s]", "modal [s]");
  const auto row = [](const char *name, const Model &m, double e) {
    std::printf("%-28s %8u %12.3e %14.6f %14.6f\n", name, m.discretisation.n_dofs(), e,
                seconds(m.discretisation, nsm::ReceptanceMethod::direct),
                seconds(m.discretisation, nsm::ReceptanceMethod::modal));
  };
  row("seed: FE_Q(1), 4000 cells", seed, seed_error);
  char name[64];
  std::snprintf(name, sizeof name, "FE_Q(%u), %u cells", best->discretisation.fe().degree,
                best->discretisation.n_cells());
  row(name, *best, best_error);
  const double t_seed = seconds(seed.discretisation, nsm::ReceptanceMethod::direct);
  const double t_best = seconds(best->discretisation, nsm::ReceptanceMethod::direct);
  const double t_best_modal = seconds(best->discretisation, nsm::ReceptanceMethod::modal);
  std::printf("ratios (seed / high order): DoFs %.1f, time direct %.1f, time seed direct / high-order modal %.1f\n",
              double(seed.discretisation.n_dofs()) / best->discretisation.n_dofs(),
              t_seed / t_best, t_seed / t_best_modal);
}
