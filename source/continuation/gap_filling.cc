#include <nsm/base/interruption.h>
#include <nsm/continuation/gap_filling.h>
#include <nsm/continuation/main_branch.h>
#include <nsm/continuation/sequential_steps.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace nsm
{
  namespace
  {
    /// From `first` to `second` in the direction of continuation.
    using Gap = std::pair<double, double>;

    /// The points in the range, labelled as they would be written.
    std::vector<BackbonePoint> labelled_in_range(BranchContext &context, const Backbone &backbone)
    {
      std::vector<BackbonePoint> points;
      for (const BackbonePoint &p : backbone.points)
        if (context.in_range(p.omega))
          points.push_back(p);
      label_branches(context.hb, context.scene, points);
      return points;
    }

    /// The gaps wider than `width` between main points, in the direction of
    /// continuation; the last main point's distance to the range's end too
    /// if the branch reached it.
    std::vector<Gap> wide_gaps(const BranchContext &context, const std::vector<BackbonePoint> &points,
                               const double width, const bool reached_end)
    {
      std::vector<Gap> gaps = main_gaps(points, context.direction,
                                        reached_end ? std::optional<double>(context.far_end) : std::nullopt);
      gaps.erase(std::remove_if(gaps.begin(), gaps.end(),
                                [&](const Gap &g) { return !(std::abs(g.second - g.first) > width); }),
                 gaps.end());
      return gaps;
    }

    /// The main points of the branch with half the harmonics strictly inside
    /// the gap, nearest its start first.
    std::vector<const BackbonePoint *> guesses_in(BranchContext &context, const Gap &gap)
    {
      std::vector<const BackbonePoint *> inside;
      if (const Backbone *fewer = context.fewer_harmonics())
        for (const BackbonePoint &q : fewer->points)
          if (context.beyond(q.omega, gap.first) && context.beyond(gap.second, q.omega))
            inside.push_back(&q);
      std::sort(inside.begin(), inside.end(), [&](const BackbonePoint *a, const BackbonePoint *b) {
        if (a->branch != b->branch)
          return a->branch == Branch::main;
        return context.beyond(b->omega, a->omega);
      });
      return inside;
    }

    /// (1 + Tongue share) times the envelope at the gap's far side (the
    /// labels' rule, main_branch.h): a point above it is a tongue point,
    /// whatever the filling adds.
    double tongue_threshold(const BranchContext &context, const std::vector<BackbonePoint> &points,
                            const double far_side)
    {
      return (1 + context.scene.continuation.tongue_share) * envelope_at(points, far_side, context.direction);
    }

    /// The first solution inside the gap that the labels put on the main
    /// branch, from the guesses in turn; false if none.
    bool landing(BranchContext &context, const std::vector<BackbonePoint> &labelled, const Gap &gap,
                 const unsigned int segment, BackbonePoint &point)
    {
      for (const BackbonePoint *q : guesses_in(context, gap))
        {
          if (!context.solve(q->omega, context.guess_from_fewer_harmonics(*q), segment, point,
                             BranchContext::Newton::both))
            continue;
          label_point(context.hb, context.scene, labelled, point);
          if (point.branch == Branch::main)
            return true;
        }
      return false;
    }

    /// The landing becomes the first point of a new segment, traced until it
    /// folds, climbs above the tongue threshold or reaches the gap's far side.
    bool fill(BranchContext &context, Backbone &backbone, const std::vector<BackbonePoint> &labelled, const Gap &gap)
    {
      unsigned int segment = 0;
      for (const BackbonePoint &p : backbone.points)
        segment = std::max(segment, p.segment + 1);
      BackbonePoint point;
      if (!landing(context, labelled, gap, segment, point))
        return false;
      backbone.events.push_back(
        event_message("filled a gap of the main branch from the branch with half the harmonics", point.omega));
      backbone.points.push_back(std::move(point));
      sequential_segment(context, backbone, segment, StepLimits{gap.second, tongue_threshold(context, labelled, gap.second)});
      return true;
    }
  } // namespace

  void fill_gaps(BranchContext &context, Backbone &backbone)
  {
    const double width = context.scene.continuation.fill_gaps_wider_than;
    if (width <= 0)
      return;
    const PointStopsDeferred            whole;
    std::set<Gap>                       tried; // gaps with no landing
    for (bool filled = true; filled;)
      {
        if (context.full(backbone))
          return backbone.events.push_back(event_message(
            "Continuation/Max steps = " + std::to_string(context.scene.continuation.max_steps) +
              " points reached while filling the main branch's gaps",
            backbone.points.back().omega));
        filled                                   = false;
        const std::vector<BackbonePoint> labelled = labelled_in_range(context, backbone);
        for (const Gap &gap : wide_gaps(context, labelled, width, backbone.end == BackboneEnd::range))
          if (tried.insert(gap).second && fill(context, backbone, labelled, gap))
            {
              filled = true;
              break;
            }
      }
  }
} // namespace nsm
