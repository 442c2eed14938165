#include <nsm/base/errors.h>
#include <nsm/base/interruption.h>
#include <nsm/continuation/branch_context.h>
#include <nsm/continuation/checkpoint.h>
#include <nsm/continuation/continuation.h>
#include <nsm/continuation/gap_filling.h>
#include <nsm/continuation/grazing_start.h>
#include <nsm/continuation/leap.h>
#include <nsm/continuation/main_branch.h>
#include <nsm/continuation/range_end.h>
#include <nsm/continuation/segment_tracer.h>
#include <nsm/continuation/sequential_steps.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace nsm
{
  std::vector<InternalResonance> internal_resonances(const Receptance       &receptance,
                                                     const BranchParameters &params)
  {
    const auto                    &c   = params.continuation;
    const unsigned int             top = params.harmonic_balance.harmonics;
    std::vector<InternalResonance> found;
    for (unsigned int j = 0; j < receptance.poles().size(); ++j)
      for (unsigned int k = 1; k <= top; ++k)
        {
          const double w = std::sqrt(receptance.poles()[j]);
          if (w <= top * c.omega_max && in_omega_range(c, w / k))
            found.push_back({w / k, j + 1, k});
        }
    std::sort(found.begin(), found.end(),
              [](const auto &a, const auto &b) { return a.omega < b.omega; });
    return found;
  }

  namespace
  {
    /// How far the backbone's lists reach: at a segment's start (its first
    /// point the last), where an interrupted arclength segment is traced
    /// again from, or at its end.
    struct Counts
    {
      std::size_t  points, events, folds;
      unsigned int leaps;
    };

    Counts counts(const Backbone &b) { return {b.points.size(), b.events.size(), b.folds.size(), b.leaps}; }

    /// A checkpoint of the backbone's lists up to `cut`, with the context's span.
    std::shared_ptr<ContinuationCheckpoint> checkpoint_up_to(const BranchContext &context, const Backbone &b,
                                                             const Counts &cut)
    {
      auto c = std::make_shared<ContinuationCheckpoint>();
      c->points.assign(b.points.begin(), b.points.begin() + cut.points);
      c->events.assign(b.events.begin(), b.events.begin() + cut.events);
      c->folds.assign(b.folds.begin(), b.folds.begin() + cut.folds);
      c->gap_searches = b.gap_searches;
      c->leaps = cut.leaps;
      c->span  = context.span;
      return c;
    }

    /// The checkpoint of a continuation interrupted in `segment`: from its
    /// last point with the step the tracer would take next (the sequential
    /// method's), or else from the segment's first point.
    std::shared_ptr<ContinuationCheckpoint> interrupted_checkpoint(const BranchContext &context,
                                                                   const SegmentTracer &method,
                                                                   const Backbone &backbone,
                                                                   const unsigned int segment, const Counts &start)
    {
      const std::optional<double> step = method.resume_step();
      auto c     = checkpoint_up_to(context, backbone, step ? counts(backbone) : start);
      c->segment = segment;
      c->step    = step;
      c->end     = BackboneEnd::interrupted;
      return c;
    }

    /// fill_gaps, its Newton solves and wall time kept in the backbone.
    void fill_gaps_counted(BranchContext &context, Backbone &backbone)
    {
      const NewtonCost before = context.newton_cost();
      const auto       start  = std::chrono::steady_clock::now();
      fill_gaps(context, backbone);
      backbone.gap_search_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      backbone.gap_search_cost    = context.newton_cost().since(before);
    }

    /// Segments joined by leaps over folds and tongues, from `segment` on,
    /// until the range, Max steps, a leap that finds no branch, or a stop
    /// signal (the checkpoint is then kept). At the range or a lost branch,
    /// the gaps behind are filled if the scene asks (gap_filling.h).
    void trace(BranchContext &context, SegmentTracer &method, Backbone &backbone, unsigned int segment)
    {
      for (;; ++segment)
        {
          const Counts start = counts(backbone);
          const SegmentEnd end   = method.trace(context, backbone, segment);
          const double omega = backbone.points.back().omega;
          if (end == SegmentEnd::range)
            {
              backbone.events.push_back(event_message(
                context.in_range(omega) ? "end of the Omega range" : "left the Omega range", omega));
              if (context.in_range(omega))
                find_branch_below_at_end(context, backbone, segment);
              return fill_gaps_counted(context, backbone);
            }
          if (end == SegmentEnd::interrupted)
            {
              backbone.checkpoint = interrupted_checkpoint(context, method, backbone, segment, start);
              backbone.end        = BackboneEnd::interrupted;
              return backbone.events.push_back(
                event_message(std::string("stopped by ") + stop_signal_name(point_stop_signal()), omega));
            }
          if (end == SegmentEnd::max_steps)
            {
              backbone.end = BackboneEnd::max_steps;
              return backbone.events.push_back(event_message(
                "Continuation/Max steps = " + std::to_string(context.params.continuation.max_steps) +
                  " points reached (raise it to go on)",
                omega));
            }
          if (end == SegmentEnd::refused)
            {
              backbone.end = BackboneEnd::refused;
              return;
            }
          backbone.folds.push_back(omega);
          backbone.events.push_back(event_message(end == SegmentEnd::fold ?
                                                    "branch folds (continuation stalls)" :
                                                    "resonance tongue above Energy max",
                                                  omega, context.resonances));
          if (!leap(context, backbone, segment + 1, method.first_fold()))
            return fill_gaps_counted(context, backbone);
        }
    }

    /// The checkpoint of a continuation that ended: its points before the
    /// range filter and labels.
    std::shared_ptr<ContinuationCheckpoint> complete_checkpoint(const BranchContext &context,
                                                                const Backbone      &backbone)
    {
      auto c      = checkpoint_up_to(context, backbone, counts(backbone));
      c->segment  = backbone.points.back().segment;
      c->complete = true;
      c->end      = backbone.end;
      return c;
    }

    /// The backbone, the context and the tracer as the checkpoint left them.
    void restore(const ContinuationCheckpoint &c, BranchContext &context, SegmentTracer &method, Backbone &backbone)
    {
      backbone.points      = c.points;
      backbone.events      = c.events;
      backbone.folds       = c.folds;
      backbone.gap_searches = c.gap_searches;
      backbone.leaps       = c.leaps;
      backbone.end         = c.end;
      context.span         = c.span;
      method.resume_with(c.step);
    }
  } // namespace

  Backbone compute_backbone(HarmonicBalance                      &hb,
                            const BranchParameters               &params,
                            const std::vector<InternalResonance> &resonances,
                            const ContinuationCheckpoint         *resume)
  {
    Backbone             backbone;
    FewerHarmonicsBranch fewer(hb, params, resonances);
    BranchContext        context(hb, params, resonances, &fewer);
    const std::unique_ptr<SegmentTracer> method = make_segment_tracer(params.continuation.method);
    if (resume)
      restore(*resume, context, *method, backbone);
    else
      backbone.points.push_back(start_at_grazing(context, backbone));
    if (!resume || !resume->complete)
      {
        backbone.end = BackboneEnd::range;
        trace(context, *method, backbone, resume ? resume->segment : 0);
      }
    if (!backbone.checkpoint)
      backbone.checkpoint = complete_checkpoint(context, backbone);
    backbone.newton_cost = context.newton_cost();
    backbone.newton_cost += fewer.newton_cost();
    backbone.fewer_harmonics_traced = fewer.traced();
    // Points traced on the way from grazing to the range are not written.
    auto &p = backbone.points;
    if (!p.empty())
      {
        backbone.traced_span  = {p.front().omega, p.front().omega};
        backbone.traced_start = p.front().omega;
      }
    for (const BackbonePoint &q : p)
      backbone.traced_span = {std::min(backbone.traced_span.first, q.omega), std::max(backbone.traced_span.second, q.omega)};
    p.erase(std::remove_if(p.begin(), p.end(),
                           [&](const BackbonePoint &q) { return !in_omega_range(params.continuation, q.omega); }),
            p.end());
    label_branches(hb, params, p);
    backbone.tongues = collect_tongues(p);
    return backbone;
  }
} // namespace nsm

