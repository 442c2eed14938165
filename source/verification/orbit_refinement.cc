#include <nsm/base/interruption.h>
#include <nsm/base/progress.h>
#include <nsm/verification/orbit_refinement.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// Largest |v(T/2)| / (Omega g0) of an orbit: the flow is exact, so
    /// Newton reaches 1e-12 to 1e-13 where it converges; 1e-10 leaves room
    /// for the round-off of larger meshes.
    constexpr double orbit_tolerance = 1e-10;
    /// The relative energy error up to which the summary counts HB against
    /// the orbit as close (1 %, the figure users quote for a backbone).
    constexpr double summary_energy_error = 0.01;
  } // namespace

  PeriodicOrbit refine_point(const PeriodicField &field, const Discretisation &discretisation, const ContactLaw &law,
                             const OutputParameters &output, const dealii::Vector<double> &fallback)
  {
    const OrbitSettings settings{orbit_tolerance, output.stability_margin, true};
    PeriodicOrbit orbit = find_periodic_orbit(discretisation, law, field.omega(), field.displacement(0.0), settings);
    if (!orbit.converged && fallback.size() > 0)
      orbit = find_periodic_orbit(discretisation, law, field.omega(), fallback, settings);
    return orbit;
  }

  std::vector<std::optional<PeriodicOrbit>> refine_backbone(HarmonicBalance      &hb,
                                                            const Discretisation &discretisation,
                                                            const Backbone       &backbone,
                                                            const OutputParameters  &output,
                                                            Progress             &progress,
                                                            std::vector<std::optional<PeriodicOrbit>> known)
  {
    std::vector<std::optional<PeriodicOrbit>> orbits = std::move(known);
    orbits.resize(backbone.points.size());
    dealii::Vector<double> last;
    unsigned int           main = 0;
    // A stop asked for leaves the remaining points unrefined (empty cells).
    for (std::size_t i = 0; i < orbits.size() && point_stop_signal() == 0; ++i)
      if (backbone.points[i].branch == Branch::main && main++ % output.refine_every == 0)
        {
          const bool kept = orbits[i].has_value();
          if (!kept)
            {
              const PeriodicField field(hb, discretisation, backbone.points[i]);
              orbits[i] = refine_point(field, discretisation, hb.law(), output, last);
            }
          if (orbits[i]->converged)
            last = orbits[i]->displacement;
          if (!kept)
            progress.update(
              [&] { return "point " + std::to_string(i + 1) + " of " + std::to_string(orbits.size()); });
        }
    return orbits;
  }

  double hb_energy_error(const BackbonePoint &point, const PeriodicOrbit &orbit)
  {
    return point.measures.energy / orbit.energy - 1;
  }

  std::string refinement_summary(const Backbone &backbone, const std::vector<std::optional<PeriodicOrbit>> &orbits,
                                 const OutputParameters &output)
  {
    unsigned int        shot = 0, stable = 0;
    std::vector<double> errors;
    for (std::size_t i = 0; i < orbits.size(); ++i)
      if (orbits[i])
        {
          ++shot;
          if (!orbits[i]->converged)
            continue;
          errors.push_back(std::abs(hb_energy_error(backbone.points[i], *orbits[i])));
          stable += orbits[i]->stable;
        }
    std::sort(errors.begin(), errors.end());
    const auto within = std::count_if(errors.begin(), errors.end(), [](double e) { return e <= summary_energy_error; });
    std::ostringstream s;
    s.precision(3);
    s << "refinement in time: " << shot << " main points shot, " << errors.size() << " orbits found ("
      << shot - errors.size() << " not found, left empty)";
    if (!errors.empty())
      s << "; HB energy error against the orbit: median " << errors[errors.size() / 2] << ", max " << errors.back()
        << ", within " << 100 * summary_energy_error << " %: " << within << " of " << errors.size() << " (" << std::lround(100.0 * within / shot)
        << " % of the main points shot); stable (|multiplier| <= 1 + "
        << output.stability_margin << "): " << stable << " of " << errors.size();
    // What an unstable orbit means (doc/method.md, "What the instability
    // belongs to"): measured on the seed bar, not re-derived per run.
    if (stable < errors.size())
      s << " (unstable as motions of this FE bar with its wall: on the seed bar the largest |multiplier| "
           "does not fall with h or p, so it is not the mesh's)";
    return s.str();
  }
} // namespace nsm
