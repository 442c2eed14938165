// Study (not a test): how much of the gaps that leaps leave does sequential
// continuation backwards from each landing fill? The seed bar (FE_Q(10) x 20,
// exact integration, grazing to 2.2) at M (argument, default 160): for every
// leap wider than 0.003, steps of 1e-3 (grown by 1.5 after easy solves,
// quartered on failure down to 1e-6) from the landing towards the front of
// the segment before, with the same branch guard as the sequential method;
// prints how far back each gets, with the energies on the way.
//   study_backfill [M]
#include <nsm/base/threads.h>
#include <nsm/continuation/sequential_steps.h>
#include <nsm/harmonic_balance/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "hb_model.h"

int main(int argc, char **argv)
{
  nsm::use_one_thread();
  const unsigned int M = argc > 1 ? std::atoi(argv[1]) : 160;
  nsm::Scene scene = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
  scene.discretisation.cells       = 20;
  scene.harmonic_balance.harmonics = M;
  testing_helpers::HbModel model(scene);
  const nsm::Backbone      b = model.backbone();
  nsm::NewtonSolver        newton(model.hb, scene.harmonic_balance);
  const auto              &p = b.points;
  double                   filled_total = 0, gap_total = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    {
      if (p[i].segment == p[i - 1].segment)
        continue;
      // the previous segment's furthest point
      double front = 0;
      for (std::size_t j = 0; j < i; ++j)
        if (p[j].segment == p[i - 1].segment)
          front = std::max(front, p[j].omega);
      const double gap = p[i].omega - front;
      if (gap < 0.003)
        continue;
      gap_total += gap;
      // backwards from the landing
      std::vector<nsm::BackbonePoint> back{p[i]};
      if (i + 1 < p.size() && p[i + 1].segment == p[i].segment)
        back.insert(back.begin(), p[i + 1]);
      double step = 1e-3, reached = p[i].omega;
      int    points = 0;
      double emin = 1e300, emax = 0;
      while (step >= 1e-6 && reached > front)
        {
          const auto  &cur = back.back();
          const double omega = std::max(front, cur.omega - step);
          std::vector<double> guess = cur.x;
          if (back.size() > 1)
            {
              const auto  &prev = back[back.size() - 2];
              const double r    = (omega - cur.omega) / (cur.omega - prev.omega);
              for (std::size_t k = 0; k < guess.size(); ++k)
                guess[k] += r * (cur.x[k] - prev.x[k]);
            }
          const nsm::NewtonResult res = newton.solve(omega, guess);
          nsm::BackbonePoint      pt{cur.segment, omega, {}, res.iterations, res.residual, res.x};
          if (res.converged)
            {
              model.hb.set_omega(omega);
              pt.measures = model.hb.measure(res.x);
            }
          if (res.converged && pt.measures.contact_fraction > 0 && nsm::stays_on_branch(cur, pt, scene.continuation))
            {
              back.push_back(pt);
              reached = omega;
              ++points;
              emin = std::min(emin, pt.measures.energy), emax = std::max(emax, pt.measures.energy);
              if (res.iterations <= 4)
                step = std::min(1.5 * step, 0.01);
            }
          else
            step /= 4;
        }
      filled_total += p[i].omega - reached;
      std::printf("front %.5f landing %.5f gap %.4f: back to %.5f (%d points) E landing %.3e, back E %.3e..%.3e, front E %.3e\n",
                  front, p[i].omega, gap, reached, points, p[i].measures.energy, emin, emax, p[i - 1].measures.energy);
    }
  std::printf("gaps %.4f, filled %.4f\n", gap_total, filled_total);
}
