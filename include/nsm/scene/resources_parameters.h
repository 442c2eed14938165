// The Resources subsection: the memory a run may take (model/memory_estimate.h
// reads it). It declares and parses its own entries; Scene (scene.h) composes
// the subsections.
#pragma once

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  struct ResourcesParameters
  {
    double memory_limit = 0; ///< MiB; 0: the memory the machine has available

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace nsm
