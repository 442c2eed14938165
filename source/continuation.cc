#include <nsm/continuation.h>
#include <nsm/progress.h>
#include <nsm/main_branch.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace nsm
{
  std::vector<InternalResonance> internal_resonances(const Receptance &receptance,
                                                     const Scene      &scene)
  {
    const auto                    &c   = scene.continuation;
    const unsigned int             top = scene.harmonic_balance.harmonics;
    std::vector<InternalResonance> found;
    for (unsigned int j = 0; j < receptance.poles().size(); ++j)
      for (unsigned int k = 1; k <= top; ++k)
        {
          const double w = std::sqrt(receptance.poles()[j]);
          if (w <= top * c.omega_max && in_omega_range(scene, w / k))
            found.push_back({w / k, j + 1, k});
        }
    std::sort(found.begin(), found.end(),
              [](const auto &a, const auto &b) { return a.omega < b.omega; });
    return found;
  }

  bool in_omega_range(const Scene &scene, const double omega)
  {
    return omega >= scene.continuation.omega_min && omega <= scene.continuation.omega_max;
  }

  double branch_direction(const Scene &scene)
  {
    return scene.contact.sign == ForceSign::physical ? 1.0 : -1.0;
  }

  unsigned int Backbone::main_points() const
  {
    return std::count_if(points.begin(), points.end(),
                         [](const BackbonePoint &p) { return p.branch == Branch::main; });
  }

  const InternalResonance &nearest_resonance(const std::vector<InternalResonance> &resonances,
                                             const double                          omega)
  {
    return *std::min_element(resonances.begin(), resonances.end(), [&](const auto &a, const auto &b) {
      return std::abs(a.omega - omega) < std::abs(b.omega - omega);
    });
  }

  namespace
  {
    /// "what at Omega = ..." for the run summary, with the nearest internal
    /// resonance when given the list.
    std::string event_message(const std::string                    &what,
                              const double                          omega,
                              const std::vector<InternalResonance> &resonances = {})
    {
      std::ostringstream s;
      s.precision(8);
      s << what << " at Omega = " << omega;
      if (!resonances.empty())
        {
          const auto &r = nearest_resonance(resonances, omega);
          s << "; nearest internal resonance w_" << r.mode << " / " << r.harmonic
            << " = " << r.omega;
        }
      return s.str();
    }

    /// A leap starts far from the solution: Newton with a line search and
    /// twice the iterations.
    Scene::HarmonicBalance leap_parameters(Scene::HarmonicBalance params)
    {
      params.line_search    = "Polynomial";
      params.max_iterations *= 2;
      return params;
    }

    /// Start, acceptance and both continuation methods for one branch.
    class BranchTracer
    {
    public:
      BranchTracer(HarmonicBalance                      &hb,
                   const Scene                          &scene,
                   const std::vector<InternalResonance> &resonances)
        : hb_(hb)
        , scene_(scene)
        , resonances_(resonances)
        , newton_(hb, scene.harmonic_balance)
        , leap_newton_(hb, leap_parameters(scene.harmonic_balance))
        , direction_(branch_direction(scene))
        , near_(direction_ > 0 ? scene.continuation.omega_min : scene.continuation.omega_max)
        , far_(direction_ > 0 ? scene.continuation.omega_max : scene.continuation.omega_min)
        , progress_("continuation", scene.output.progress_every)
      {}

      /// A converged solve becomes a point only if it is a genuine contact
      /// motion: the trivial solution (no contact) and, in the full basis, a
      /// solution whose unfolding parameter does not vanish are refused.
      bool make_point(const std::vector<double> &x, double omega, double residual,
                      unsigned int iterations, unsigned int segment, BackbonePoint &point)
      {
        if (!(residual <= scene_.harmonic_balance.tolerance))
          return false;
        hb_.set_omega(omega);
        const PeriodicSolutionMeasures m = hb_.measure(x);
        if (!(m.contact_fraction > 0 && m.max_contact_force > 0 && m.energy > 0 &&
              std::isfinite(m.energy_spread)))
          return false;
        if (hb_.has_unfolding() && std::abs(x[1]) > 1e-6)
          return false;
        point = {segment, omega, m, iterations, residual, x};
        return true;
      }

      /// Newton from the guess; a leap that fails with full steps tries
      /// again with a line search and more iterations.
      bool solve(double omega, const std::vector<double> &guess, unsigned int segment,
                 BackbonePoint &point, bool leaping = false)
      {
        for (NewtonSolver *solver : {&newton_, &leap_newton_})
          {
            const NewtonResult r = solver->solve(omega, guess);
            if (r.converged && make_point(r.x, omega, r.residual, r.iterations, segment, point))
              return true;
            if (!leaping)
              return false;
          }
        return false;
      }

      /// The first point: just beyond w_j (above it with the physical sign),
      /// from an impulsive-contact guess, moving away until Newton converges.
      BackbonePoint start(Backbone &backbone)
      {
        const unsigned int         mode  = scene_.continuation.mode;
        const std::vector<double> &poles = hb_.receptance().poles();
        if (mode > poles.size())
          throw InputError("parameter 'Continuation/Mode' = " + std::to_string(mode) +
                           " is out of range: allowed 1 to " + std::to_string(poles.size()) +
                           " (clamped-free modes below Harmonics x Omega max)");
        const double w = std::sqrt(poles[mode - 1]);
        // The contact lasts a vanishing share of the period at grazing; 5 % of
        // w_j away the branch is far beyond its grazing end. A start before
        // the range is traced up to it; one beyond it has no point in it.
        for (double offset = scene_.continuation.grazing_offset; offset < 0.05; offset *= 2)
          {
            const double omega = w * (1 + direction_ * offset);
            if (beyond(omega, far_))
              break;
            hb_.set_omega(omega);
            const std::vector<double> guess = hb_.grazing_guess();
            BackbonePoint             point;
            if (!guess.empty() && solve(omega, guess, 0, point))
              {
                std::ostringstream s;
                s.precision(10);
                s << "start at grazing of clamped-free mode " << mode << " (w = " << w
                  << ") at Omega = " << omega;
                backbone.events.push_back(s.str());
                if (point.measures.energy > scene_.continuation.energy_max)
                  throw InputError("parameter 'Continuation/Energy max' = " +
                                   std::to_string(scene_.continuation.energy_max) +
                                   " is out of range: allowed above the energy at grazing, " +
                                   std::to_string(point.measures.energy));
                span_ = std::abs(far_ - (beyond(near_, omega) ? near_ : omega));
                return point;
              }
          }
        std::ostringstream s;
        s << "no converged non-trivial solution within 5 % of grazing of clamped-free mode "
          << mode << " (w = " << w << ") and before the end of Continuation/Omega min..max"
          << "; Contact/Alpha = " << scene_.contact.alpha << " gives alpha gamma(0) = "
          << scene_.contact.alpha * hb_.receptance()(0.0).gamma
          << " (the contact law's switch lambda - alpha g balances force and gap for alpha "
             "gamma(0) near 1, where the start converges most easily)";
        throw NumericalError(s.str());
      }

      enum class SegmentEnd
      {
        approach,  ///< the start of the range reached from a start before it
        range,     ///< Omega min or max reached
        fold,      ///< no convergence below Min step, or LOCA gave up
        tongue,    ///< energy above Energy max (climbing a resonance tongue)
        max_steps, ///< Max steps points in all
        refused,   ///< arclength reached a point that is not a contact motion
        jump       ///< an arclength step left the branch (shortened and retried)
      };

      /// Segments joined by leaps over folds and tongues, until the range,
      /// Max steps, or a leap that finds no branch.
      void trace(Backbone &backbone)
      {
        for (unsigned int segment = 0;; ++segment)
          {
            SegmentEnd end = scene_.continuation.method == ContinuationMethod::sequential ||
                                 beyond(near_, backbone.points.back().omega) ?
                               sequential(backbone, segment) :
                               arclength(backbone, segment);
            if (end == SegmentEnd::approach)
              end = arclength(backbone, segment);
            const double omega = backbone.points.back().omega;
            if (end == SegmentEnd::range)
              return backbone.events.push_back(event_message(
                in_range(omega) ? "end of the Omega range" : "left the Omega range", omega));
            if (end == SegmentEnd::max_steps)
              return backbone.events.push_back(event_message("Max steps reached", omega));
            if (end == SegmentEnd::refused)
              return;
            backbone.folds.push_back(omega);
            backbone.events.push_back(event_message(end == SegmentEnd::fold ?
                                                     "branch folds (continuation stalls)" :
                                                     "resonance tongue above Energy max",
                                                   omega, resonances_));
            if (!leap(backbone, segment + 1))
              return;
            first_fold_.reset();
          }
      }

      NewtonCost newton_cost() const
      {
        NewtonCost total = newton_.cost();
        total += leap_newton_.cost();
        return total;
      }

    private:
      /// Called after each point: Max steps reached? Also reports progress.
      bool full(const Backbone &backbone)
      {
        progress_.update([&] {
          std::ostringstream s;
          s << backbone.points.size() << " points, Omega = " << backbone.points.back().omega
            << " (range " << near_ << " to " << far_ << "), " << backbone.leaps << " leaps";
          return s.str();
        });
        return backbone.points.size() >= scene_.continuation.max_steps;
      }

      bool in_range(double omega) const { return in_omega_range(scene_, omega); }

      /// a lies beyond b in the direction of continuation.
      bool beyond(const double a, const double b) const { return direction_ * (a - b) > 0; }

      /// Steps never exceed a tenth of the range covered, so that a narrow
      /// range still gets points.
      double max_step() const { return std::min(scene_.continuation.max_step, span_ / 10); }

      /// A step whose solution moved by more than a fifth of the solution
      /// itself has jumped to another branch (over a fold), not followed it.
      static bool stays_on_branch(const BackbonePoint &from, const BackbonePoint &to)
      {
        double change = 0, size = 0;
        for (std::size_t i = 0; i < from.x.size(); ++i)
          {
            change += (to.x[i] - from.x[i]) * (to.x[i] - from.x[i]);
            size += from.x[i] * from.x[i];
          }
        return change <= 0.04 * size;
      }

      /// An arclength step may also turn a fold, where the solution changes
      /// little along the arc but the contact set does: one whose contact
      /// fraction changed by more than Max contact change has jumped.
      bool arc_stays_on_branch(const BackbonePoint &from, const BackbonePoint &to) const
      {
        return stays_on_branch(from, to) &&
               std::abs(to.measures.contact_fraction - from.measures.contact_fraction) <=
                 scene_.continuation.max_contact_change;
      }

      /// Steps in Omega with a secant predictor; quarters the step on failure
      /// or on a jump to another branch. Steps stop exactly at the start of
      /// the range (coming from before it) and at its end.
      SegmentEnd sequential(Backbone &backbone, unsigned int segment)
      {
        const auto       &c     = scene_.continuation;
        double            step  = std::min(c.initial_step, max_step());
        const std::size_t first = backbone.points.size() - 1;
        while (!full(backbone))
          {
            const BackbonePoint current = backbone.points.back();
            if (current.omega == far_)
              return SegmentEnd::range;
            const bool before = beyond(near_, current.omega);
            if (!before && c.method == ContinuationMethod::arclength)
              return SegmentEnd::approach;
            double omega = current.omega + direction_ * step;
            if (before && beyond(omega, near_))
              omega = near_;
            if (beyond(omega, far_))
              omega = far_;
            std::vector<double> guess = current.x;
            if (backbone.points.size() - 1 > first)
              {
                const BackbonePoint &previous = backbone.points[backbone.points.size() - 2];
                const double ratio = (omega - current.omega) / (current.omega - previous.omega);
                for (unsigned int i = 0; i < guess.size(); ++i)
                  guess[i] += ratio * (current.x[i] - previous.x[i]);
              }
            BackbonePoint point;
            if (solve(omega, guess, segment, point) && stays_on_branch(current, point))
              {
                if (point.measures.energy > c.energy_max)
                  return SegmentEnd::tongue;
                if (point.newton_iterations <= 4)
                  step = std::min(1.5 * step, max_step());
                backbone.points.push_back(std::move(point));
                continue;
              }
            // Shrink fast: at a fold every smaller step fails too.
            step /= 4;
            if (step < c.min_step)
              return SegmentEnd::fold;
          }
        return SegmentEnd::max_steps;
      }

      /// The main branch rises with Omega; where arclength first turns back
      /// (the segment's first fold) it has entered a resonance tongue. True
      /// once the tongue is above Tongue energy ratio times the energy there.
      bool climbed_tongue(const Backbone &backbone, const BackbonePoint &point) const
      {
        return first_fold_ && point.measures.energy > scene_.continuation.tongue_energy_ratio *
                                                        backbone.points[*first_fold_].measures.energy;
      }

      /// LOCA pseudo-arclength from the segment's last point; a step that
      /// jumps to another branch stops LOCA, which starts again from the last
      /// point with a quarter of the step, down to Min step.
      SegmentEnd arclength(Backbone &backbone, unsigned int segment)
      {
        for (double step = std::min(scene_.continuation.initial_step, max_step());
             step >= scene_.continuation.min_step;
             step /= 4)
          if (const SegmentEnd end = arclength_run(backbone, segment, step); end != SegmentEnd::jump)
            return end;
        return SegmentEnd::fold;
      }

      /// An arclength step went past the end of the range: the last point is
      /// solved exactly there, from the guess interpolated between the
      /// segment's last point and the step's.
      void land_on_end(Backbone &backbone, unsigned int segment, const BackbonePoint &past)
      {
        const BackbonePoint &last = backbone.points.back();
        const double         t    = (far_ - last.omega) / (past.omega - last.omega);
        std::vector<double>  guess(last.x.size());
        for (std::size_t i = 0; i < guess.size(); ++i)
          guess[i] = (1 - t) * last.x[i] + t * past.x[i];
        BackbonePoint point;
        if (solve(far_, guess, segment, point) && arc_stays_on_branch(last, point))
          backbone.points.push_back(std::move(point));
      }

      /// One LOCA run; a fold is where Omega turns back.
      SegmentEnd arclength_run(Backbone &backbone, unsigned int segment, double initial_step)
      {
        const auto &c   = scene_.continuation;
        SegmentEnd  end = SegmentEnd::fold;
        // A copy: accepting steps grows backbone.points and moves its elements.
        const BackbonePoint start = backbone.points.back();
        const bool finished = run_arclength(hb_, scene_, start, initial_step, [&](const BackbonePoint &candidate) {
          BackbonePoint point;
          if (!make_point(candidate.x, candidate.omega, candidate.residual, 0, segment, point))
            {
              std::ostringstream why;
              why << "arclength step refused (residual " << candidate.residual
                  << ", contact fraction " << candidate.measures.contact_fraction
                  << "): not a converged contact motion";
              backbone.events.push_back(event_message(why.str(), candidate.omega));
              end = SegmentEnd::refused;
              return false;
            }
          if (point.measures.energy > c.energy_max || climbed_tongue(backbone, point))
            {
              end = SegmentEnd::tongue;
              return false;
            }
          if (!arc_stays_on_branch(backbone.points.back(), point))
            {
              end = SegmentEnd::jump;
              return false;
            }
          if (beyond(point.omega, far_))
            {
              land_on_end(backbone, segment, point);
              end = SegmentEnd::range;
              return false;
            }
          const auto &points = backbone.points;
          if (points.size() >= 2 && points[points.size() - 2].segment == segment)
            {
              const double before = points.back().omega - points[points.size() - 2].omega;
              const double after  = point.omega - points.back().omega;
              if (before * after < 0)
                {
                  if (!first_fold_)
                    first_fold_ = points.size() - 1;
                  backbone.folds.push_back(points.back().omega);
                  backbone.events.push_back(
                    event_message("arclength turns a fold", points.back().omega, resonances_));
                }
            }
          backbone.points.push_back(point);
          if (full(backbone))
            {
              end = SegmentEnd::max_steps;
              return false;
            }
          if (!in_range(point.omega + direction_ * c.min_step) &&
              (point.omega >= c.omega_max || point.omega <= c.omega_min))
            {
              end = SegmentEnd::range;
              return false;
            }
          return true;
        });
        // LOCA finished its run without a stop from accept(): it reached its
        // Min or Max Value. Otherwise it failed to converge a step (a fold).
        if (finished && end == SegmentEnd::fold)
          return SegmentEnd::range;
        return end;
      }

      /// Tries W beyond the fold at distances growing from Initial step to
      /// 5 % of Omega, from three guesses: the front of the segment (its last
      /// point, or where arclength first turned back before climbing a
      /// tongue), the segment's first point, which the resonance has not
      /// distorted yet, and an impulsive contact reaching the gap at that W. A landing must be at about the energy the branch had
      /// (a landing far from it is on a tongue's flank). A success opens a
      /// new segment.
      bool leap(Backbone &backbone, unsigned int segment)
      {
        const auto         &c     = scene_.continuation;
        const BackbonePoint front =
          backbone.points[first_fold_.value_or(backbone.points.size() - 1)];
        std::size_t         first = backbone.points.size() - 1;
        while (first > 0 && backbone.points[first - 1].segment == front.segment)
          --first;
        const std::vector<double> guesses[] = {front.x, backbone.points[first].x};
        const double              energy    = front.measures.energy;
        for (double distance = c.initial_step;
             distance <= 0.05 * front.omega && beyond(far_, front.omega); distance *= 2)
          {
            // The last try lands exactly on the end of the range.
            const double omega =
              beyond(front.omega + direction_ * distance, far_) ? far_ : front.omega + direction_ * distance;
            hb_.set_omega(omega);
            for (const std::vector<double> &guess : {guesses[0], guesses[1], hb_.grazing_guess()})
              {
                if (guess.empty())
                  continue;
                BackbonePoint point;
                if (solve(omega, guess, segment, point, true) &&
                    point.measures.energy <= c.energy_max && point.measures.energy < 4 * energy &&
                    point.measures.energy > energy / 4)
                  {
                    backbone.events.push_back(event_message("leapt to a new segment", omega));
                    ++backbone.leaps;
                    backbone.points.push_back(std::move(point));
                    return true;
                  }
              }
            if (omega == far_)
              break;
          }
        backbone.events.push_back(event_message("branch lost after the fold", front.omega));
        return false;
      }

      HarmonicBalance                      &hb_;
      const Scene                          &scene_;
      const std::vector<InternalResonance> &resonances_;
      NewtonSolver                          newton_;
      NewtonSolver                          leap_newton_;
      const double                          direction_;
      const double                          near_, far_; ///< the range's ends, first met and last
      double                                span_ = 0;   ///< of the range covered from the start
      std::optional<std::size_t>            first_fold_; ///< in the current segment
      Progress                              progress_;
    };
  } // namespace

  Backbone compute_backbone(HarmonicBalance                      &hb,
                            const Scene                          &scene,
                            const std::vector<InternalResonance> &resonances)
  {
    Backbone     backbone;
    BranchTracer tracer(hb, scene, resonances);
    backbone.points.push_back(tracer.start(backbone));
    tracer.trace(backbone);
    backbone.newton_cost = tracer.newton_cost();
    // Points traced on the way from grazing to the range are not written.
    const auto &c = scene.continuation;
    auto       &p = backbone.points;
    p.erase(std::remove_if(p.begin(), p.end(),
                           [&](const BackbonePoint &q) { return !in_omega_range(scene, q.omega); }),
            p.end());
    label_branches(hb, c.tongue_share, branch_direction(scene), p);
    backbone.tongues = collect_tongues(p);
    return backbone;
  }
} // namespace nsm

namespace nsm
{
  BackbonePoint solve_on_branch(HarmonicBalance &hb,
                                const Scene     &scene,
                                const Backbone  &backbone,
                                const double     omega,
                                const bool       main_only)
  {
    const auto &p = backbone.points;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
      if (p[i].segment == p[i + 1].segment &&
          (p[i].omega - omega) * (p[i + 1].omega - omega) <= 0 &&
          (!main_only || (p[i].branch == Branch::main && p[i + 1].branch == Branch::main)))
        {
          const double        t = (omega - p[i].omega) / (p[i + 1].omega - p[i].omega);
          std::vector<double> guess(p[i].x.size());
          for (std::size_t j = 0; j < guess.size(); ++j)
            guess[j] = (1 - t) * p[i].x[j] + t * p[i + 1].x[j];
          const std::vector<InternalResonance> none;
          BranchTracer                         tracer(hb, scene, none);
          BackbonePoint point;
          if (tracer.solve(omega, guess, p[i].segment, point))
            return point;
          break;
        }
    std::ostringstream s;
    s.precision(10);
    s << "no converged solution on the computed branch at Omega = " << omega;
    throw NumericalError(s.str());
  }
} // namespace nsm
