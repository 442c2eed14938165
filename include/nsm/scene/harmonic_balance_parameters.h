// The Harmonic balance subsection: the harmonics, the basis, the integration
// and the Newton settings (harmonic_balance/ reads it). It declares and parses
// its own entries; Scene (scene.h) composes the subsections.
#pragma once

#include <string>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  enum class HarmonicBasis
  {
    cosine,
    full
  };

  enum class Integration
  {
    sampled,
    exact
  };

  struct HarmonicBalanceParameters
  {
    unsigned int  harmonics      = 40;
    unsigned int  time_samples   = 0; ///< 0: chosen from the harmonics
    HarmonicBasis basis          = HarmonicBasis::cosine;
    Integration   integration    = Integration::exact;
    double        tolerance      = 1e-10;
    unsigned int  max_iterations = 0; ///< 0: chosen from the harmonics (iterations())
    std::string   line_search    = "Full Step";

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
    /// Newton iterations per solve: Max iterations, or where it is 0,
    /// max(12, M / 16).
    unsigned int iterations() const;
    /// Time samples of the sampled rule: Time samples, or where it is 0,
    /// the smallest power of 2 not below 16 M.
    unsigned int samples() const;
  };
} // namespace nsm
