// Study (not a test): (1) the uniform bar's energy and Signorini residuals
// against the exact solution as M grows; (2) sampled against exact
// integration of the contact law: at one Omega on the exact branch, the
// sampled system is solved from the exact solution; the table gives the
// energy difference, the cost of one residual + Jacobian evaluation, and the
// Newton iterations.
#include <nsm/base/threads.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "hb_model.h"

namespace
{
  /// Milliseconds per residual + Jacobian evaluation near x (perturbed at
  /// each repeat so that no cached Gram matrix is reused).
  double evaluation_ms(nsm::HarmonicBalance &hb, double omega, std::vector<double> x)
  {
    hb.set_omega(omega);
    std::vector<double> r, j;
    const int           repeats = 200;
    const auto          start   = std::chrono::steady_clock::now();
    for (int k = 0; k < repeats; ++k)
      {
        for (double &v : x)
          v += 1e-14;
        hb.evaluate(x, &r, &j, nullptr);
      }
    return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / repeats;
  }
} // namespace

/// Uniform bar: E = g0^2 / (2 (T - 3)^2) (Yoong, Thorin, Legrand 2018).
void uniform_convergence()
{
  std::printf("| M | Omega | energy | exact | relative error | min g / g0 | min lambda / max lambda | max lambda g / (max lambda g0) |\n|---|---|---|---|---|---|---|---|\n");
  for (const unsigned int m : {5u, 10u, 20u, 40u})
    {
      nsm::Scene scene = testing_helpers::hb_scene("1", m);
      scene.continuation.omega_max  = 1.85;
      scene.continuation.max_step   = 5e-3;
      scene.continuation.energy_max = 1e-5;
      testing_helpers::HbModel model(scene);
      const auto               backbone = model.backbone();
      for (const double omega : {1.6, 1.8})
        {
          const double period = 2 * M_PI / omega, g0 = scene.contact.gap;
          const double exact  = g0 * g0 / (2 * (period - 3) * (period - 3));
          try
            {
              const auto p = nsm::solve_on_branch(model.hb, nsm::BranchParameters(scene), backbone, omega).measures;
              std::printf("| %u | %g | %.6e | %.6e | %+.2e | %.4f | %.4f | %.4f |\n", m, omega, p.energy, exact,
                          p.energy / exact - 1, p.min_gap, p.min_force, p.max_complementarity);
            }
          catch (const std::exception &e)
            {
              std::printf("| %u | %g | not on the computed branch | %.6e | | | | |\n", m, omega, exact);
            }
        }
    }
}

int main()
{
  nsm::use_one_thread(); // as nsm-bar: the same results
  uniform_convergence();
  struct Case
  {
    const char  *name;
    const char  *section;
    unsigned int harmonics;
    double       omega_max, omega, energy_max;
  };
  for (const Case &c : {Case{"uniform bar, M = 10", "1", 10, 1.85, 1.6, 1e-5},
                        Case{"seed bar, M = 40", "1.5 - x", 40, 2.0, 1.95, 1e-3}})
    {
      nsm::Scene scene = testing_helpers::hb_scene(c.section, c.harmonics);
      scene.continuation.omega_max  = c.omega_max;
      scene.continuation.energy_max = c.energy_max;
      testing_helpers::HbModel exact(scene);
      const auto point = nsm::solve_on_branch(exact.hb, nsm::BranchParameters(scene), exact.backbone(), c.omega);
      std::printf("\n%s, Omega = %g: exact integration E = %.10e, %.4f ms per evaluation\n\n",
                  c.name, c.omega, point.measures.energy, evaluation_ms(exact.hb, c.omega, point.x));
      std::printf("| time samples | relative energy difference to exact | ms per evaluation | Newton iterations from the exact solution |\n|---|---|---|---|\n");
      scene.harmonic_balance.integration = nsm::Integration::sampled;
      for (const unsigned int samples : {128u, 256u, 512u, 1024u, 2048u, 4096u, 8192u, 16384u})
        {
          scene.harmonic_balance.time_samples = samples;
          testing_helpers::HbModel sampled(scene);
          nsm::NewtonSolver        newton(sampled.hb, scene.harmonic_balance);
          const auto               result = newton.solve(c.omega, point.x);
          if (!result.converged)
            {
              std::printf("| %u | Newton did not converge | | |\n", samples);
              continue;
            }
          sampled.hb.set_omega(c.omega);
          const double energy = sampled.hb.measure(result.x).energy;
          std::printf("| %u | %.2e | %.4f | %u |\n", samples, std::abs(energy / point.measures.energy - 1),
                      evaluation_ms(sampled.hb, c.omega, result.x), result.iterations);
        }
    }
}
