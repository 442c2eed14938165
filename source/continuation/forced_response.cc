#include <nsm/base/dense_lu.h>
#include <nsm/base/vector_norm.h>
#include <nsm/continuation/constants.h>
#include <nsm/continuation/dense_lu_group.h>
#include <nsm/continuation/forced_response.h>
#include <nsm/harmonic_balance/nox_hb_system.h>

#include <LOCA.H>
#include <LOCA_LAPACK.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <Teuchos_oblackholestream.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

namespace nsm
{
  namespace
  {
    /// The parameter a curve is traced in, as LOCA sees it: W, or the load
    /// F / F_max (in [0, 1], so that the scene's steps suit it).
    struct Sweep
    {
      ForcedSweep kind;
      double      scale; ///< F_max (forcing), 1 (omega)

      double value(const ForcedPoint &p) const { return kind == ForcedSweep::omega ? p.omega : p.forcing / scale; }

      void set(ForcedHarmonicBalance &hb, const double v) const
      {
        if (kind == ForcedSweep::omega)
          hb.set_omega(v);
        else
          hb.set_forcing(v * scale);
      }

      /// Whether the system can be evaluated at v: an arclength corrector's
      /// W may leave the band a distributed drive is summed over: with one
      /// harmonic the band ends at Omega max itself, and a corrector past the
      /// range's end (W = 2.2032 on the seed bar's uniform load) lies beyond
      /// it (farther correctors, W = -540 at M = 80, lie beyond the
      /// interface's reach too).
      bool evaluable(const ForcedHarmonicBalance &hb, const double v) const
      {
        return kind != ForcedSweep::omega || hb.drives_at(v);
      }

      /// dR / d(value) at x, the parameter set.
      std::vector<double> derivative(const ForcedHarmonicBalance &hb, const std::vector<double> &x) const
      {
        std::vector<double> d;
        if (kind == ForcedSweep::omega)
          {
            hb.evaluate(x, nullptr, nullptr, &d);
            return d;
          }
        d = hb.dforcing(x);
        for (double &v : d)
          v *= scale;
        return d;
      }
    };

    /// The forced system at the parameter LOCA sets, with its derivative,
    /// evaluated only within `reach` of the parameter (the range and a
    /// Max step beyond each end): no point beyond is written, and a
    /// corrector that wanders farther (to W = -9 and 2.3 on the seed bar,
    /// where every harmonic beyond the receptance's band costs a direct
    /// solve) diverges. Newton's finite-value test then fails the step at
    /// once instead of after its iterations, and LOCA shortens it.
    class ForcedInterface : public LocaSystem
    {
    public:
      ForcedInterface(ForcedHarmonicBalance &hb, const Sweep &sweep, const std::vector<double> &guess,
                      const std::array<double, 2> &reach)
        : hb_(hb)
        , sweep_(sweep)
        , guess_(hb.n_unknowns())
        , reach_(reach)
      {
        for (unsigned int i = 0; i < guess.size(); ++i)
          guess_(i) = guess[i];
      }

      const NOX::LAPACK::Vector &getInitialGuess() override { return guess_; }

      bool computeF(NOX::LAPACK::Vector &f, const NOX::LAPACK::Vector &x) override
      {
        if (!evaluable())
          return not_a_number(f.length(), &f(0));
        sweep_.set(hb_, value_);
        hb_.evaluate(HbInterface::to_std(x), &scratch_, nullptr);
        return copy(scratch_, &f(0));
      }

      bool computeJacobian(NOX::LAPACK::Matrix<double> &jacobian, const NOX::LAPACK::Vector &x) override
      {
        if (!evaluable())
          return not_a_number(std::size_t(jacobian.numRows()) * jacobian.numCols(), &jacobian(0, 0));
        sweep_.set(hb_, value_);
        hb_.evaluate(HbInterface::to_std(x), nullptr, &scratch_);
        return copy(scratch_, &jacobian(0, 0));
      }

      bool compute_domega(NOX::LAPACK::Vector &result, const NOX::LAPACK::Vector &x) override
      {
        if (!evaluable())
          return not_a_number(result.length(), &result(0));
        sweep_.set(hb_, value_);
        return copy(sweep_.derivative(hb_, HbInterface::to_std(x)), &result(0));
      }

      void setParams(const LOCA::ParameterVector &p) override { value_ = p.getValue("Omega"); }

      void printSolution(const NOX::LAPACK::Vector &x, const double value) override
      {
        if (on_step)
          on_step(HbInterface::to_std(x), value);
      }

      std::function<void(const std::vector<double> &, double)> on_step;

    private:
      bool evaluable() const { return value_ >= reach_[0] && value_ <= reach_[1] && sweep_.evaluable(hb_, value_); }

      /// Where the system is not evaluated (evaluable()), NaN: the
      /// Newton tests' finite-value test fails the step, which LOCA
      /// shortens (a failed evaluation would end the run with an error).
      static bool not_a_number(const std::size_t count, double *to)
      {
        std::fill(to, to + count, std::numeric_limits<double>::quiet_NaN());
        return true;
      }

      static bool copy(const std::vector<double> &from, double *to)
      {
        bool finite = true;
        for (std::size_t i = 0; i < from.size(); ++i)
          finite = finite && std::isfinite(to[i] = from[i]);
        return finite;
      }

      ForcedHarmonicBalance &hb_;
      const Sweep           &sweep_;
      NOX::LAPACK::Vector    guess_;
      std::array<double, 2>  reach_;
      double                 value_ = 0;
      std::vector<double>    scratch_;
    };

