// The Forcing subsection: the harmonic force that drives the bar for its
// forced response, F cos(W t) at the contact end or per unit length along
// the bar, one frequency-response curve per amplitude F (continuation/forced_response.h reads it). It
// declares and parses its own entries; Scene (scene.h) composes the
// subsections.
#pragma once

#include <vector>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  /// Where the drive acts.
  enum class ForcingShape
  {
    tip,    ///< a force F cos(W t) at the contact end
    uniform ///< a force F cos(W t) per unit length along the whole bar
  };

  struct ForcingParameters
  {
    ForcingShape shape = ForcingShape::tip;
    /// Force levels F, one curve each; empty: no frequency-response curve.
    std::vector<double> amplitudes;
    /// Drive frequencies W, one curve in F each over [0, amplitude_max];
    /// empty: none.
    std::vector<double> omegas;
    /// The F-curves' largest F; 0: the largest of amplitudes.
    double amplitude_max = 0;
    /// Every n-th point of each curve integrated in time (0: none).
    unsigned int verify_every = 0;
    /// Periods integrated from each such point; 0: to steady state
    /// (verification/forced_time_verification.h, steady_state_periods).
    unsigned int verify_periods = 0;
    /// Floquet multipliers at every point verified (compliant wall only;
    /// verification/forced_floquet.h).
    bool floquet = false;
    /// The most periods a verification integrates, given or to steady state.
    static constexpr unsigned int max_verify_periods = 100000;

    bool enabled() const { return !amplitudes.empty() || !omegas.empty(); }

    /// The F-curves' range's end: Amplitude max, or the largest amplitude.
    double force_range() const;

    /// The longest list of Amplitudes, and of Omegas: each value is a curve
    /// of up to Max steps points, and a study of the damping needs a handful.
    static constexpr unsigned int max_amplitudes = 100;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace nsm
