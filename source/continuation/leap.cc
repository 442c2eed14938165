#include <nsm/continuation/constants.h>
#include <nsm/continuation/leap.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
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
    std::size_t leap_front(const BranchContext &context, const Backbone &backbone, const std::size_t first,
                           const std::optional<std::size_t> &first_fold)
    {
      const std::size_t last  = first_fold.value_or(backbone.points.size() - 1);
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
      /// One leap from the front of the segment that ended: its guesses in
    /// turn, each step a method of its own (leap.h says in which order).
    class Leap
    {
    public:
      Leap(BranchContext &context, Backbone &backbone, const unsigned int segment,
           const std::optional<std::size_t> &first_fold)
        : context_(context)
        , backbone_(backbone)
        , c_(context.params.continuation)
        , segment_(segment)
        , first_(last_segment_start(backbone))
        , front_(backbone.points[leap_front(context, backbone, first_, first_fold)])
        , reach_(c_.search_reach * front_.omega)
        // A front high on a tongue (a previous leap may have landed there)
        // must not bar the way back down: landings may go as low as the least
        // energy written within reach behind the front, divided by Leap
        // energy ratio.
        , least_(least_energy_behind(context, backbone, front_.omega, reach_))
      {}

      /// The last resort, where the previous leap landed on a tongue that ends
      /// in a fold no guess gets past, is the last point before that leap. A
      /// branch that goes on above Energy max is not lost: fewer harmonics
      /// would not bring it back below.
      bool run()
      {
        if (from_guesses(false) || (first_ > 0 && from_guesses(true)) || from_lowest_behind() ||
            (!tally_.left_energy_range() && (from_fewer_harmonics(false) || from_fewer_harmonics(true))))
          return true;
        record_loss();
        return false;
      }

    private:
      /// Newton from a guess; the first landing within the energy bounds
      /// starts the new segment.
      bool lands(const double omega, const std::vector<double> &guess, const char *how)
      {
        BackbonePoint point;
        if (tally_.solves++ == 0 || context_.beyond(omega, tally_.furthest))
          tally_.furthest = omega;
        if (!context_.solve(omega, guess, segment_, point, BranchContext::Newton::both))
          {
            tally_.failed(context_.last_failure());
            return false;
          }
        const double e = point.measures.energy, energy = front_.measures.energy;
        if (!(e < c_.leap_energy_ratio * energy && e > least_ / c_.leap_energy_ratio))
          ++tally_.outside;
        else if (!(e <= c_.energy_max))
          ++tally_.above_energy_max;
        else
          {
            backbone_.events.push_back(event_message(how, omega));
            ++backbone_.leaps;
            backbone_.points.push_back(std::move(point));
            return true;
          }
        return false;
      }

      /// Omega at `distance` beyond the front, the range's far end at most.
      double beyond_front(const double distance) const
      {
        const double omega = front_.omega + context_.direction * distance;
        return context_.beyond(omega, context_.far_end) ? context_.far_end : omega;
      }

      /// try_at(omega) at distances growing from Initial step to the reach
      /// beyond the front (the range's far end the last); true at the first
      /// that lands.
      template <typename Try>
      bool at_growing_distances(const Try &try_at)
      {
        for (double distance = c_.initial_step; distance <= reach_ && context_.beyond(context_.far_end, front_.omega);
             distance *= continuation_constants::search_growth)
          {
            const double omega = beyond_front(distance);
            if (try_at(omega))
              return true;
            if (omega == context_.far_end)
              break;
          }
        return false;
      }

      /// Guesses at growing distances: the front, the segment's first point
      /// and the impulsive guess, or (`last_resort`) the last point before the
      /// segment alone.
      bool from_guesses(const bool last_resort)
      {
        return at_growing_distances([&](const double omega) {
          context_.hb.set_omega(omega);
          const std::vector<std::vector<double>> guesses =
            last_resort ? std::vector<std::vector<double>>{backbone_.points[first_ - 1].x} :
                          std::vector<std::vector<double>>{front_.x, backbone_.points[first_].x,
                                                           context_.hb.grazing_guess()};
          for (const std::vector<double> &guess : guesses)
            if (!guess.empty() && lands(omega, guess,
                                        last_resort ? "leapt to a new segment from the fold before the tongue" :
                                                      "leapt to a new segment"))
              return true;
          return false;
        });
      }

      /// The point of least energy within reach behind the front, where the
      /// branch was lowest before it climbed the tongue that ends in the
      /// fold, as the only guess at growing distances.
      bool from_lowest_behind()
      {
        const BackbonePoint *lowest = lowest_point_behind(context_, backbone_, front_.omega, reach_);
        if (!lowest)
          return false;
        const std::vector<double> guess = lowest->x; // the backbone grows when a leap lands
        return at_growing_distances([&](const double omega) {
          return lands(omega, guess, "leapt to a new segment from the lowest point before the tongue");
        });
      }

      /// The main points of the branch with half the harmonics beyond the
      /// front, within reach or (`beyond_reach`) further on, nearest first.
      std::vector<const BackbonePoint *> fewer_harmonics_near_front(const bool beyond_reach)
      {
        std::vector<const BackbonePoint *> near;
        const Backbone *fewer = c_.leap_from_fewer_harmonics ? context_.fewer_harmonics() : nullptr;
        if (!fewer)
          return near;
        for (const BackbonePoint &q : fewer->points)
          if (q.branch == Branch::main && context_.beyond(q.omega, front_.omega) &&
              (std::abs(q.omega - front_.omega) <= reach_) != beyond_reach)
            near.push_back(&q);
        std::sort(near.begin(), near.end(), [&](const BackbonePoint *a, const BackbonePoint *b) {
          return std::abs(a->omega - front_.omega) < std::abs(b->omega - front_.omega);
        });
        return near;
      }

      /// Each of those points at its own Omega, its higher harmonics zero.
      bool from_fewer_harmonics(const bool beyond_reach)
      {
        for (const BackbonePoint *q : fewer_harmonics_near_front(beyond_reach))
          {
            if (lands(q->omega, context_.guess_from_fewer_harmonics(*q),
                      beyond_reach ? "leapt beyond Search reach to a new segment from the branch with half the harmonics" :
                                     "leapt to a new segment from the branch with half the harmonics"))
              return true;
          }
        return false;
      }

      /// How the backbone ended, and what the leap's Newton solves ended in.
      void record_loss()
      {
        const bool above = tally_.left_energy_range();
        backbone_.end    = above ? BackboneEnd::energy_max : BackboneEnd::lost;
        backbone_.events.push_back(
          event_message(above ? "branch goes on only above Energy max after the fold" : "branch lost after the fold",
                        front_.omega) +
          tally_.text(least_ / c_.leap_energy_ratio, c_.leap_energy_ratio * front_.measures.energy, c_.energy_max,
                      context_.params.harmonic_balance.iterations()));
      }

      BranchContext                &context_;
      Backbone                     &backbone_;
      const ContinuationParameters    &c_;
      const unsigned int            segment_;
      const std::size_t             first_;
      const BackbonePoint           front_;
      const double                  reach_, least_;
      LeapTally                     tally_;
    };
  } // namespace

  bool leap(BranchContext &context, Backbone &backbone, const unsigned int segment,
            const std::optional<std::size_t> &first_fold)
  {
    return Leap(context, backbone, segment, first_fold).run();
  }
} // namespace nsm