    /// The last point written, as the step's guard compares with it.
    struct LastPoint
    {
      double              contact = std::nan(""); ///< NaN: none yet
      std::vector<double> displacement;          ///< u(L, t)'s coefficients
    };

    /// The guard's view of the point x at the parameter's value.
    LastPoint last_point(ForcedHarmonicBalance &hb, const Sweep &sweep, const double value,
                         const std::vector<double> &x)
    {
      sweep.set(hb, value);
      return {hb.contact_fraction(x), hb.displacement(x)};
    }

    /// 2-norm of a - b over 2-norm of the larger.
    double relative_change(const std::vector<double> &a, const std::vector<double> &b)
    {
      double difference = 0, size_a = 0, size_b = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        {
          difference += (a[i] - b[i]) * (a[i] - b[i]);
          size_a += a[i] * a[i];
          size_b += b[i] * b[i];
        }
      return std::sqrt(difference / std::max({size_a, size_b, std::numeric_limits<double>::min()}));
    }

    /// The step's guard: the contact fraction within Max contact change of
    /// the last point's, and the contact end's motion (its coefficients)
    /// within Max solution change of the last point's, relative.
    bool within_guard(const ContinuationParameters &continuation, const LastPoint &last, const double contact,
                      const std::vector<double> &displacement)
    {
      return std::abs(contact - last.contact) <= continuation.max_contact_change &&
             relative_change(displacement, last.displacement) <= continuation.max_solution_change;
    }

    /// Newton's tests, and where they converge, the step's guard: a step
    /// whose contact fraction moved more than Max contact change from the
    /// last point written, or whose contact end's motion u(L, t) changed by
    /// more than Max solution change (relative), fails, and LOCA retries it
    /// shorter. Without the first a step of Max step passes over the fold of
    /// a curve whose peak is a few steps wide, onto the curve's other side;
    /// without the second a step from where the curve leaves the wall lands
    /// on the linear response on the other side of the resonance, where the
    /// contact force is zero too (both seen on the seed bar).
    class GuardedStep : public NOX::StatusTest::Generic
    {
    public:
      /// Once `ended` is set every step fails at once: LOCA shortens it to
      /// Min step and the run ends there.
      GuardedStep(Teuchos::RCP<NOX::StatusTest::Generic> newton, ForcedHarmonicBalance &hb, const Sweep &sweep,
                  const ContinuationParameters &continuation, const LastPoint &last, const bool &ended)
        : newton_(newton)
        , hb_(hb)
        , sweep_(sweep)
        , continuation_(continuation)
        , last_(last)
        , ended_(ended)
      {}

      NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic &problem,
                                              NOX::StatusTest::CheckType  type) override
      {
        if (ended_)
          return status_ = NOX::StatusTest::Failed;
        status_ = newton_->checkStatus(problem, type);
        if (status_ != NOX::StatusTest::Converged || std::isnan(last_.contact))
          return status_;
        const auto &extended =
          dynamic_cast<const LOCA::MultiContinuation::ExtendedVector &>(problem.getSolutionGroup().getX());
        const auto &x = dynamic_cast<const NOX::LAPACK::Vector &>(*extended.getXVec());
        sweep_.set(hb_, extended.getScalar(0));
        const std::vector<double> unknowns = HbInterface::to_std(x);
        if (!within_guard(continuation_, last_, hb_.contact_fraction(unknowns), hb_.displacement(unknowns)))
          status_ = NOX::StatusTest::Failed;
        return status_;
      }

      NOX::StatusTest::StatusType getStatus() const override { return status_; }

      std::ostream &print(std::ostream &stream, int indent) const override
      {
        return stream << std::string(indent, ' ') << status_ << " contact and motion within Max contact change and Max solution change\n";
      }

    private:
      Teuchos::RCP<NOX::StatusTest::Generic> newton_;
      ForcedHarmonicBalance                 &hb_;
      const Sweep                           &sweep_;
      const ContinuationParameters          &continuation_;
      const LastPoint                       &last_;
      const bool                            &ended_;
      NOX::StatusTest::StatusType            status_ = NOX::StatusTest::Unevaluated;
    };

    /// LOCA's parameters: pseudo-arclength in the swept parameter (LOCA's
    /// "Omega", W or the load) over the range with the scene's step bounds,
    /// Newton as the backbone's, LOCA's messages discarded.
    Teuchos::RCP<Teuchos::ParameterList> forced_parameters(const HarmonicBalanceParameters &hb,
                                                           const ContinuationParameters    &c,
                                                           const double low, const double high,
                                                           const double start)
    {
      auto  params  = Teuchos::rcp(new Teuchos::ParameterList);
      auto &stepper = params->sublist("LOCA").sublist("Stepper");
      stepper.set("Continuation Method", "Arc Length");
      stepper.set("Continuation Parameter", "Omega");
      stepper.set("Initial Value", start);
      stepper.set("Max Value", high);
      stepper.set("Min Value", low);
      stepper.set("Max Steps", static_cast<int>(c.max_steps));
      stepper.set("Max Nonlinear Iterations", static_cast<int>(hb.iterations()));
      stepper.set("Compute Eigenvalues", false);
      stepper.set("Enable Arc Length Scaling", false);
      auto &predictor = params->sublist("LOCA").sublist("Predictor");
      predictor.set("Method", "Secant");
      predictor.sublist("First Step Predictor").set("Method", "Tangent");
      predictor.sublist("Last Step Predictor").set("Method", "Tangent");
      auto &step = params->sublist("LOCA").sublist("Step Size");
      step.set("Method", "Adaptive");
      step.set("Aggressiveness", continuation_constants::loca_aggressiveness);
      step.set("Initial Step Size", c.initial_step);
      step.set("Min Step Size", c.min_step);
      step.set("Max Step Size", c.max_step);
      set_newton_parameters(params->sublist("NOX"), hb);
      params->sublist("NOX").sublist("Printing").set("Output Information", NOX::Utils::Error);
      params->sublist("LOCA").sublist("Utilities").set("Output Information", NOX::Utils::Error);
      params->sublist("NOX").sublist("Printing").set("Error Stream",
                                                      Teuchos::RCP<std::ostream>(new Teuchos::oblackholestream));
      return params;
    }

