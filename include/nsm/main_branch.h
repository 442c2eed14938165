// Main branch or tongue, for every point. On the main branch the energy per
// harmonic varies smoothly with k; near W = w_j / k harmonic k drives mode j
// near its resonance and stands out of that envelope. A point where one
// harmonic stands out by more than Tongue share of the energy is labelled a
// tongue point of that resonance; every other point is on the main branch.
#pragma once

#include <nsm/continuation.h>

namespace nsm
{
  /// How far harmonic k stands above the envelope of its neighbours (the
  /// geometric mean of harmonics k - 2 and k + 2, or harmonic k - 2 alone at
  /// the top), as a share of the total energy; 0 for k < 3.
  double harmonic_excess(const std::vector<double> &harmonic_energies, unsigned int k);

  /// The harmonic k >= 3 that stands out most, and its excess.
  struct SpectralExcess
  {
    unsigned int harmonic;
    double       share;
  };

  SpectralExcess spectral_excess(const std::vector<double> &harmonic_energies);

  /// The resonance w_j / k of harmonic k at Omega: j the clamped-free mode
  /// whose frequency is nearest to k Omega.
  InternalResonance resonance_of(const Receptance &receptance, unsigned int k, double omega);

  /// Sets the point's branch and resonance from its spectrum at its Omega.
  void classify(HarmonicBalance &hb, double tongue_share, BackbonePoint &point);

  /// The tongues of a labelled backbone: runs of tongue points of one
  /// resonance, with the Omega of the main points at their feet.
  std::vector<Tongue> collect_tongues(const std::vector<BackbonePoint> &points);
} // namespace nsm
