#include <nsm/main_branch.h>

#include <cmath>
#include <numeric>

namespace nsm
{
  namespace
  {
    /// harmonic_excess() with the total energy given.
    double excess(const std::vector<double> &energies, const unsigned int k, const double total)
    {
      // k = 0 is the static part, k = 1 the fundamental, and k = 2 has no
      // oscillating neighbour below it.
      if (k < 3 || k >= energies.size())
        return 0;
      // The geometric mean of the same-parity neighbours follows a smooth
      // decay, and the odd-even alternation of symmetric motions.
      const bool   above    = k + 2 < energies.size();
      const double envelope = above ? std::sqrt(energies[k - 2] * energies[k + 2]) : energies[k - 2];
      return (energies[k] - envelope) / total;
    }

    double total_of(const std::vector<double> &energies)
    {
      return std::accumulate(energies.begin(), energies.end(), 0.0);
    }
  } // namespace

  double harmonic_excess(const std::vector<double> &energies, const unsigned int k)
  {
    return excess(energies, k, total_of(energies));
  }

  SpectralExcess spectral_excess(const std::vector<double> &energies)
  {
    const double   total = total_of(energies);
    SpectralExcess worst{0, 0.0};
    for (unsigned int k = 3; k < energies.size(); ++k)
      if (const double share = excess(energies, k, total); share > worst.share)
        worst = {k, share};
    return worst;
  }

  InternalResonance resonance_of(const Receptance &receptance, const unsigned int k, const double omega)
  {
    const std::vector<double> &poles = receptance.poles();
    unsigned int               j     = 0;
    for (unsigned int i = 1; i < poles.size(); ++i)
      if (std::abs(std::sqrt(poles[i]) - k * omega) < std::abs(std::sqrt(poles[j]) - k * omega))
        j = i;
    return poles.empty() ? InternalResonance{0, 0, k} :
                           InternalResonance{std::sqrt(poles[j]) / k, j + 1, k};
  }

  void classify(HarmonicBalance &hb, const double tongue_share, BackbonePoint &point)
  {
    hb.set_omega(point.omega);
    const SpectralExcess excess = spectral_excess(hb.harmonic_energies(point.x));
    const bool           tongue = excess.share > tongue_share;
    point.branch                = tongue ? Branch::tongue : Branch::main;
    point.resonance             = tongue ? resonance_of(hb.receptance(), excess.harmonic, point.omega) :
                                           InternalResonance{0, 0, 0};
  }

  std::vector<Tongue> collect_tongues(const std::vector<BackbonePoint> &points)
  {
    std::vector<Tongue> tongues;
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        const BackbonePoint &p = points[i];
        if (p.branch != Branch::tongue)
          continue;
        const BackbonePoint *before = i > 0 ? &points[i - 1] : nullptr;
        const bool continues = before && before->branch == Branch::tongue &&
                               before->resonance.mode == p.resonance.mode &&
                               before->resonance.harmonic == p.resonance.harmonic;
        if (!continues)
          {
            const double foot = before ? before->omega : p.omega;
            tongues.push_back({p.resonance, foot, foot, 0, 0});
          }
        Tongue &t    = tongues.back();
        t.max_energy = std::max(t.max_energy, p.measures.energy);
        ++t.points;
        t.foot_end = i + 1 < points.size() ? points[i + 1].omega : p.omega;
      }
    return tongues;
  }
} // namespace nsm