    /// The point x of hb at its current W and F, whose residual's 2-norm is
    /// `residual`.
    ForcedPoint point_of(const ForcedHarmonicBalance &hb, const unsigned int segment, const std::vector<double> &x,
                         const double residual)
    {
      return {segment, hb.omega(), hb.forcing(), hb.measure(x), residual, hb.stable(x), x};
    }

    /// Where a stepper run starts, and how.
    struct StepperStart
    {
      double              value; ///< the swept parameter's
      std::vector<double> x;
      double              step;           ///< signed: the first step's direction in the parameter
      unsigned int        max_steps;
      bool                keep_start;     ///< the start is a new point (else already written)
      unsigned int        segment = 0;    ///< of the points it writes
    };

    /// Distance in the stepper's unscaled arclength metric (the parameter and x).
    double distance(const Sweep &sweep, const ForcedPoint &a, const ForcedPoint &b)
    {
      const double d   = sweep.value(a) - sweep.value(b);
      double       sum = d * d;
      for (std::size_t i = 0; i < a.x.size(); ++i)
        sum += (a.x[i] - b.x[i]) * (a.x[i] - b.x[i]);
      return std::sqrt(sum);
    }

    /// One LOCA run from `start`, appending the points that meet the
    /// tolerance to `points` (counting the others in `rejected`). Returns
    /// whether it reached an end of the range.
    bool run_stepper(ForcedHarmonicBalance &hb, const Sweep &sweep, const HarmonicBalanceParameters &harmonic_balance,
                     const ContinuationParameters &continuation, const double low, const double high,
                     const StepperStart &start, std::vector<ForcedPoint> &points, unsigned int &rejected,
                     const std::function<bool()> &ends = {})
    {
      ContinuationParameters c = continuation;
      c.initial_step           = start.step;
      c.max_steps              = start.max_steps;
      const auto params        = forced_parameters(harmonic_balance, c, low, high, start.value);
      auto       data          = LOCA::createGlobalData(params);
      LastPoint  last;
      if (!start.keep_start)
        last = last_point(hb, sweep, start.value, start.x);
      bool       finished      = false;
      bool       ended         = false;
      {
        ForcedInterface interface(hb, sweep, start.x, {{low - continuation.max_step, high + continuation.max_step}});
        auto            group = Teuchos::rcp(new DenseLuGroup(data, interface));
        LOCA::ParameterVector parameters;
        parameters.addParameter("Omega", start.value);
        group->setParams(parameters);
        bool at_start = true;
        interface.on_step = [&](const std::vector<double> &x, const double value) {
          const bool skip = at_start && !start.keep_start;
          at_start        = false;
          // The arclength corrector may carry the step before the range's end
          // beyond it (up to 0.18 % of W measured); LOCA then writes the end
          // itself, which is kept.
          if (skip || value < low || value > high)
            return;
          sweep.set(hb, value);
          std::vector<double> residual;
          hb.evaluate(x, &residual, nullptr);
          const double norm = two_norm(residual);
          if (norm > harmonic_balance.tolerance)
            ++rejected;
          else
            {
              points.push_back(point_of(hb, start.segment, x, norm));
              last  = {points.back().measures.contact_fraction, hb.displacement(x)};
              ended = ends && ends();
            }
        };
        const auto status = Teuchos::rcp(
          new GuardedStep(newton_status(harmonic_balance), hb, sweep, continuation, last, ended));
        LOCA::Stepper stepper(data, group, status, params);
        finished = stepper.run() == LOCA::Abstract::Iterator::Finished;
      }
      LOCA::destroyGlobalData(data);
      return finished;
    }

    /// Whether `next` lies within the step's guard of `last` (GuardedStep).
    bool within_guard(ForcedHarmonicBalance &hb, const Sweep &sweep, const ContinuationParameters &continuation,
                      const ForcedPoint &last, const ForcedPoint &next)
    {
      const LastPoint guard = last_point(hb, sweep, sweep.value(last), last.x);
      sweep.set(hb, sweep.value(next));
      return within_guard(continuation, guard, next.measures.contact_fraction, hb.displacement(next.x));
    }

    /// The direction of travel at a stall is read over this many points
    /// back: near a stall the last steps may go back and forth.
    constexpr std::size_t travel_points = 10;

    /// One curve: the stepper from the linear response (or the bar at rest)
    /// at the range's low end, and where every step fails, restarts at a
    /// corner and leaps past a stall.
    class CurveTracer
    {
    public:
      CurveTracer(ForcedHarmonicBalance &hb, const Sweep &sweep, const HarmonicBalanceParameters &harmonic_balance,
                  const ContinuationParameters &continuation, const double low, const double high)
        : hb_(hb)
        , sweep_(sweep)
        , harmonic_balance_(harmonic_balance)
        , continuation_(continuation)
        , scene_min_step_(continuation.min_step)
        , low_(low)
        , high_(high)
      {}

