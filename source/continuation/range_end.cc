#include <nsm/continuation/main_branch.h>
#include <nsm/continuation/range_end.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace nsm
{
  namespace
  {
    /// The segment's first point, the impulsive contact, the last point
    /// before the segment, and every earlier point within reach that the
    /// envelope of the points written so far puts on the main branch.
    std::vector<std::vector<double>> guesses_at_end(BranchContext &context, const Backbone &backbone,
                                                    const std::size_t first, const double reach)
    {
      const std::vector<BackbonePoint> &p = backbone.points;
      const std::vector<bool> above = above_envelope(p, context.direction, context.params.continuation.tongue_share);
      context.hb.set_omega(p.back().omega);
      std::vector<std::vector<double>> guesses{p[first].x, context.hb.grazing_guess()};
      if (first > 0)
        guesses.push_back(p[first - 1].x);
      for (std::size_t i = 0; i + 1 < first; ++i)
        if (!above[i] && std::abs(p[i].omega - p.back().omega) <= reach)
          guesses.push_back(p[i].x);
      return guesses;
    }

    /// The last segment climbed to the end (its last point lies more than
    /// Tongue share above `bottom`) and has less contact than the branch
    /// behind it: more than Max contact change below the most contact written
    /// within `reach`. The main branch's contact grows along it, so an end on
    /// it that climbs (every hardening run's) is not searched.
    bool climbed_with_less_contact(const BranchContext &context, const Backbone &backbone,
                                   const BackbonePoint &bottom, const double reach)
    {
      const auto          &c    = context.params.continuation;
      const BackbonePoint &last = backbone.points.back();
      if (!(last.measures.energy > (1 + c.tongue_share) * bottom.measures.energy))
        return false;
      double most = 0;
      for (const BackbonePoint &p : backbone.points)
        if (std::abs(p.omega - last.omega) <= reach)
          most = std::max(most, p.measures.contact_fraction);
      return last.measures.contact_fraction < most - c.max_contact_change;
    }
  } // namespace

  bool find_branch_below_at_end(BranchContext &context, Backbone &backbone, const unsigned int segment)
  {
    const auto         &c     = context.params.continuation;
    const BackbonePoint last  = backbone.points.back();
    const std::size_t   first = last_segment_start(backbone);
    const double        reach = c.search_reach * last.omega;
    const auto [bottom, top] = std::minmax_element(backbone.points.begin() + first, backbone.points.end(),
                                                   [](const BackbonePoint &a, const BackbonePoint &b) {
                                                     return a.measures.energy < b.measures.energy;
                                                   });
    const bool descended = top->measures.energy > (1 + c.tongue_share) * last.measures.energy;
    if (!descended && !climbed_with_less_contact(context, backbone, *bottom, reach))
      return false;
    const double least = least_energy_behind(context, backbone, last.omega, reach);

    // The lowest landing (the labels' envelope is the least energy) with at
    // least the end's contact: the main branch has the most contact at its
    // Omega, the other branches below a rising end less (doc/method.md).
    std::optional<BackbonePoint> lowest;
    for (const std::vector<double> &guess : guesses_at_end(context, backbone, first, reach))
      {
        BackbonePoint point;
        if (!guess.empty() && context.solve(last.omega, guess, segment + 1, point, BranchContext::Newton::both) &&
            (1 + c.tongue_share) * point.measures.energy < last.measures.energy &&
            point.measures.energy > least / c.leap_energy_ratio &&
            point.measures.contact_fraction >= last.measures.contact_fraction &&
            (!lowest || point.measures.energy < lowest->measures.energy))
          lowest = std::move(point);
      }
    if (!lowest)
      return false;
    backbone.events.push_back(event_message("found the branch below a tongue's flank", last.omega));
    ++backbone.leaps;
    backbone.points.push_back(std::move(*lowest));
    return true;
  }
} // namespace nsm
