// A bar's model for the forced-response tests: its scene, FE model and modal
// receptance over a band.
#pragma once

#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/receptance.h>

#include <string>

#include "scene_helpers.h"

namespace testing_helpers
{
  struct ForcedModel
  {
    ForcedModel(const std::string &section, unsigned int degree, unsigned int cells, double band)
      : scene(bar_scene(section, degree, cells))
      , bar(scene.bar)
      , discretisation(bar, scene.discretisation)
      , receptance(discretisation, {nsm::ReceptanceMethod::modal, 0}, band)
    {}
    nsm::Scene          scene;
    nsm::BarModel       bar;
    nsm::Discretisation discretisation;
    nsm::Receptance     receptance;
  };
} // namespace testing_helpers