      /// The curve, with the drive's fixed value (F, or W) set in hb.
      ForcedCurve trace()
      {
        curve_.sweep    = sweep_.kind;
        curve_.forcing  = sweep_.kind == ForcedSweep::omega ? hb_.forcing() : sweep_.scale;
        curve_.omega    = sweep_.kind == ForcedSweep::omega ? 0.0 : hb_.omega();
        curve_.finished = run_on({low_, std::vector<double>(hb_.n_unknowns(), 0.0), continuation_.initial_step,
                                  continuation_.max_steps, true, 0});
        // In W, the far side is traced from Omega max before any leap onto
        // another motion: such a leap (onto the linear response past a
        // stall below the peak) jumps over the stretch where the peak may
        // lie, which the trace from the far end climbs to.
        const bool from_both_ends = sweep_.kind == ForcedSweep::omega;
        go_on_at_stalls(!from_both_ends);
        if (!curve_.finished && from_both_ends && steps_left() > 0)
          {
            // Where that trace wrote nothing, the first trace's stall has had
            // every other start: a leap onto another motion is left.
            trace_from_far_end();
            if (curve_.from_far_end->points == 0 && curve_.points.size() >= 2 && leap(true))
              go_on_at_stalls(true);
          }
        curve_.out_of_steps = !curve_.whole() && steps_left() == 0;
        return curve_;
      }

    private:
      /// Restarts at corners, entries into contact and leaps from the
      /// curve's last point while every step fails there (leaps onto
      /// another motion only if `onto_other_motions`), and where none goes
      /// on, a finer Min step (refine_min_step).
      void go_on_at_stalls(const bool onto_other_motions)
      {
        set_aside_.clear();
        while (!curve_.finished && !joined_ &&
               curve_.restarts + curve_.leaps < continuation_constants::forced_restarts &&
               curve_.points.size() >= 2 && steps_left() > 0 &&
               (restart_at_corner() || enter_contact() || enter_at_grazing() || leap(onto_other_motions) ||
                refine_min_step()))
          {}
        // The points refine_min_step set aside go back, the last set aside
        // first, while nothing went on from where each left the curve.
        for (std::size_t i = set_aside_.size(); i-- > 0 && curve_.points.size() == set_aside_[i].kept;)
          curve_.points.insert(curve_.points.end(), set_aside_[i].points.begin(), set_aside_[i].points.end());
      }

      /// How many of the curve's last points lie in its last point's segment.
      std::size_t own_points() const
      {
        std::size_t own = 0;
        while (own < curve_.points.size() &&
               curve_.points[curve_.points.size() - 1 - own].segment == curve_.points.back().segment)
          ++own;
        return own;
      }

      /// Where nothing else goes on, the stall may be a fold sharper than
      /// Min step resolves: Min step divided by forced_min_step_division
      /// (at most forced_min_step_refinements times per trace; the finer
      /// step holds for the rest of the trace),
      /// and up to travel_points of the segment's last points set aside (two
      /// stay), for the restarts to approach the fold again with the finer
      /// step (go_on_at_stalls puts them back where nothing went on).
      bool refine_min_step()
      {
        if (trace_refinements_ == continuation_constants::forced_min_step_refinements)
          return false;
        ++trace_refinements_;
        ++curve_.min_step_refinements;
        continuation_.min_step /= continuation_constants::forced_min_step_division;
        origins_.clear();
        const std::size_t own  = own_points();
        const std::size_t back = own > 2 ? std::min(travel_points, own - 2) : 0;
        set_aside_.push_back({{curve_.points.end() - back, curve_.points.end()}, curve_.points.size() - back});
        curve_.points.erase(curve_.points.end() - back, curve_.points.end());
        return true;
      }

      /// The curve from the linear response's guess at the range's far end
      /// back towards where the trace from the near end stopped, as a new
      /// segment, on at its own stalls; it ends where it lands back on the
      /// curve's linear response or comes back along the curve, as any run,
      /// where it stalls too, or where it joins the first trace's path
      /// (cut_retrace: the two traces meet and the curve is whole).
      void trace_from_far_end()
      {
        // A trace of its own: the scene's Min step, refined again only at
        // its own stalls.
        continuation_.min_step = scene_min_step_;
        trace_refinements_     = 0;
        // Where the start at the near end converged nowhere (its linear
        // response's guess far from the curve, next to the resonance), the
        // trace from the far end is the whole curve if it reaches the near end.
        if (curve_.points.empty())
          {
            curve_.finished = run_on({high_, std::vector<double>(hb_.n_unknowns(), 0.0),
                                      -continuation_.initial_step, steps_left(), true, 0});
            go_on_at_stalls(true);
            // LOCA writes the range's end itself where a run reaches it.
            const bool reached_near_end = curve_.finished && curve_.points.back().omega == low_;
            curve_.finished             = false;
            curve_.from_far_end         = ForcedCurve::FromFarEnd{
              std::numeric_limits<double>::quiet_NaN(),
              curve_.points.empty() ? std::numeric_limits<double>::quiet_NaN() : curve_.points.back().omega,
              unsigned(curve_.points.size()),
              reached_near_end ? ForcedCurve::Meeting::near_end : ForcedCurve::Meeting::none};
            return;
          }
        const ForcedPoint stopped = curve_.points.back();
        const std::size_t before  = curve_.points.size();
        far_from_                 = before;
        run_on({high_, std::vector<double>(hb_.n_unknowns(), 0.0), -continuation_.initial_step, steps_left(), true,
                stopped.segment + 1});
        // Its own restarts need two points of its own (the direction they
        // leave); one reaching Omega min does not make the first trace's
        // `finished`.
        if (curve_.points.size() >= before + 2)
          go_on_at_stalls(true);
        curve_.finished = false;
        const unsigned int written = curve_.points.size() - before;
        if (written == 0)
          {
            curve_.from_far_end =
              ForcedCurve::FromFarEnd{sweep_.value(stopped), std::numeric_limits<double>::quiet_NaN(), 0,
                                      ForcedCurve::Meeting::none};
            return;
          }
        // The traces meet where the far trace runs along the first trace's
        // path (cut_retrace): the curve is whole.
        const ForcedPoint &reached = curve_.points.back();
        const auto         meeting = joined_ ? ForcedCurve::Meeting::joined : ForcedCurve::Meeting::none;
        curve_.from_far_end = ForcedCurve::FromFarEnd{sweep_.value(stopped), sweep_.value(reached), written, meeting};
      }

