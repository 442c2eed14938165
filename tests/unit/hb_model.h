// A complete HB model (bar, mesh, receptance, harmonic balance) for tests.
#pragma once

#include <nsm/bar_model.h>
#include <nsm/continuation.h>
#include <nsm/discretisation.h>
#include <nsm/harmonic_balance.h>
#include <nsm/receptance.h>

#include <memory>

#include "scene_helpers.h"

namespace testing_helpers
{
  /// The uniform bar (A = 1) or the seed bar (A = 1.5 - x), resolved far
  /// beyond the HB truncation (FE_Q(10), 10 cells: gamma exact to ~1e-10 up
  /// to kW = 80), with the modal receptance.
  inline nsm::Scene hb_scene(const std::string &section, unsigned int harmonics)
  {
    nsm::Scene scene = bar_scene(section, 10, 10);
    scene.receptance.method          = nsm::ReceptanceMethod::modal;
    scene.harmonic_balance.harmonics = harmonics;
    return scene;
  }

  struct HbModel
  {
    explicit HbModel(const nsm::Scene &s)
      : scene(s)
      , bar(scene.bar)
      , discretisation(bar, scene.discretisation)
      , receptance(discretisation, scene.receptance,
                   scene.harmonic_balance.harmonics * scene.continuation.omega_max)
      , hb(scene, receptance)
      , resonances(nsm::internal_resonances(receptance, scene))
    {}

    nsm::Backbone backbone() { return nsm::compute_backbone(hb, scene, resonances); }

    nsm::Scene                          scene;
    nsm::BarModel                       bar;
    nsm::Discretisation                 discretisation;
    nsm::Receptance                     receptance;
    nsm::HarmonicBalance                hb;
    std::vector<nsm::InternalResonance> resonances;
  };
} // namespace testing_helpers
