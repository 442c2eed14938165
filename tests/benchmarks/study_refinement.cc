// Study (not a test): the fewest DoFs with which uniform, graded and
// adaptive meshes reach a target accuracy of gamma over a band, for three
// tapers A(x) = a - x. Results are in doc/studies.md.
#include <nsm/base/threads.h>

#include <cstdio>

#include "refinement_study.h"

int main()
{
  nsm::use_one_thread(); // as nsm-bar: the same results
  std::printf("| a (A = a - x) | p | band | target | uniform DoFs | graded DoFs (mesh) | adaptive DoFs (mesh) |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const double a : {1.5, 1.1, 1.02})
    for (const unsigned int p : {1u, 2u, 4u})
      for (const double band : {2.0, 10.0})
        {
          const study::Case c{a, p, band, p == 1 ? 1e-4 : 1e-7};
          const auto u = study::uniform_or_graded(c, false);
          const auto g = study::uniform_or_graded(c, true);
          const auto d = study::adaptive(c);
          std::printf("| %g | %u | [0, %g] | %g | %u | %u (%s) | %u (%s) |\n",
                      a, p, band, c.target, u.dofs, g.dofs, g.mesh.c_str(), d.dofs, d.mesh.c_str());
        }
}