      /// A run onto the curve ends as soon as it runs along the path traced
      /// before it (cut_retrace then cuts it): LOCA would go on along that
      /// path, or round a loop again, up to Max steps. Its points are counted
      /// as they come (run_retrace_).
      bool run(const StepperStart &start, std::vector<ForcedPoint> &points)
      {
        if (&points != &curve_.points)
          return run_stepper(hb_, sweep_, harmonic_balance_, continuation_, low_, high_, start, points,
                             curve_.rejected);
        run_retrace_ = {};
        return run_stepper(hb_, sweep_, harmonic_balance_, continuation_, low_, high_, start, points,
                           curve_.rejected, [&] {
                             if (run_retrace_.end == 0 &&
                                 run_retrace_.count.add(traced_path_beside(curve_.points.size() - 1)))
                               run_retrace_.end = curve_.points.size();
                             return run_retrace_.end != 0;
                           });
      }

      unsigned int steps_left() const
      {
        return continuation_.max_steps > curve_.points.size() ?
                 unsigned(continuation_.max_steps - curve_.points.size()) :
                 0u;
      }

      /// Goes on from `start` if its first point is acceptable and the run
      /// keeps a point (a run cut whole, cut_retrace, went nowhere).
      template <typename Accept>
      bool go_on(StepperStart start, const Accept &accept)
      {
        if (start.value < low_ || start.value > high_)
          return false;
        std::vector<ForcedPoint> probe;
        run(start, probe);
        if (probe.empty() || !accept(probe.front()))
          return false;
        start.max_steps           = steps_left();
        const std::size_t before  = curve_.points.size();
        curve_.finished           = run_on(start);
        return curve_.finished || curve_.points.size() > before;
      }

      /// The stepper from `start`, its points appended to the curve up to
      /// the first that lands back on the curve's linear response: off the
      /// wall (contact fraction 0) at an Omega between two consecutive
      /// points of a segment off the wall written before it. There the motion is the
      /// linear response, unique at each Omega, so such a point and those
      /// after it retrace the curve backwards (a contact branch that leaves
      /// a fold back to grazing meets the linear response below it, and the
      /// stepper follows it back to the range's start); and without the
      /// points after a turn back onto the path it came on (cut_retrace).
      /// Returns whether the run reached an end of the range without either.
      bool run_on(const StepperStart &start)
      {
        const std::size_t before   = curve_.points.size();
        const bool        finished = run(start, curve_.points);
        for (std::size_t i = before; i < curve_.points.size(); ++i)
          if (on_linear_response(curve_.points[i], i))
            {
              curve_.points.resize(i);
              cut_retrace(before);
              return false;
            }
        return !cut_retrace(before) && finished;
      }

      /// Where the stepper has come back along the curve (retrace_points
      /// points in a row on the path traced before them, traced_path_beside
      /// at most retrace_share, against its direction), it turned at a corner
      /// onto the branch it came on: the points after that turn (the last turn
      /// of the swept parameter before them; with none in the run, after the
      /// run's first point, or the whole run where that point already
      /// retraces) are dropped and counted. Where they run along that path in
      /// its own direction, the stepper has gone round a closed loop of the
      /// curve and begun it again: they and the points after them are
      /// dropped and counted. Where a trace from the far end runs so along
      /// the first trace's path (either way), it has joined it: they and the
      /// points after them are dropped, and the trace ends there (joined_).
      /// Returns whether it cut.
      bool cut_retrace(const std::size_t before)
      {
        using namespace continuation_constants;
        // The run's count (run()); points cut off its end since (onto the
        // linear response) leave the count's last points out.
        const RetraceCount &count = run_retrace_.count;
        const std::size_t   end   = run_retrace_.end;
        if (end == 0 || end > curve_.points.size())
          return false;
        const std::size_t found = end - retrace_points;
        if (count.first == retrace_points)
          {
            joined_ = true;
            curve_.points.resize(end - count.first_run);
            return true;
          }
        if (count.back < retrace_points)
          {
            curve_.retraced += curve_.points.size() - found;
            curve_.points.resize(found);
            return true;
          }
        std::size_t turn = found - 1;
        while (turn > before && turn + 1 < curve_.points.size() &&
               (sweep_.value(curve_.points[turn]) - sweep_.value(curve_.points[turn - 1])) *
                   (sweep_.value(curve_.points[turn + 1]) - sweep_.value(curve_.points[turn])) >= 0)
          --turn;
        curve_.retraced += curve_.points.size() - (turn + 1);
        curve_.points.resize(turn + 1);
        return true;
      }

      /// How near the curve's point `index` runs along a path traced before.
      struct TracedPath
      {
        /// The least distance from the path between two consecutive points of
        /// one segment, of its verdict, that it lies beside (not beyond
        /// either), among the curve's points before index - 2, over that
        /// pair's distance (the stepper's metric), over the pairs the step
        /// into it runs against and along; infinity if none.
        double back    = std::numeric_limits<double>::infinity();
        double forward = std::numeric_limits<double>::infinity();
        /// For a point of the trace from the far end: the least of either
        /// way over the first trace's pairs (infinity otherwise).
        double first = std::numeric_limits<double>::infinity();
      };

