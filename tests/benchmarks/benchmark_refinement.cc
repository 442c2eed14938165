// Benchmark (not a test): the time to refine a backbone point in time
// (Output/Refine in time: shooting on the exact modal flow, with the Floquet
// multipliers) on the seed bar at M = 40, FE_Q(10) x 7 and x 20, from every
// 10th main point between grazing and 2.2. Each point is refined `repeats`
// times; the table gives min / median / max of its time, for the points
// whose orbit was found and for those where shooting gave up, apart.
#include <nsm/base/threads.h>
#include <nsm/verification/orbit_refinement.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "hb_model.h"

namespace
{
  constexpr unsigned int repeats = 3;
  constexpr unsigned int every   = 10;

  struct Times
  {
    std::vector<double> seconds;
    unsigned int        points = 0;

    void add(const double t) { seconds.push_back(t); }
    void print(const char *what) const
    {
      if (seconds.empty())
        return void(std::printf("    %s: none\n", what));
      std::vector<double> s = seconds;
      std::sort(s.begin(), s.end());
      std::printf("    %s: %u points, per point min %.3f s, median %.3f s, max %.3f s\n", what, points, s.front(),
                  s[s.size() / 2], s.back());
    }
  };

  void run(const unsigned int cells)
  {
    nsm::Scene scene = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
    scene.discretisation.cells = cells;
    testing_helpers::HbModel model(scene);
    const nsm::Backbone      backbone = model.backbone();
    Times                    found, failed;
    unsigned int             main = 0;
    for (const nsm::BackbonePoint &p : backbone.points)
      if (p.branch == nsm::Branch::main && main++ % every == 0)
        {
          std::vector<double> times;
          bool                converged = false;
          for (unsigned int r = 0; r < repeats; ++r)
            {
              // As a run refines it: its HB field first, then the shooting.
              const auto               start = std::chrono::steady_clock::now();
              const nsm::PeriodicField field(model.hb, model.discretisation, p);
              const nsm::PeriodicOrbit orbit =
                nsm::refine_point(field, model.discretisation, model.hb.law(), scene.output, {});
              times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
              converged = orbit.converged;
            }
          std::sort(times.begin(), times.end());
          Times &t = converged ? found : failed;
          ++t.points;
          for (const double s : times)
            t.add(s);
        }
    std::printf("FE_Q(10) x %u (%u DoFs), M = 40, every %u-th main point, %u repeats each:\n", cells,
                model.discretisation.n_dofs(), every, repeats);
    found.print("orbit found");
    failed.print("shooting gave up");
  }
} // namespace

int main()
{
  nsm::use_one_thread();
  for (const unsigned int cells : {7u, 20u})
    run(cells);
}
