// The uniform bar's exact nonsmooth mode (the tent, exact_bar.h) on an FE
// mesh, against the rigid wall at tent_gap: shared by the flow, periodic
// orbit and time-integration tests.
#pragma once

#include <nsm/model/bar_model.h>
#include <nsm/model/contact_law.h>
#include <nsm/model/discretisation.h>
#include <nsm/scene/scene.h>

#include <deal.II/lac/vector.h>

#include "exact_bar.h"
#include "scene_helpers.h"

namespace testing_helpers
{
  constexpr double tent_gap = 1e-3;

  /// The rigid wall at tent_gap.
  inline nsm::ContactLaw tent_wall() { return wall_at(tent_gap); }

  /// The uniform bar on `cells` cells of FE_Q(degree), and the exact tent of
  /// period T interpolated on it.
  struct UniformTent
  {
    UniformTent(const double period, const unsigned int degree, const unsigned int cells)
      : exact(period, tent_gap)
      , scene(bar_scene("1", degree, cells))
      , bar(scene.bar)
      , discretisation(bar, scene.discretisation)
      , tent(discretisation.n_dofs())
    {
      const double x_peak = exact.x_peak, peak = exact.peak;
      const auto   x      = discretisation.support_points();
      for (unsigned int i = 0; i < x.size(); ++i)
        tent[i] = x[i] <= x_peak ? peak * x[i] / x_peak : peak + (tent_gap - peak) * (x[i] - x_peak) / (1 - x_peak);
    }

    exact::UniformMode     exact;
    nsm::Scene             scene;
    nsm::BarModel          bar;
    nsm::Discretisation    discretisation;
    dealii::Vector<double> tent;
  };
} // namespace testing_helpers
