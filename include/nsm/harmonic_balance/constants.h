// The harmonic balance's algorithm constants, each named once with its
// reason. What a user may need to tune is a scene parameter (Harmonic
// balance/...).
#pragma once

namespace nsm::harmonic_balance_constants
{
  /// The roots of q, and so the ends of the contact intervals, are found to
  /// this accuracy in tau: the Gram integrals are then exact to far below any
  /// Newton tolerance. Roots closer than this are one root.
  constexpr double root_tolerance = 1e-13;
  /// Safeguarded Newton on a root's bracket halves it at worst: 60 steps take
  /// any bracket of the period below root_tolerance.
  constexpr int root_iterations = 60;
  /// Step of the central difference that gives q'' where an extremum of q is
  /// located between samples: q' is smooth, and the slope only guides Newton.
  constexpr double extremum_slope_step = 1e-6;
  /// The exact rule samples q only to bracket its roots: this many points per
  /// period of the highest harmonic (plus the extremum checks between them).
  constexpr unsigned int bracketing_samples_per_harmonic = 8;
  /// Exactly on a pole of the receptance, theta is continuous: a frequency
  /// this much (relative) off the pole gives theta to that accuracy.
  constexpr double pole_offset = 1e-13;
  /// Newton on the exact rule converges quadratically once it converges at
  /// all: a residual that has not halved (stagnation_ratio) in
  /// stagnation_steps steps in a row, or has grown beyond divergence_limit,
  /// will not converge, and costs most of the time at folds.
  constexpr int    stagnation_steps = 6;
  constexpr double stagnation_ratio = 0.5;
  constexpr double divergence_limit = 1e8;
} // namespace nsm::harmonic_balance_constants
