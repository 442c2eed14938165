// The Continuation subsection: the Omega range, the steps and the guards that
// keep a trace on its branch (continuation/ reads it). It declares and parses
// its own entries; Scene (scene.h) composes the subsections.
#pragma once

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  enum class ContinuationMethod
  {
    sequential,
    arclength
  };

  struct ContinuationParameters
  {
    ContinuationMethod method         = ContinuationMethod::sequential;
    unsigned int       mode           = 1;
    double             omega_min      = 0.0;
    double             omega_max      = 0.0; ///< 0: from the spectrum (automatic_range.h)
    double             energy_max     = 0.0; ///< 0: energy_max_over_grazing x E_g
    double             energy_max_over_grazing = 1000.0;
    double             initial_step   = 1e-3;
    double             min_step       = 1e-6;
    double             max_step       = 1e-2;
    unsigned int       max_steps      = 2000;
    double             grazing_offset = 1e-5;
    double             tongue_share   = 0.02;
    double             main_contact_drop = 0.1; ///< main_branch.h
    double             tongue_energy_ratio = 2.0;
    double             max_contact_change  = 0.01;
    double             max_solution_change = 0.2;
    double             leap_energy_ratio   = 4.0;
    double             search_reach        = 0.05;
    bool               leap_from_fewer_harmonics = true;
    double             fill_gaps_wider_than      = 0.02; ///< 0: no filling (gap_filling.h)

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace nsm
