#include <nsm/continuation/leap.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace nsm
{
  namespace
  {
    /// Where the leap starts: the point of the segment furthest along the
    /// continuation up to its first fold (the last point if none). A segment
    /// that begins on a tongue's flank can run backwards first; leaping from a
    /// point behind its own start could go round the same tongues for ever.
    std::size_t leap_front(const BranchContext &context, const Backbone &backbone, const std::size_t first)
    {
      const std::size_t last  = context.first_fold.value_or(backbone.points.size() - 1);
      std::size_t       front = last;
      for (std::size_t i = first; i < last; ++i)
        if (context.beyond(backbone.points[i].omega, backbone.points[front].omega))
          front = i;
      return front;
    }

    /// What the leap's Newton solves ended in. A lost branch says so, with
    /// the two things a user can change: the energy bounds of a landing and
    /// Max iterations (at M = 160 on the seed bar, Newton from these guesses
    /// needs more than the default 12).
    struct LeapTally
    {
      unsigned int solves = 0, outside = 0, above_energy_max = 0, at_limit = 0, stalled = 0, no_contact = 0;
      double       furthest = 0;

      /// Landings that only Energy max refused: the branch goes on above it.
      bool left_energy_range() const { return above_energy_max > 0; }

      void failed(const BranchContext::SolveFailure failure)
      {
        using F = BranchContext::SolveFailure;
        ++(failure == F::iteration_limit ? at_limit : failure == F::stalled ? stalled : no_contact);
      }

      std::string text(const double lowest, const double highest, const double energy_max,
                       const unsigned int max_iterations) const
      {
        std::ostringstream s;
        s << std::setprecision(8) << ": no landing from " << solves << " Newton solves up to Omega = " << furthest
          << std::setprecision(3);
        std::string separator = " (";
        const auto  part      = [&](const unsigned int n) -> std::ostream & {
          s << separator << n << ' ';
          separator = ", ";
          return s;
        };
        if (above_energy_max > 0)
          part(above_energy_max) << "converged above Energy max = " << energy_max << " only";
        if (outside > 0)
          part(outside) << "converged outside the landing energies " << lowest << " to " << highest;
        if (at_limit > 0)
          part(at_limit) << "stopped at Max iterations = " << max_iterations;
        if (stalled > 0)
          part(stalled) << "stalled or diverged";
        if (no_contact > 0)
          part(no_contact) << "converged to no contact";
        if (separator == ", ")
          s << ')';
        return s.str();
      }
    };
  } // namespace

  bool leap(BranchContext &context, Backbone &backbone, const unsigned int segment)
  {
    const auto         &c      = context.scene.continuation;
    const std::size_t   first  = last_segment_start(backbone);
    const BackbonePoint front  = backbone.points[leap_front(context, backbone, first)];
    const double        energy = front.measures.energy;
    const double        reach  = c.search_reach * front.omega;
    // A front high on a tongue (a previous leap may have landed there) must
    // not bar the way back down: landings may go as low as the least energy
    // written within reach behind the front, divided by Leap energy ratio.
    const double least = least_energy_behind(context, backbone, front.omega, reach);

    // Newton from a guess; the first landing within the energy bounds starts
    // the new segment.
    LeapTally  tally;
    const auto landed = [&](const double omega, const std::vector<double> &guess, const char *how) {
      BackbonePoint point;
      if (tally.solves++ == 0 || context.beyond(omega, tally.furthest))
        tally.furthest = omega;
      if (!context.solve(omega, guess, segment, point, true))
        {
          tally.failed(context.last_failure());
          return false;
        }
      const double e = point.measures.energy;
      if (!(e < c.leap_energy_ratio * energy && e > least / c.leap_energy_ratio))
        ++tally.outside;
      else if (!(e <= c.energy_max))
        ++tally.above_energy_max;
      else
        {
          backbone.events.push_back(event_message(how, omega));
          ++backbone.leaps;
          backbone.points.push_back(std::move(point));
          return true;
        }
      return false;
    };
    // Guesses at growing distances beyond the front.
    const auto land = [&](const bool last_resort) {
      for (double distance = c.initial_step;
           distance <= reach && context.beyond(context.far_end, front.omega);
           distance *= 2)
        {
          const double omega = context.beyond(front.omega + context.direction * distance, context.far_end) ?
                                 context.far_end :
                                 front.omega + context.direction * distance;
          context.hb.set_omega(omega);
          const std::vector<std::vector<double>> guesses =
            last_resort ? std::vector<std::vector<double>>{backbone.points[first - 1].x} :
                          std::vector<std::vector<double>>{front.x, backbone.points[first].x,
                                                           context.hb.grazing_guess()};
          for (const std::vector<double> &guess : guesses)
            if (!guess.empty() &&
                landed(omega, guess,
                       last_resort ? "leapt to a new segment from the fold before the tongue" :
                                     "leapt to a new segment"))
              return true;
          if (omega == context.far_end)
            break;
        }
      return false;
    };
    // The main points of the branch with half the harmonics within reach,
    // nearest first, their higher harmonics zero.
    const auto land_from_fewer_harmonics = [&]() {
      const Backbone *fewer = context.fewer_harmonics();
      if (!fewer)
        return false;
      std::vector<const BackbonePoint *> near;
      for (const BackbonePoint &q : fewer->points)
        if (q.branch == Branch::main && context.beyond(q.omega, front.omega) &&
            std::abs(q.omega - front.omega) <= reach)
          near.push_back(&q);
      std::sort(near.begin(), near.end(), [&](const BackbonePoint *a, const BackbonePoint *b) {
        return std::abs(a->omega - front.omega) < std::abs(b->omega - front.omega);
      });
      for (const BackbonePoint *q : near)
        {
          std::vector<double> guess(context.hb.n_unknowns(), 0.0);
          std::copy(q->x.begin(), q->x.end(), guess.begin());
          if (landed(q->omega, guess, "leapt to a new segment from the branch with half the harmonics"))
            return true;
        }
      return false;
    };
    // The last resort, where the previous leap landed on a tongue that ends in
    // a fold no guess gets past: the last point before that leap, before the
    // tongue. A branch that goes on above Energy max is not lost: fewer
    // harmonics would not bring it back below.
    if (land(false) || (first > 0 && land(true)) || (!tally.left_energy_range() && land_from_fewer_harmonics()))
      return true;
    backbone.end = tally.left_energy_range() ? BackboneEnd::energy_max : BackboneEnd::lost;
    backbone.events.push_back(
      event_message(tally.left_energy_range() ? "branch goes on only above Energy max after the fold" :
                                                "branch lost after the fold",
                    front.omega) +
      tally.text(least / c.leap_energy_ratio, c.leap_energy_ratio * energy, c.energy_max,
                 context.scene.harmonic_balance.max_iterations));
    return false;
  }
} // namespace nsm
