// The bounds the subsections' entries share: every dimensional input and
// every frequency a scene names lies within them.
#pragma once

namespace nsm
{
  /// Dimensional inputs (L, E, rho, A(x), g0, alpha, k) lie in
  /// [1 / magnitude_limit, magnitude_limit]: the products and quotients the
  /// run forms of them (frequencies, energies, contact forces) then stay
  /// finite and above the underflow threshold.
  constexpr double magnitude_limit = 1e20;

  /// Frequencies (Omega, receptance and field frequencies, bands) lie in
  /// [0, frequency_limit]: w^2 times the mass matrix stays finite.
  constexpr double frequency_limit = 1e100;
} // namespace nsm
