// The Contact subsection: the gap, the wall and the contact force's sign
// convention (model/contact_law.h reads it). It declares and parses its own
// entries; Scene (scene.h) composes the subsections.
#pragma once

#include <string>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  enum class ForceSign
  {
    physical, ///< the wall pushes the bar in -x: u_N = -gamma lambda
    seed_eq5  ///< the paper's eq. (5) literally: u_N = +gamma lambda
  };

  /// What the bar's end meets beyond the gap (doc/method.md, "The wall").
  enum class Wall
  {
    rigid,    ///< Signorini: g >= 0, lambda >= 0, lambda g = 0
    compliant ///< a unilateral spring of stiffness k: lambda = k max(-g, 0)
  };

  struct ContactParameters
  {
    bool      enabled = true;
    double    gap     = 1e-3;
    double    alpha   = 1.0;
    ForceSign sign    = ForceSign::physical;
    Wall      wall    = Wall::rigid;
    double    stiffness = 100.0; ///< k of a compliant wall

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  /// The wall's name in Contact/Wall ("rigid", "compliant").
  std::string wall_name(Wall wall);
} // namespace nsm
