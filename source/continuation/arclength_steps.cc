#include <nsm/continuation/constants.h>
#include <nsm/continuation/arclength_steps.h>
#include <nsm/continuation/loca_arclength.h>
#include <nsm/continuation/sequential_steps.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// The steps of one LOCA run, accepted one at a time.
    class ArclengthRun
    {
    public:
      ArclengthRun(BranchContext &context, Backbone &backbone, const unsigned int segment,
                   std::optional<std::size_t> &first_fold)
        : context_(context)
        , backbone_(backbone)
        , segment_(segment)
        , first_fold_(first_fold)
      {}

      /// LOCA finished its run without a stop from accept(): it reached its
      /// Min or Max Value. Otherwise it failed to converge a step (a fold).
      SegmentEnd run(const double initial_step)
      {
        // A copy: accepting steps grows backbone.points and moves its elements.
        const BackbonePoint start = backbone_.points.back();
        const bool          finished =
          run_arclength(context_.hb, context_.params, start, initial_step,
                        [&](const BackbonePoint &candidate) { return accept(candidate); });
        return finished && end_ == SegmentEnd::fold ? SegmentEnd::range : end_;
      }

    private:
      /// Keeps a converged step or stops LOCA, setting how the segment ends.
      bool accept(const BackbonePoint &candidate)
      {
        const auto   &c = context_.params.continuation;
        BackbonePoint point;
        if (!context_.make_point(candidate.x, candidate.omega, candidate.residual, 0, segment_, point))
          return stop(SegmentEnd::refused, refusal(candidate));
        if (point.measures.energy > c.energy_max || climbed_tongue(point))
          return stop(SegmentEnd::tongue);
        if (!stays(backbone_.points.back(), point))
          return stop(SegmentEnd::jump);
        if (context_.beyond(point.omega, context_.far_end))
          {
            land_on_end(point);
            return stop(SegmentEnd::range);
          }
        note_fold(point);
        backbone_.points.push_back(point);
        if (context_.full(backbone_))
          return stop(context_.full_end());
        if (!context_.in_range(point.omega + context_.direction * c.min_step) &&
            (point.omega >= c.omega_max || point.omega <= c.omega_min))
          return stop(SegmentEnd::range);
        return true;
      }

      bool stop(const SegmentEnd end, const std::string &event = "")
      {
        end_ = end;
        if (!event.empty())
          backbone_.events.push_back(event);
        return false;
      }

      static std::string refusal(const BackbonePoint &candidate)
      {
        std::ostringstream why;
        why << "arclength step refused (residual " << candidate.residual << ", contact fraction "
            << candidate.measures.contact_fraction << "): not a converged contact motion";
        return event_message(why.str(), candidate.omega);
      }

      /// The step guards of stays_on_branch, and one of LOCA's own: its
      /// corrector moves on the plane normal to the tangent, which does not
      /// bound Omega, and where the tangent lies mostly along the unknowns it
      /// can slide far along Omega onto another branch. A step never moves
      /// Omega by more than its length, at most Max step.
      bool stays(const BackbonePoint &from, const BackbonePoint &to) const
      {
        const auto &c = context_.params.continuation;
        return stays_on_branch(from, to, c) && std::abs(to.omega - from.omega) <= c.max_step;
      }

      /// The main branch rises with Omega; where arclength first turns back
      /// (the segment's first fold) it has entered a resonance tongue. True
      /// once the tongue is above Tongue energy ratio times the energy there.
      bool climbed_tongue(const BackbonePoint &point) const
      {
        return first_fold_ &&
               point.measures.energy > context_.params.continuation.tongue_energy_ratio *
                                         backbone_.points[*first_fold_].measures.energy;
      }

      /// A fold is where Omega turns back within the segment.
      void note_fold(const BackbonePoint &point)
      {
        const auto &points = backbone_.points;
        if (points.size() < 2 || points[points.size() - 2].segment != segment_)
          return;
        const double before = points.back().omega - points[points.size() - 2].omega;
        const double after  = point.omega - points.back().omega;
        if (before * after >= 0)
          return;
        if (!first_fold_)
          first_fold_ = points.size() - 1;
        backbone_.folds.push_back(points.back().omega);
        backbone_.events.push_back(
          event_message("arclength turns a fold", points.back().omega, context_.resonances));
      }

      /// A step went past the end of the range: the last point is solved
      /// exactly there, from the guess interpolated between the segment's
      /// last point and the step's.
      void land_on_end(const BackbonePoint &past)
      {
        const BackbonePoint &last = backbone_.points.back();
        BackbonePoint        point;
        if (context_.solve(context_.far_end, interpolated_guess(last, past, context_.far_end), segment_, point) &&
            stays(last, point))
          backbone_.points.push_back(std::move(point));
      }

      BranchContext     &context_;
      Backbone          &backbone_;
      const unsigned int          segment_;
      std::optional<std::size_t> &first_fold_;
      SegmentEnd                  end_ = SegmentEnd::fold;
    };
  } // namespace

  SegmentEnd ArclengthSteps::trace(BranchContext &context, Backbone &backbone, const unsigned int segment)
  {
    first_fold_.reset();
    if (!context.beyond(context.near_end, backbone.points.back().omega))
      approach_step_.reset(); // in the range: no approach to go on with
    else if (const SegmentEnd end = sequential_segment(context, backbone, segment, approach_step_, true);
             end != SegmentEnd::approach)
      return end;
    return arclength_segment(context, backbone, segment, first_fold_);
  }

  SegmentEnd arclength_segment(BranchContext &context, Backbone &backbone, const unsigned int segment,
                               std::optional<std::size_t> &first_fold)
  {
    const auto &c = context.params.continuation;
    for (double step = std::min(c.initial_step, context.max_step()); step >= c.min_step;
         step /= continuation_constants::step_shrink)
      if (const SegmentEnd end = ArclengthRun(context, backbone, segment, first_fold).run(step);
          end != SegmentEnd::jump)
        return end;
    return SegmentEnd::fold;
  }
} // namespace nsm
