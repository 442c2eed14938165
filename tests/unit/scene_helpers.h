// Small builders shared by the unit tests.
#pragma once

#include <nsm/model/contact_law.h>
#include <nsm/scene/scene.h>

#include <fstream>
#include <string>

namespace testing_helpers
{
  /// The seed bar (A = 1.5 - x) or the uniform bar on a given mesh, with an
  /// Omega range to 2.2 and Energy max 1 (the scene's automatic values, 0,
  /// are set by the run from its FE model: automatic_range.h).
  inline nsm::Scene bar_scene(const std::string &section,
                              unsigned int       degree,
                              unsigned int       cells)
  {
    nsm::Scene scene;
    scene.bar.cross_section         = section;
    scene.discretisation.degree     = degree;
    scene.discretisation.cells      = cells;
    scene.continuation.omega_max    = 2.2;
    scene.continuation.energy_max   = 1.0;
    return scene;
  }

  /// The wall at `gap` (rigid unless told; a compliant one of `stiffness`),
  /// with the physical force sign.
  inline nsm::ContactLaw wall_at(const double gap, const nsm::Wall wall = nsm::Wall::rigid,
                                 const double stiffness = nsm::ContactParameters().stiffness)
  {
    nsm::ContactParameters contact;
    contact.gap       = gap;
    contact.wall      = wall;
    contact.stiffness = stiffness;
    return nsm::ContactLaw(contact);
  }

  /// Writes a scene file with the given body and returns its path.
  inline std::string write_scene(const std::string &name, const std::string &body)
  {
    const std::string path = "scene_" + name + ".prm";
    std::ofstream(path) << body;
    return path;
  }
} // namespace testing_helpers
