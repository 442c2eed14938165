// The fewest DoFs with which uniform, graded and adaptive meshes reach a
// target accuracy of gamma over a band, for a bar A(x) = a - x, measured
// against the exact Bessel receptance. Shared by the unit test and the
// documented study.
#pragma once

#include <nsm/model/adaptive_refinement.h>
#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/receptance.h>

#include <cmath>
#include <limits>
#include <string>

#include "exact_bar.h"
#include "scene_helpers.h"

namespace study
{
  struct Case
  {
    double       taper;    ///< a in A(x) = a - x
    unsigned int degree;
    double       band_max; ///< band [0, band_max]
    double       target;   ///< relative error of gamma over the band
  };

  struct Result
  {
    unsigned int dofs = std::numeric_limits<unsigned int>::max();
    std::string  mesh;
  };

  inline std::string section(const Case &c)
  {
    return std::to_string(c.taper) + " - x";
  }

  /// max |gamma_h - gamma| / max |gamma| over the band's 16 midpoints.
  inline double band_error(const nsm::Discretisation &d, const Case &c)
  {
    const nsm::Receptance r(d, {nsm::ReceptanceMethod::direct, 0}, 0.0);
    double error = 0, scale = 0;
    for (const double w : nsm::band_frequencies(c.band_max))
      {
        const double exact = exact::tapered_receptance(w, c.taper);
        error = std::max(error, std::abs(r(w).gamma - exact));
        scale = std::max(scale, std::abs(exact));
      }
    return error / scale;
  }

  /// Smallest cell count (growing by ~10 %) reaching the target; graded
  /// meshes try a few ratios with every cell in the graded layer.
  inline Result uniform_or_graded(const Case &c, bool graded)
  {
    nsm::Scene scene = testing_helpers::bar_scene(section(c), c.degree, 1);
    const nsm::BarModel bar(scene.bar);
    for (unsigned int cells = 1; cells < 100000; cells = std::max(cells + 1, cells * 11 / 10))
      for (const double ratio : graded ? std::vector<double>{0.99, 0.97, 0.95, 0.9, 0.8, 0.7, 0.6}
                                       : std::vector<double>{1.0})
        {
          scene.discretisation.cells = cells;
          scene.discretisation.refinement =
            graded ? nsm::Refinement::graded : nsm::Refinement::none;
          scene.discretisation.graded_ratio  = ratio;
          // Every cell graded, as far as the smallest may be 1e-6 of the largest.
          scene.discretisation.graded_layers =
            std::min<unsigned int>(cells, std::log(1e-6) / std::log(ratio));
          const nsm::Discretisation d(bar, scene.discretisation);
          if (band_error(d, c) <= c.target)
            return {d.n_dofs(),
                    std::to_string(cells) + " cells" +
                      (graded ? ", ratio " + std::to_string(ratio).substr(0, 4) : "")};
        }
    return {};
  }

  /// Adaptive refinement from 2 cells, one step at a time, until the true
  /// error reaches the target.
  inline Result adaptive(const Case &c)
  {
    nsm::Scene scene = testing_helpers::bar_scene(section(c), c.degree, 2);
    scene.discretisation.adaptive_steps     = 0; // one estimate per call
    const nsm::BarModel bar(scene.bar);
    nsm::Discretisation d(bar, scene.discretisation);
    for (unsigned int step = 0; step < 60; ++step)
      {
        if (band_error(d, c) <= c.target)
          return {d.n_dofs(), std::to_string(d.n_cells()) + " cells after " +
                                std::to_string(step) + " steps"};
        scene.discretisation.adaptive_steps = 1;
        scene.discretisation.adaptive_tolerance = 1e-300;
        nsm::refine_adaptively(d, scene.discretisation, c.band_max);
      }
    return {};
  }
} // namespace study
