// The Bar subsection: the bar's length, material and cross-section A(x)
// (model/bar_model.h reads it). It declares and parses its own entries; Scene
// (scene.h) composes the subsections.
#pragma once

#include <string>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  struct BarParameters
  {
    double      length        = 1.0;
    double      young_modulus = 1.0;
    double      density       = 1.0;
    std::string cross_section = "1.5 - x";

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace nsm