      /// Points in a row on the path traced before them, against it and
      /// along it.
      struct RetraceCount
      {
        std::size_t back = 0, along = 0, first = 0;
        /// The points of the run on the first trace's path: those counted
        /// in `first`, and between them those within retrace_share_most.
        std::size_t first_run = 0;
        /// Counts the next point; true once a count reaches retrace_points.
        bool add(const TracedPath &on)
        {
          using namespace continuation_constants;
          back  = on.back <= retrace_share ? back + 1 : 0;
          along = on.forward <= retrace_share ? along + 1 : 0;
          if (on.first <= retrace_share)
            ++first, ++first_run;
          else if (on.first <= retrace_share_most && first > 0)
            ++first_run;
          else
            first = first_run = 0;
          return back == retrace_points || along == retrace_points || first == retrace_points;
        }
      };

      TracedPath traced_path_beside(const std::size_t index) const
      {
        const ForcedPoint &p = curve_.points[index];
        TracedPath         least;
        if (index == 0 || curve_.points[index - 1].segment != p.segment)
          return least;
        const ForcedPoint &previous = curve_.points[index - 1];
        // (q - r) . (u - w) in the stepper's metric: the parameter, then x.
        const auto dot = [&](const ForcedPoint &q, const ForcedPoint &r, const ForcedPoint &u, const ForcedPoint &w) {
          double sum = (sweep_.value(q) - sweep_.value(r)) * (sweep_.value(u) - sweep_.value(w));
          for (std::size_t k = 0; k < q.x.size(); ++k)
            sum += (q.x[k] - r.x[k]) * (u.x[k] - w.x[k]);
          return sum;
        };
        for (std::size_t i = 1; i + 2 < index; ++i)
          {
            const ForcedPoint &a = curve_.points[i - 1], &b = curve_.points[i];
            // The same motion has the same verdict: beside a fold the other
            // side's points (the fold test's other verdict) come as close.
            if (a.segment != b.segment || a.stable != p.stable || b.stable != p.stable)
              continue;
            const double length2 = dot(b, a, b, a);
            if (!(length2 > 0))
              continue;
            const double t     = dot(p, a, b, a) / length2;
            const double along = dot(p, previous, b, a);
            // The distance from the chord's nearest point over its length.
            const auto share_at = [&](const double s) {
              const double dv = (sweep_.value(p) - sweep_.value(a)) - s * (sweep_.value(b) - sweep_.value(a));
              double       d  = dv * dv;
              for (std::size_t k = 0; k < p.x.size(); ++k)
                d += ((p.x[k] - a.x[k]) - s * (b.x[k] - a.x[k])) * ((p.x[k] - a.x[k]) - s * (b.x[k] - a.x[k]));
              return std::sqrt(d / length2);
            };
            // The first trace's path is a polyline: beside its points too.
            if (i < far_from_ && index >= far_from_)
              least.first = std::min(least.first, share_at(std::clamp(t, 0.0, 1.0)));
            if (t < 0 || t > 1 || along == 0)
              continue;
            double &share = along > 0 ? least.forward : least.back;
            share         = std::min(share, share_at(t));
          }
        return least;
      }

      /// Whether `next` is off the wall at a parameter between two
      /// consecutive points of a segment off the wall among the curve's
      /// first `count`.
      bool on_linear_response(const ForcedPoint &next, const std::size_t count) const
      {
        if (next.measures.contact_fraction != 0)
          return false;
        const double v = sweep_.value(next);
        for (std::size_t i = 1; i < count; ++i)
          {
            const ForcedPoint &a = curve_.points[i - 1], &b = curve_.points[i];
            if (a.segment == b.segment && a.measures.contact_fraction == 0 && b.measures.contact_fraction == 0 &&
                std::min(sweep_.value(a), sweep_.value(b)) < v && v < std::max(sweep_.value(a), sweep_.value(b)))
              return true;
          }
        return false;
      }

      /// Where every step fails, the curve may turn at a corner (a contact
      /// interval opening or closing) that the stepper's tangent does not
      /// follow: start again from the last point, along the tangent either
      /// way, or at fixed W a distance away on either side, halving from
      /// Initial step to Min step, with the first start whose first point
      /// leaves the point before behind within the step's guard. Where the
      /// curve meets the linear response (its contact ends) only a fixed-W
      /// start leaves the contact branch, and near a light damping's
      /// resonance only a short one: the linear response's amplitude changes
      /// by a share 2 W dW / |w1^2 - W^2| per dW, more than Max solution
      /// change over Initial step at 0.1 % damping. Not twice from one
      /// Omega: a curve back there cycles.
      bool restart_at_corner()
      {
        const ForcedPoint last = curve_.points.back(), before = curve_.points[curve_.points.size() - 2];
        const bool        revisited = std::any_of(origins_.begin(), origins_.end(), [&](double w) {
          return std::abs(w - sweep_.value(last)) <= continuation_.min_step;
        });
        origins_.push_back(sweep_.value(last));
        if (revisited)
          return false;
        const auto leaves_behind = [&](const ForcedPoint &next) {
          return distance(sweep_, next, before) > distance(sweep_, last, before) && !retraces(next) &&
                 within_guard(hb_, sweep_, continuation_, last, next);
        };
        std::vector<StepperStart> starts;
        const double              step = continuation_.initial_step;
        for (const double direction : {1.0, -1.0})
          starts.push_back({sweep_.value(last), last.x, direction * step, 1, false, last.segment});
        for (double distance = step; distance >= continuation_.min_step; distance /= 2)
          for (const double direction : {1.0, -1.0})
            starts.push_back(
              {sweep_.value(last) + direction * distance, last.x, direction * distance, 1, true, last.segment});
        for (const StepperStart &start : starts)
          if (go_on(start, leaves_behind))
            {
              ++curve_.restarts;
              return true;
            }
        return false;
      }

