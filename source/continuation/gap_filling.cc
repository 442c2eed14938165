#include <nsm/base/interruption.h>
#include <nsm/continuation/constants.h>
#include <nsm/continuation/gap_filling.h>
#include <nsm/continuation/main_branch.h>
#include <nsm/continuation/search_memory.h>
#include <nsm/continuation/sequential_steps.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
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
      label_branches(context.hb, context.params, points);
      return points;
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
        if ((a->branch == Branch::main) != (b->branch == Branch::main))
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
      return (1 + context.params.continuation.tongue_share) * envelope_at(points, far_side, context.direction,
                                                                          accumulation_passed(context.params));
    }

    /// The main points that predict the mode in a gap: the one at its start,
    /// one about trend_base x Omega behind it, and the first at or beyond
    /// its far side (each null if none).
    struct Trend
    {
      const BackbonePoint *start = nullptr, *base = nullptr, *far = nullptr;
    };

    Trend trend_into(const BranchContext &context, const std::vector<BackbonePoint> &labelled, const Gap &gap)
    {
      Trend        t;
      const double back = gap.first - context.direction * continuation_constants::trend_base * gap.first;
      for (const BackbonePoint &p : labelled)
        {
          if (p.branch != Branch::main)
            continue;
          if (context.beyond(p.omega, gap.first))
            {
              if (!context.beyond(gap.second, p.omega) && (!t.far || context.beyond(t.far->omega, p.omega)))
                t.far = &p;
              continue;
            }
          if (!t.start || context.beyond(p.omega, t.start->omega))
            t.start = &p;
          if (p.omega != gap.first && (!t.base || std::abs(p.omega - back) < std::abs(t.base->omega - back)))
            t.base = &p;
        }
      return t;
    }

    /// The guesses at omega, each drawn between two main points: the
    /// straight line to the far side's main point; the secant along the
    /// trend and the start's own unknowns where they predict (`near`: within
    /// the trend's own span, trend_base x Omega, beyond the gap's start, or
    /// anywhere in a gap up to the range's end, which has no far side).
    std::vector<std::pair<const BackbonePoint *, const BackbonePoint *>> predicted_guesses(const Trend &t,
                                                                                           const bool near)
    {
      std::vector<std::pair<const BackbonePoint *, const BackbonePoint *>> guesses;
      if (t.base && near)
        guesses.emplace_back(t.base, t.start);
      if (t.far)
        guesses.emplace_back(t.start, t.far);
      if (near)
        guesses.emplace_back(t.start, t.start);
      return guesses;
    }

    /// Newton from the mode predicted along its trend (predicted_guesses) at
    /// Omegas spaced a gap_starts_per_width-th of Fill gaps wider than across
    /// the gap, nearest its start first, each start solved once in the run
    /// (`memory`); the first solution the labels put on the main branch;
    /// what the others were is counted in `search`.
    bool predicted_landing(BranchContext &context, const std::vector<BackbonePoint> &labelled, const Gap &gap,
                           const Trend &trend, const unsigned int segment, BackbonePoint &point, GapSearch &search,
                           SearchMemory &memory)
    {
      const double spacing =
        context.params.continuation.fill_gaps_wider_than / continuation_constants::gap_starts_per_width;
      const double reach = gap.first + context.direction * continuation_constants::trend_base * gap.first;
      for (double omega = gap.first + context.direction * spacing; context.beyond(gap.second, omega);
           omega += context.direction * spacing)
        for (const auto &[a, b] : predicted_guesses(trend, !trend.far || !context.beyond(omega, reach)))
          {
            ++search.starts;
            const std::optional<BackbonePoint> &solution =
              memory.solve(context, omega, {omega, a->omega, b->omega}, interpolated_guess(*a, *b, omega));
            if (!solution)
              continue;
            point = *solution;
            point.segment = segment;
            if (!(point.measures.energy <= context.params.continuation.energy_max))
              {
                ++search.above_energy_max;
                continue;
              }
            label_point(context.hb, context.params, labelled, point);
            if (point.branch == Branch::main)
              return true;
            if (point.branch == Branch::other)
              {
                ++search.other_family;
                if (!moves_at_omega(point))
                  ++search.other_harmonic;
                else
                  search.most_contact = std::max(search.most_contact, point.measures.contact_fraction);
              }
            else
              ++search.tongue;
          }
      return false;
    }

    /// The first solution inside the gap that the labels put on the main
    /// branch, from the guesses of the branch with half the harmonics in turn.
    bool landing_from_fewer_harmonics(BranchContext &context, const std::vector<BackbonePoint> &labelled,
                                      const Gap &gap, const unsigned int segment, BackbonePoint &point,
                                      SearchMemory &memory)
    {
      for (const BackbonePoint *q : guesses_in(context, gap))
        {
          const std::optional<BackbonePoint> &solution =
            memory.solve(context, q->omega, {q->omega, q->omega, q->omega}, context.guess_from_fewer_harmonics(*q));
          if (!solution || !(solution->measures.energy <= context.params.continuation.energy_max))
            continue;
          point         = *solution;
          point.segment = segment;
          label_point(context.hb, context.params, labelled, point);
          if (point.branch == Branch::main)
            return true;
        }
      return false;
    }

    enum class Landing
    {
      none,
      predicted,
      fewer_harmonics
    };

    /// Which guesses a search tries first.
    enum class Prediction
    {
      trend_first,          ///< the predicted mode, then the branch with half the harmonics
      fewer_harmonics_first ///< the other way round
    };

    /// A main solution in the gap from the mode predicted along its trend and
    /// from the branch with half the harmonics, in the order `from` gives.
    Landing land(BranchContext &context, const std::vector<BackbonePoint> &labelled, const Gap &gap,
                 const Trend &trend, const unsigned int segment, BackbonePoint &point, GapSearch &search,
                 SearchMemory &memory, const Prediction from)
    {
      const auto from_trend = [&] {
        return trend.start && predicted_landing(context, labelled, gap, trend, segment, point, search, memory);
      };
      const auto from_fewer = [&] {
        return landing_from_fewer_harmonics(context, labelled, gap, segment, point, memory);
      };
      if (from == Prediction::fewer_harmonics_first)
        return from_fewer() ? Landing::fewer_harmonics : from_trend() ? Landing::predicted : Landing::none;
      return from_trend() ? Landing::predicted : from_fewer() ? Landing::fewer_harmonics : Landing::none;
    }

    /// Sequential steps from the far side's main point back towards the
    /// gap's start (the secant predictor and the jump guard of a segment),
    /// until the branch folds, reaches the start, climbs above
    /// `tongue_above` or Max steps would be passed; the points traced, in
    /// the direction of continuation, become a new segment. True if any.
    bool traced_back(BranchContext &context, Backbone &backbone, const Trend &trend, const Gap &gap,
                     const unsigned int segment, const double tongue_above)
    {
      const auto                &c = context.params.continuation;
      std::vector<BackbonePoint> back{*trend.far};
      double                     step = c.initial_step;
      while (step >= c.min_step && backbone.points.size() + back.size() <= c.max_steps)
        {
          const BackbonePoint &current = back.back();
          const double         omega   = current.omega - context.direction * step;
          if (!context.beyond(omega, gap.first))
            break;
          const std::vector<double> guess =
            back.size() > 1 ? interpolated_guess(back[back.size() - 2], current, omega) : current.x;
          BackbonePoint point;
          if (!context.solve(omega, guess, segment, point) || !stays_on_branch(current, point, c))
            {
              step /= continuation_constants::step_shrink;
              continue;
            }
          if (point.measures.energy > tongue_above)
            break;
          if (point.newton_iterations <= continuation_constants::easy_iterations)
            step = std::min(continuation_constants::step_growth * step, context.max_step());
          back.push_back(std::move(point));
        }
      if (back.size() < 2)
        return false;
      backbone.events.push_back(event_message("traced into a gap of the main branch back from its far side",
                                              back.back().omega));
      std::move(back.rbegin(), back.rend() - 1, std::back_inserter(backbone.points));
      return true;
    }

    /// A landing from the predicted mode or from the branch with half the
    /// harmonics becomes the first point of a new segment, traced until it
    /// folds, climbs above the tongue threshold or reaches the gap's far
    /// side; without one, the branch is traced back from the far side. A gap
    /// left is recorded with its search.
    bool fill(BranchContext &context, Backbone &backbone, const std::vector<BackbonePoint> &labelled, const Gap &gap,
              SearchMemory &memory, const Prediction from)
    {
      unsigned int segment = 0;
      for (const BackbonePoint &p : backbone.points)
        segment = std::max(segment, p.segment + 1);
      const Trend  trend     = trend_into(context, labelled, gap);
      // Points above it are tongue points, or above Energy max not kept.
      const double threshold =
        std::min(tongue_threshold(context, labelled, gap.second), context.params.continuation.energy_max);
      GapSearch    search;
      search.from = gap.first;
      search.to   = gap.second;
      search.contact_before =
        most_contact_before(labelled, gap.second, context.direction, context.params.continuation.tongue_share,
                            accumulation_passed(context.params));
      BackbonePoint     point;
      const std::size_t before  = backbone.points.size();
      const Landing     landing = land(context, labelled, gap, trend, segment, point, search, memory, from);
      if (landing != Landing::none)
        {
          backbone.events.push_back(event_message(landing == Landing::predicted ?
                                                    "traced into a gap of the main branch from the predicted mode" :
                                                    "traced into a gap of the main branch from the branch with half the harmonics",
                                                  point.omega));
          search.landed = point.omega;
          backbone.points.push_back(std::move(point));
          sequential_segment(context, backbone, segment, StepLimits{gap.second, threshold});
        }
      else if (trend.far && traced_back(context, backbone, trend, gap, segment, threshold))
        search.landed = backbone.points[before].omega;
      backbone.gap_searches.push_back(search);
      return search.landed.has_value();
    }
  } // namespace

  void fill_gaps(BranchContext &context, Backbone &backbone)
  {
    const double width = context.params.continuation.fill_gaps_wider_than;
    if (width <= 0)
      return;
    const PointStopsDeferred            whole;
    std::vector<Gap>                    tried; // gaps searched
    // A gap whose far side lies within a start's spacing of a gap searched
    // before (a segment traced into that gap shortened it from its start):
    // the branch with half the harmonics gives the same guesses there, whose
    // solutions are kept from the last search and cost no Newton solve to
    // label again, while the predicted mode's starts, drawn from the new
    // start, are all new.
    const double spacing = width / continuation_constants::gap_starts_per_width;
    const auto   same_far_side = [&](const Gap &gap) {
      return std::any_of(tried.begin(), tried.end(),
                         [&](const Gap &t) { return std::abs(t.second - gap.second) < spacing; });
    };
    SearchMemory                        memory;
    for (bool filled = true; filled;)
      {
        if (context.full(backbone))
          return backbone.events.push_back(event_message(
            "Continuation/Max steps = " + std::to_string(context.params.continuation.max_steps) +
              " points reached while filling the main branch's gaps",
            backbone.points.back().omega));
        filled                                   = false;
        const std::vector<BackbonePoint> labelled = labelled_in_range(context, backbone);
        // Up to the range's end too if the branch reached it.
        const std::optional<double> end =
          backbone.end == BackboneEnd::range ? std::optional<double>(context.far_end) : std::nullopt;
        // From the range's near end too where the branch entered the range
        // from outside it (grazing beyond Omega min).
        const std::optional<double> start =
          context.in_range(backbone.points.front().omega) ? std::nullopt : std::optional<double>(context.near_end);
        for (const Gap &gap : main_gaps_wider_than(labelled, context.direction, width, end, start))
          {
            if (std::find(tried.begin(), tried.end(), gap) != tried.end())
              continue;
            const Prediction from = same_far_side(gap) ? Prediction::fewer_harmonics_first : Prediction::trend_first;
            tried.push_back(gap);
            if (fill(context, backbone, labelled, gap, memory, from))
              {
                filled = true;
                break;
              }
          }
      }
  }
} // namespace nsm
