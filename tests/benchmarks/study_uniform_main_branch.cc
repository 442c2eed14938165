// Study (not a test): how close to the uniform bar's exact mode can any
// harmonic-balance solution be, whatever the continuation? At each Omega of a
// grid, Newton starts from the exact mode's contact force projected on the HB
// unknowns (and from that guess scaled by 0.9 and 1.1); the converged solution
// closest in energy to the exact one is kept. The table bounds what a
// continuation that labels main points can reach at this M: the share of Omega
// values with a solution within 5 % of the exact energy, the median error, and
// the windows of width 0.01 in [1.58, 2.08) that hold such a solution.
#include <nsm/base/threads.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "exact_bar.h"
#include "hb_model.h"

namespace
{
  /// x_i = a_i / cos(theta_i) / F (the HB unknown carrying force a_i); 0 where
  /// cos(theta) nearly vanishes, which the exact force does there too.
  std::vector<double> projected_guess(const nsm::HarmonicBalance &hb, const exact::UniformMode &mode)
  {
    const unsigned int  n = hb.n_unknowns();
    const double        F = hb.force_scale();
    std::vector<double> x(n, 0.0);
    for (unsigned int i = 0; i < n; ++i)
      {
        std::vector<double> unit(n, 0.0);
        unit[i]                             = 1;
        const nsm::FourierCoefficients c    = hb.coefficients(unit);
        const double                   cosk = c.force[i] / F;
        if (!c.is_sine[i] && std::abs(cosk) > 1e-3)
          x[i] = mode.force_harmonic(c.order[i]) / cosk / F;
      }
    return x;
  }
} // namespace

int main(int argc, char **argv)
{
  nsm::use_one_thread(); // as nsm-bar: the same results
  const double grid = argc > 1 ? std::atof(argv[1]) : 0.0025;
  std::printf("uniform bar, FE_Q(10) x 10 cells, modal, exact integration; Omega = 1.5775 + i %g < 2.08\n\n", grid);
  std::printf("| M | Omega values | converged | within 5 %% | within 2.5 %% | median error | windows with a point within 5 %% (of 50) | empty windows |\n|---|---|---|---|---|---|---|---|\n");
  for (const unsigned int harmonics : {10u, 20u, 40u, 80u})
    {
      nsm::Scene scene                 = testing_helpers::hb_scene("1", harmonics);
      scene.continuation.omega_max     = 2.08;
      testing_helpers::HbModel model(scene);
      nsm::NewtonSolver        newton(model.hb, scene.harmonic_balance);
      unsigned int             total = 0, converged = 0, within5 = 0, within25 = 0;
      std::vector<double>      errors;
      std::set<int>            windows;
      for (double omega = 1.5775; omega < 2.08; omega += grid)
        {
          ++total;
          const exact::UniformMode mode(2 * M_PI / omega, scene.contact.gap);
          model.hb.set_omega(omega);
          const std::vector<double> guess = projected_guess(model.hb, mode);
          double                    best  = INFINITY;
          for (const double scale : {1.0, 0.9, 1.1})
            {
              std::vector<double> x = guess;
              for (double &v : x)
                v *= scale;
              const nsm::NewtonResult r = newton.solve(omega, x);
              if (!r.converged || !(r.residual <= scene.harmonic_balance.tolerance))
                continue;
              model.hb.set_omega(omega);
              const auto m = model.hb.measure(r.x);
              if (m.energy > 0 && m.contact_fraction > 0)
                best = std::min(best, std::abs(m.energy / mode.energy - 1));
            }
          if (!std::isfinite(best))
            continue;
          ++converged;
          errors.push_back(best);
          within5 += best < 0.05;
          within25 += best < 0.025;
          if (best < 0.05 && omega >= 1.58)
            windows.insert(static_cast<int>((omega - 1.58) / 0.01));
        }
      std::sort(errors.begin(), errors.end());
      std::string empty;
      for (int w = 0; w < 50; ++w)
        if (!windows.count(w))
          empty += (empty.empty() ? "" : ", ") + std::to_string(1.58 + 0.01 * w).substr(0, 4);
      std::printf("| %u | %u | %u | %u (%.0f %%) | %u | %.3f | %zu | %s |\n", harmonics, total, converged, within5,
                  100.0 * within5 / total, within25, errors.empty() ? NAN : errors[errors.size() / 2],
                  windows.size(), empty.c_str());
      std::fflush(stdout);
    }
}