      /// Where the curve meets the wall at a corner whose contact branch
      /// turns back (a curve in F above the resonance: beyond the grazing
      /// load only the linear response, which penetrates, goes on), neither
      /// the tangent nor a fixed start leaves the branch it came on: Newton
      /// on R = 0 with the contact force's mean moved by a small share from
      /// the last point's, instead of the parameter (both F or W and the
      /// other unknowns free), lands on the branch that the mean parameterises
      /// there, at shares from contact_share down by tenths, more contact
      /// first; the stepper goes on from the first landing that is new and
      /// within the step's guard, away from the last point.
      bool enter_contact()
      {
        const ForcedPoint last = curve_.points.back();
        for (double share = continuation_constants::contact_share; share >= continuation_constants::contact_share * 1e-4;
             share /= 10)
          for (const double sign : {1.0, -1.0})
            if (const std::optional<ForcedPoint> p = solve_with_contact_mean(last, last.x[0] + sign * share);
                p && !retraces(*p) && within_guard(hb_, sweep_, continuation_, last, *p))
              {
                const double away = sweep_.value(*p) >= sweep_.value(last) ? 1.0 : -1.0;
                if (go_on({sweep_.value(*p), p->x, away * continuation_.initial_step, 1, true, last.segment},
                          [](const ForcedPoint &) { return true; }))
                  {
                    ++curve_.restarts;
                    return true;
                  }
              }
        return false;
      }

      /// Where a curve traced down its linear response meets the wall (a
      /// light damping's trace from Omega max, at the grazing point above the
      /// resonance), the contact branch it goes on on starts with short
      /// impacts at the instant the end swings farthest, which neither a
      /// restart (it lands back on the linear response) nor the contact
      /// force's mean reaches: Newton at fixed W a little either side
      /// (nearest first: from Min step, doubling while within Initial step)
      /// from an impulse train at that instant, of a period mean from
      /// grazing_impulse times F_s down by tenths; the stepper goes on from
      /// the first landing in contact that is new and within Max solution
      /// change of the last point's motion (its contact fraction jumps from
      /// 0, beyond Max contact change).
      bool enter_at_grazing()
      {
        const ForcedPoint last = curve_.points.back();
        if (last.measures.contact_fraction != 0 || sweep_.kind != ForcedSweep::omega)
          return false;
        sweep_.set(hb_, sweep_.value(last));
        const std::vector<double> u = hb_.displacement(last.x);
        // Off the wall the contact end moves with the drive alone, at W: its
        // farthest swing is at the fundamental's phase.
        const double       farthest = std::atan2(u[1], u[2]);
        const unsigned int harmonics = (hb_.n_unknowns() - 1) / 2;
        const auto         lands     = [&](const ForcedPoint &p) {
          sweep_.set(hb_, sweep_.value(p));
          return p.measures.contact_fraction > 0 && !retraces(p) &&
                 relative_change(hb_.displacement(p.x), u) <= continuation_.max_solution_change;
        };
        for (double distance = continuation_.min_step; distance <= continuation_.initial_step; distance *= 2)
          for (double mean = continuation_constants::grazing_impulse;
               mean >= continuation_constants::grazing_impulse * 1e-4; mean /= 10)
            for (const double direction : {1.0, -1.0})
              {
                // A unit impulse at tau*: mean 1, cos k and sin k 2 cos k tau* and 2 sin k tau*.
                std::vector<double> x(hb_.n_unknowns());
                x[0] = mean;
                for (unsigned int k = 1; k <= harmonics; ++k)
                  x[2 * k - 1] = 2 * mean * std::sin(k * farthest), x[2 * k] = 2 * mean * std::cos(k * farthest);
                if (go_on({sweep_.value(last) + direction * distance, x, direction * continuation_.initial_step, 1,
                           true, last.segment},
                          lands))
                  {
                    ++curve_.restarts;
                    return true;
                  }
              }
        return false;
      }

      /// Newton from `from` on R(x, v) = 0 with x_0 = mean (the contact
      /// force's mean over F_s) and v the swept parameter free; the point if
      /// it converges to the tolerance.
      std::optional<ForcedPoint> solve_with_contact_mean(const ForcedPoint &from, const double mean)
      {
        const unsigned int  n = hb_.n_unknowns();
        std::vector<double> x = from.x, residual, jacobian;
        x[0]                  = mean;
        double value          = sweep_.value(from);
        for (unsigned int iteration = 0; iteration <= harmonic_balance_.iterations(); ++iteration)
          {
            sweep_.set(hb_, value);
            hb_.evaluate(x, &residual, &jacobian);
            const double norm = two_norm(residual);
            if (!std::isfinite(norm))
              return std::nullopt;
            if (norm <= harmonic_balance_.tolerance)
              return point_of(hb_, from.segment, x, norm);
            // The mean's column gives way to dR/dv: unknowns (v, x_1, ...).
            const std::vector<double> dv = sweep_.derivative(hb_, x);
            std::copy(dv.begin(), dv.end(), jacobian.begin());
            for (double &r : residual)
              r = -r;
            if (!dense_solve(n, jacobian.data(), residual.data()))
              return std::nullopt;
            value += residual[0];
            for (unsigned int i = 1; i < n; ++i)
              x[i] += residual[i];
            if (value < low_ || value > high_)
              return std::nullopt;
          }
        return std::nullopt;
      }

