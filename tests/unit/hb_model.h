// A complete HB model (bar, mesh, receptance, harmonic balance) for tests.
#pragma once

#include <nsm/model/bar_model.h>
#include <nsm/continuation/branch_context.h>
#include <nsm/continuation/continuation.h>
#include <nsm/model/discretisation.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/model/receptance.h>
#include <nsm/model/spectrum.h>

#include <memory>
#include <optional>
#include <utility>

#include "scene_helpers.h"

namespace testing_helpers
{
  /// The uniform bar (A = 1) or the seed bar (A = 1.5 - x), resolved far
  /// beyond the HB truncation (FE_Q(10), 10 cells: gamma exact to ~1e-10 up
  /// to kW = 80), with the modal receptance. The continuation alone: the
  /// gap search (on by default) is set where it is tested (test_gap_filling,
  /// scene.main_branch), so that a trace's last point is where it ended.
  inline nsm::Scene hb_scene(const std::string &section, unsigned int harmonics)
  {
    nsm::Scene scene = bar_scene(section, 10, 10);
    scene.receptance.method          = nsm::ReceptanceMethod::modal;
    scene.harmonic_balance.harmonics = harmonics;
    scene.continuation.fill_gaps_wider_than = 0;
    return scene;
  }

  /// w1 of the seed bar (method.md), to 6 digits.
  constexpr double w1_seed = 1.919137;

  /// The seed bar's HB scene (M = 40) with a force sign and an Omega range;
  /// Energy max 1e-3.
  inline nsm::Scene seed_scene(nsm::ForceSign sign, double omega_min, double omega_max)
  {
    nsm::Scene scene = hb_scene("1.5 - x", 40);
    scene.contact.sign            = sign;
    scene.continuation.omega_min  = omega_min;
    scene.continuation.omega_max  = omega_max;
    scene.continuation.energy_max = 1e-3;
    return scene;
  }

  /// The seed bar (to Omega 2.2) on FE_Q(10) x `cells` with the periodic
  /// orbits' model (Contact mass = redistributed), the direct receptance and
  /// M harmonics: harmonic balance and shooting on one model.
  inline nsm::Scene orbit_model_scene(unsigned int cells, unsigned int harmonics)
  {
    nsm::Scene scene                  = seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
    scene.discretisation.cells        = cells;
    scene.discretisation.contact_mass = nsm::ContactMass::redistributed;
    scene.receptance.method           = nsm::ReceptanceMethod::direct;
    scene.harmonic_balance.harmonics  = harmonics;
    return scene;
  }

  struct HbModel
  {
    explicit HbModel(const nsm::Scene &s)
      : scene(s)
      , branch(scene)
      , bar(scene.bar)
      , discretisation(bar, scene.discretisation)
      , receptance(discretisation, scene.receptance,
                   scene.harmonic_balance.harmonics * scene.continuation.omega_max)
      , hb(scene.harmonic_balance, scene.contact, receptance)
      , resonances(nsm::internal_resonances(receptance, branch))
    {}

    nsm::Backbone backbone() { return nsm::compute_backbone(hb, branch, resonances); }

    /// w_j^2 (1-based mode j) and the energy of that linear mode with u(L) =
    /// g0, w_j^2 g0^2 / (2 phi_j(L)^2): the motion at grazing, whatever the
    /// contact law and its sign.
    std::pair<double, double> grazing(unsigned int mode) const
    {
      const auto   modes = nsm::compute_spectrum(discretisation, nsm::EndCondition::clamped_free, mode, true);
      const double l = modes.eigenvalues[mode - 1], g0 = scene.contact.gap;
      return {l, l * g0 * g0 / (2 * modes.contact_residues[mode - 1])};
    }

    nsm::Scene                          scene;
    nsm::BranchParameters               branch; ///< the continuation's part of `scene`
    nsm::BarModel                       bar;
    nsm::Discretisation                 discretisation;
    nsm::Receptance                     receptance;
    nsm::HarmonicBalance                hb;
    std::vector<nsm::InternalResonance> resonances;
  };

  /// The solution of `model` at the Omega of `fewer`, a point with fewer
  /// harmonics: Newton (with a line search if full steps fail) from it, its
  /// higher harmonics zero. Following one solution from M to 2 M and on.
  inline std::optional<nsm::BackbonePoint> with_more_harmonics(HbModel &model, const nsm::BackbonePoint &fewer)
  {
    nsm::BranchContext context(model.hb, model.branch, {});
    nsm::BackbonePoint point;
    if (!context.solve(fewer.omega, context.guess_from_fewer_harmonics(fewer), 0, point,
                       nsm::BranchContext::Newton::both))
      return std::nullopt;
    return point;
  }

  /// A backbone of two written points at 1.6 and 1.7 (energy
  /// 1e-6, contact fraction 0.1), for the Result block's lines.
  inline nsm::Backbone two_point_backbone()
  {
    nsm::Backbone backbone;
    for (const double omega : {1.6, 1.7})
      {
        nsm::BackbonePoint p{};
        p.omega                     = omega;
        p.measures.energy           = 1e-6;
        p.measures.contact_fraction = 0.1;
        backbone.points.push_back(p);
      }
    return backbone;
  }
} // namespace testing_helpers