namespace nsm
{

  std::size_t position_beside(const std::vector<BackbonePoint> &points, const std::size_t index, const double omega,
                              const double direction)
  {
    // Segments run in the direction of continuation (falling Omega with eq. (5)).
    return index + (direction * (omega - points[index].omega) > 0 ? 1 : 0);
  }

  BackbonePoint solve_on_branch(HarmonicBalance        &hb,
                                const BranchParameters &params,
                                const Backbone         &backbone,
                                const double            omega,
                                const bool              main_only)
  {
    const auto   &p = backbone.points;
    BranchContext context(hb, params, {});
    BackbonePoint point;
    // Labelled among the points where it lies: in its segment, beside the
    // point it continues.
    const auto labelled = [&](const std::size_t position) -> BackbonePoint & {
      label_point(hb, params, p, point, position);
      return point;
    };
    const auto beside = [&](const BackbonePoint &q) {
      return position_beside(p, static_cast<std::size_t>(&q - p.data()), omega, context.direction);
    };
    // Between two points of one segment, the solution must continue the branch
    // from both, as a step would; Newton from their interpolation can land on
    // another branch.
    const auto between = [&](const BackbonePoint &a, const BackbonePoint &b) {
      return context.solve(omega, interpolated_guess(a, b, omega), a.segment, point) &&
             stays_on_branch(a, point, params.continuation) && stays_on_branch(b, point, params.continuation);
    };
    // Pairs of main points first, then (unless main_only) the others: a
    // filled gap's segment is stored after the tongue it fills (gap_filling.h).
    const auto main_pair = [&](const std::size_t i) {
      return p[i].branch == Branch::main && p[i + 1].branch == Branch::main;
    };
    for (const bool main_pairs : {true, false})
      for (std::size_t i = 0; i + 1 < p.size(); ++i)
        if (p[i].segment == p[i + 1].segment && (p[i].omega - omega) * (p[i + 1].omega - omega) <= 0 &&
            main_pair(i) == main_pairs && (main_pairs || !main_only) && between(p[i], p[i + 1]))
          return labelled(i + 1);
    // Omega in the gap a leap left, or Newton failed between the points: as a
    // leap does, with a line search, from the nearest points below and above
    // and from the impulsive guess.
    if (!main_only && !p.empty())
      {
        for (const BackbonePoint *q : {nearest_on_side(p, omega, -1), nearest_on_side(p, omega, 1)})
          if (q && context.solve(omega, q->x, q->segment, point, BranchContext::Newton::both))
            return labelled(beside(*q));
        hb.set_omega(omega);
        const std::vector<double> guess   = hb.grazing_guess();
        const BackbonePoint      &nearest = *nearest_on_side(p, omega, 0);
        if (!guess.empty() && context.solve(omega, guess, nearest.segment, point, BranchContext::Newton::both))
          return labelled(beside(nearest));
      }
    std::ostringstream s;
    s.precision(10);
    s << "no converged solution on the computed branch at Omega = " << omega;
    throw NumericalError(s.str());
  }
} // namespace nsm