      /// Whether `next` lies on the curve already: its parameter between two
      /// consecutive points of a segment, and its motion within the step's
      /// guard of the first. At a corner where the branch
      /// turns back (a curve in F meeting the wall above the resonance) the
      /// tangent points either way along the branch it came on, and a fixed
      /// start lands on that branch too.
      bool retraces(const ForcedPoint &next)
      {
        const double v = sweep_.value(next);
        for (std::size_t i = 1; i < curve_.points.size(); ++i)
          {
            const ForcedPoint &a = curve_.points[i - 1], &b = curve_.points[i];
            if (a.segment == b.segment && std::min(sweep_.value(a), sweep_.value(b)) <= v &&
                v <= std::max(sweep_.value(a), sweep_.value(b)) && within_guard(hb_, sweep_, continuation_, a, next))
              return true;
          }
        return false;
      }

      /// Where no restart goes on (the curve stalls as the backbone does
      /// near an internal resonance): Newton at fixed W from the last point's
      /// unknowns, beyond the curve's points near the stall (within Search
      /// reach) at distances doubling from Initial step up to Search reach,
      /// first in the direction of travel over the last steps, then the
      /// other way; a new segment from the first landing on the last point's
      /// motion (within the step's guard), or failing that (if
      /// `onto_other_motions`) the first that converges.
      bool leap(const bool onto_other_motions)
      {
        const ForcedPoint &last    = curve_.points.back();
        // Over the last points of its own segment (a second trace's first
        // points follow the first trace's last).
        const ForcedPoint &earlier = curve_.points[curve_.points.size() - std::min(own_points(), travel_points)];
        const double       travel  = sweep_.value(last) >= sweep_.value(earlier) ? 1.0 : -1.0;
        const double       step    = continuation_.initial_step;
        const auto same_motion = [&](const ForcedPoint &next) {
          return !retraces(next) && within_guard(hb_, sweep_, continuation_, last, next);
        };
        const auto any_motion = [&](const ForcedPoint &next) { return !retraces(next); };
        for (const bool same : {true, false})
          for (const double direction : {travel, -travel})
            {
              if (!same && !onto_other_motions)
                continue;
              const double here    = sweep_.value(last);
              double       reached = here;
              for (const ForcedPoint &p : curve_.points)
                if (std::abs(sweep_.value(p) - here) <= continuation_.search_reach)
                  reached = direction > 0 ? std::max(reached, sweep_.value(p)) : std::min(reached, sweep_.value(p));
              for (double ahead = step; ahead <= continuation_.search_reach;
                   ahead *= continuation_constants::search_growth)
                {
                  const StepperStart start{reached + direction * ahead, last.x, direction * step, 1, true,
                                           last.segment + 1};
                  if (same ? go_on(start, same_motion) : go_on(start, any_motion))
                    {
                      ++curve_.leaps;
                      return true;
                    }
                }
            }
        return false;
      }

      ForcedHarmonicBalance           &hb_;
      const Sweep                      sweep_;
      const HarmonicBalanceParameters &harmonic_balance_;
      /// The scene's, but for Min step, which refine_min_step() divides.
      ContinuationParameters           continuation_;
      double                           scene_min_step_;
      unsigned int                     trace_refinements_ = 0; ///< of the current trace (the curve's are counted in it)
      double                           low_, high_;
      ForcedCurve                      curve_;
      std::vector<double>              origins_; ///< the parameter at every restart
      /// Points refine_min_step set aside, and how many points the curve
      /// kept before them.
      struct SetAside
      {
        std::vector<ForcedPoint> points;
        std::size_t              kept;
      };
      std::vector<SetAside> set_aside_; ///< in the current go_on_at_stalls
      /// The first point of the trace from the far end (none before it).
      std::size_t far_from_ = std::numeric_limits<std::size_t>::max();
      /// That trace ran along the first trace's path (cut_retrace).
      bool joined_ = false;
      /// The last run's points counted on the paths traced before them, and
      /// one past the point where a count reached retrace_points (0: none).
      struct RunRetrace
      {
        RetraceCount count;
        std::size_t  end = 0;
      } run_retrace_;
    };
  } // namespace

  ForcedCurve trace_forced_curve(ForcedHarmonicBalance           &hb,
                                 const HarmonicBalanceParameters &harmonic_balance,
                                 const ContinuationParameters    &continuation,
                                 const double                     omega_min,
                                 const double                     omega_max,
                                 const double                     forcing)
  {
    hb.set_forcing(forcing);
    return CurveTracer(hb, {ForcedSweep::omega, 1.0}, harmonic_balance, continuation, omega_min, omega_max).trace();
  }

  ForcedCurve trace_force_curve(ForcedHarmonicBalance           &hb,
                                const HarmonicBalanceParameters &harmonic_balance,
                                const ContinuationParameters    &continuation,
                                const double                     omega,
                                const double                     forcing_max)
  {
    // The steps in the load are the scene's as shares of its Omega range, so
    // that a curve in F takes as many steps over its load as a curve in W
    // over the range, whatever W's units. From the linear response at the
    // first step's load, not from rest: the step's guard measures the
    // motion's change relative to the last point's, which at rest is all.
    ContinuationParameters in_load = continuation;
    const double           range   = continuation.omega_max - continuation.omega_min;
    if (range > 0)
      for (double *step : {&in_load.initial_step, &in_load.min_step, &in_load.max_step, &in_load.search_reach})
        *step /= range;
    hb.set_omega(omega);
    return CurveTracer(hb, {ForcedSweep::forcing, forcing_max}, harmonic_balance, in_load, in_load.initial_step, 1.0)
      .trace();
  }
} // namespace nsm
