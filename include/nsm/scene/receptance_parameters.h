// The Receptance subsection: how gamma(w) of the contact node is evaluated
// (model/receptance.h reads it). It declares and parses its own entries; Scene
// (scene.h) composes the subsections.
#pragma once

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  enum class ReceptanceMethod
  {
    direct,
    modal
  };

  struct ReceptanceParameters
  {
    ReceptanceMethod method = ReceptanceMethod::modal;
    unsigned int     modes  = 0; ///< modal basis size, 0 = all

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace nsm
