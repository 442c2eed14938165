#include <nsm/continuation/constants.h>
#include <nsm/continuation/sequential_steps.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace nsm
{
  bool stays_on_branch(const BackbonePoint &from, const BackbonePoint &to, const ContinuationParameters &c)
  {
    if (!(std::abs(to.measures.contact_fraction - from.measures.contact_fraction) <= c.max_contact_change))
      return false;
    double change = 0, size = 0;
    for (std::size_t i = 0; i < from.x.size(); ++i)
      {
        change += (to.x[i] - from.x[i]) * (to.x[i] - from.x[i]);
        size += from.x[i] * from.x[i];
      }
    return change <= c.max_solution_change * c.max_solution_change * size;
  }

  namespace
  {
    /// The secant through the segment's last two points, extended to omega;
    /// the last point alone at the segment's start.
    std::vector<double> secant_guess(const Backbone &backbone, const std::size_t first, const double omega)
    {
      const BackbonePoint &current = backbone.points.back();
      std::vector<double>  guess   = current.x;
      if (backbone.points.size() - 1 > first)
        {
          const BackbonePoint &previous = backbone.points[backbone.points.size() - 2];
          const double ratio = (omega - current.omega) / (current.omega - previous.omega);
          for (unsigned int i = 0; i < guess.size(); ++i)
            guess[i] += ratio * (current.x[i] - previous.x[i]);
        }
      return guess;
    }

    /// sequential_segment, with or without the limits of a filling segment.
    SegmentEnd steps(BranchContext &context, Backbone &backbone, const unsigned int segment,
                     std::optional<double> &carried, const bool hand_over, const std::optional<StepLimits> &limits)
    {
      const auto &c    = context.params.continuation;
      double step = std::exchange(carried, std::nullopt).value_or(std::min(c.initial_step, context.max_step()));
      const std::size_t first = last_segment_start(backbone);
      while (!context.full(backbone))
        {
          const BackbonePoint &current = backbone.points.back();
          if (current.omega == context.far_end)
            return SegmentEnd::range;
          const bool before = context.beyond(context.near_end, current.omega);
          if (!before && hand_over)
            return SegmentEnd::approach;
          double omega = current.omega + context.direction * step;
          if (before && context.beyond(omega, context.near_end))
            omega = context.near_end;
          if (context.beyond(omega, context.far_end))
            omega = context.far_end;
          if (limits && !context.beyond(limits->join_at, omega))
            return SegmentEnd::joined;
          BackbonePoint point;
          if (context.solve(omega, secant_guess(backbone, first, omega), segment, point) &&
              stays_on_branch(current, point, c))
            {
              if (point.measures.energy > c.energy_max || (limits && point.measures.energy > limits->tongue_above))
                return SegmentEnd::tongue;
              if (point.newton_iterations <= continuation_constants::easy_iterations)
                step = std::min(continuation_constants::step_growth * step, context.max_step());
              backbone.points.push_back(std::move(point));
              continue;
            }
          step /= continuation_constants::step_shrink;
          if (step < c.min_step)
            return SegmentEnd::fold;
        }
      carried = step;
      return context.full_end();
    }
  } // namespace

  SegmentEnd sequential_segment(BranchContext &context, Backbone &backbone, const unsigned int segment,
                                std::optional<double> &carried, const bool hand_over)
  {
    return steps(context, backbone, segment, carried, hand_over, std::nullopt);
  }

  SegmentEnd sequential_segment(BranchContext &context, Backbone &backbone, const unsigned int segment)
  {
    std::optional<double> carried;
    return steps(context, backbone, segment, carried, false, std::nullopt);
  }

  SegmentEnd sequential_segment(BranchContext &context, Backbone &backbone, const unsigned int segment,
                                const StepLimits &limits)
  {
    std::optional<double> carried;
    return steps(context, backbone, segment, carried, false, limits);
  }
} // namespace nsm
