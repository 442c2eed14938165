#include <nsm/continuation/backbone.h>
#include <nsm/model/contact_law.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace nsm
{
  bool in_omega_range(const ContinuationParameters &continuation, const double omega)
  {
    return omega >= continuation.omega_min && omega <= continuation.omega_max;
  }

  double branch_direction(const ContactParameters &contact)
  {
    return ContactLaw(contact).sign();
  }

  const BackbonePoint *nearest_on_side(const std::vector<BackbonePoint> &points, const double omega, const int side,
                                       const bool main_only)
  {
    const BackbonePoint *best = nullptr;
    for (const BackbonePoint &q : points)
      if ((!main_only || q.branch == Branch::main) && side * (q.omega - omega) >= 0 &&
          (!best || std::abs(q.omega - omega) < std::abs(best->omega - omega)))
        best = &q;
    return best;
  }

  const char *backbone_end_name(const BackboneEnd end)
  {
    switch (end)
      {
        case BackboneEnd::range:
          return "range";
        case BackboneEnd::max_steps:
          return "max_steps";
        case BackboneEnd::lost:
          return "lost";
        case BackboneEnd::energy_max:
          return "energy_max";
        case BackboneEnd::interrupted:
          return "interrupted";
        case BackboneEnd::refused:
          return "refused";
      }
    return "";
  }

  std::optional<double> Backbone::omega_reached(const double direction) const
  {
    if (points.empty())
      return std::nullopt;
    const auto furthest = std::max_element(points.begin(), points.end(), [&](const auto &a, const auto &b) {
      return direction * a.omega < direction * b.omega;
    });
    return furthest->omega;
  }

  std::optional<double> Backbone::traced_from() const
  {
    if (points.empty())
      return std::nullopt;
    return traced_start ? *traced_start : points.front().omega;
  }

  unsigned int Backbone::points_on(const Branch branch) const
  {
    return std::count_if(points.begin(), points.end(), [&](const BackbonePoint &p) { return p.branch == branch; });
  }

  const InternalResonance &nearest_resonance(const std::vector<InternalResonance> &resonances,
                                             const double                          omega)
  {
    return *std::min_element(resonances.begin(), resonances.end(), [&](const auto &a, const auto &b) {
      return std::abs(a.omega - omega) < std::abs(b.omega - omega);
    });
  }

  std::string range_without_points(const Backbone &backbone, const ContinuationParameters &c, const double direction)
  {
    if (!backbone.points.empty() || backbone.end == BackboneEnd::interrupted)
      return "";
    const bool   up       = direction > 0;
    const double near     = up ? c.omega_min : c.omega_max;
    const double furthest = up ? backbone.traced_span.second : backbone.traced_span.first;
    std::ostringstream s;
    s.precision(6);
    s << "parameter 'Continuation/" << (up ? "Omega min" : "Omega max") << "' = " << near << " is out of range: ";
    if (up ? furthest < near : furthest > near)
      s << "the branch from grazing ends at Omega = " << furthest << " (" << backbone_end_name(backbone.end)
        << (backbone.events.empty() ? std::string() : ": " + backbone.events.back())
        << ") before it, so no point lies in [Omega min, Omega max]; allowed " << (up ? "below " : "above ")
        << furthest;
    else
      s << "the branch passes over [Omega min, Omega max] between two points (a leap over a fold) and writes "
           "none in it; allowed a wider range";
    return s.str();
  }
} // namespace nsm
