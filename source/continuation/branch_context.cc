#include <nsm/base/interruption.h>
#include <nsm/continuation/constants.h>
#include <nsm/continuation/branch_context.h>
#include <nsm/continuation/continuation.h>
#include <nsm/base/assertions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace nsm
{
  std::string event_message(const std::string                    &what,
                            const double                          omega,
                            const std::vector<InternalResonance> &resonances)
  {
    std::ostringstream s;
    s.precision(8);
    s << what << " at Omega = " << omega;
    if (!resonances.empty())
      {
        const auto &r = nearest_resonance(resonances, omega);
        s << "; nearest internal resonance w_" << r.mode << " / " << r.harmonic << " = " << r.omega;
      }
    return s.str();
  }

  std::size_t last_segment_start(const Backbone &backbone)
  {
    std::size_t first = backbone.points.size() - 1;
    while (first > 0 && backbone.points[first - 1].segment == backbone.points.back().segment)
      --first;
    return first;
  }

  const BackbonePoint *lowest_point_behind(const BranchContext &context, const Backbone &backbone, const double omega,
                                           const double reach)
  {
    const BackbonePoint *lowest = nullptr;
    for (const BackbonePoint &p : backbone.points)
      if (std::abs(p.omega - omega) <= reach && !context.beyond(p.omega, omega) &&
          (!lowest || p.measures.energy < lowest->measures.energy))
        lowest = &p;
    return lowest;
  }

  double least_energy_behind(const BranchContext &context, const Backbone &backbone, const double omega,
                             const double reach)
  {
    const BackbonePoint *lowest = lowest_point_behind(context, backbone, omega, reach);
    return lowest ? lowest->measures.energy : std::numeric_limits<double>::infinity();
  }

  std::vector<double> interpolated_guess(const BackbonePoint &a, const BackbonePoint &b, const double omega)
  {
    const double        run = b.omega - a.omega;
    const double        t   = run == 0 ? 0 : (omega - a.omega) / run;
    AssertDimension(a.x.size(), b.x.size());
    std::vector<double> guess(a.x.size());
    for (std::size_t i = 0; i < guess.size(); ++i)
      guess[i] = (1 - t) * a.x[i] + t * b.x[i];
    return guess;
  }

  HarmonicBalanceParameters leap_parameters(HarmonicBalanceParameters params)
  {
    params.line_search    = "Polynomial";
    params.max_iterations = params.iterations() * continuation_constants::leap_iteration_factor;
    return params;
  }

  BranchContext::BranchContext(HarmonicBalance               &hb,
                               const BranchParameters        &params,
                               std::vector<InternalResonance> resonances,
                               FewerHarmonicsBranch          *fewer)
    : hb(hb)
    , params(params)
    , resonances(std::move(resonances))
    , direction(branch_direction(params.contact))
    , near_end(direction > 0 ? params.continuation.omega_min : params.continuation.omega_max)
    , far_end(direction > 0 ? params.continuation.omega_max : params.continuation.omega_min)
    , newton_(hb, params.harmonic_balance)
    , leap_newton_(hb, leap_parameters(params.harmonic_balance))
    , progress_("continuation", params.progress_every)
    , fewer_(fewer)
  {}

  bool BranchContext::make_point(const std::vector<double> &x, const double omega, const double residual,
                                 const unsigned int iterations, const unsigned int segment,
                                 BackbonePoint &point)
  {
    if (!(residual <= params.harmonic_balance.tolerance))
      return false;
    hb.set_omega(omega);
    const PeriodicSolutionMeasures m = hb.measure(x);
    if (!(m.contact_fraction > 0 && m.max_contact_force > 0 && m.energy > 0 &&
          std::isfinite(m.energy_spread)))
      return false;
    // mu is added to a residual row: beyond the residual's tolerance it is a
    // forcing the motion needs, not round-off (at most 2e-13 measured).
    if (hb.has_unfolding() && std::abs(x[1]) > params.harmonic_balance.tolerance)
      return false;
    point = {segment, omega, m, iterations, residual, x};
    return true;
  }

  bool BranchContext::solve(const double omega, const std::vector<double> &guess,
                            const unsigned int segment, BackbonePoint &point, const Newton newton)
  {
    bool converged = false, at_limit = false;
    for (NewtonSolver *solver : {&newton_, &leap_newton_})
      {
        if ((solver == &newton_ && newton == Newton::line_search) ||
            (solver == &leap_newton_ && newton == Newton::full_steps))
          continue;
        const NewtonResult r = solver->solve(omega, guess);
        if (r.converged && make_point(r.x, omega, r.residual, r.iterations, segment, point))
          return true;
        converged = converged || r.converged;
        at_limit  = at_limit || r.at_iteration_limit;
      }
    last_failure_ = at_limit ? SolveFailure::iteration_limit : converged ? SolveFailure::no_contact : SolveFailure::stalled;
    return false;
  }

  bool BranchContext::full(const Backbone &backbone)
  {
    progress_.update([&] {
      std::ostringstream s;
      // M tells the branch with half the harmonics (leap.h) from the run's own.
      s << "M = " << params.harmonic_balance.harmonics << ", " << backbone.points.size()
        << " points, Omega = " << backbone.points.back().omega << " (range " << near_end << " to " << far_end
        << "), " << backbone.leaps << " leaps";
      return s.str();
    });
    return backbone.points.size() >= params.continuation.max_steps || point_stop_signal() != 0;
  }

  SegmentEnd BranchContext::full_end() const
  {
    return point_stop_signal() != 0 ? SegmentEnd::interrupted : SegmentEnd::max_steps;
  }

  double BranchContext::max_step() const
  {
    return std::min(params.continuation.max_step, span / continuation_constants::steps_per_span);
  }

  NewtonCost BranchContext::newton_cost() const
  {
    NewtonCost total = newton_.cost();
    total += leap_newton_.cost();
    return total;
  }

  const Backbone *BranchContext::fewer_harmonics() { return fewer_ ? fewer_->get() : nullptr; }

  std::vector<double> BranchContext::guess_from_fewer_harmonics(const BackbonePoint &fewer) const
  {
    std::vector<double> guess(hb.n_unknowns(), 0.0);
    std::copy_n(fewer.x.begin(), std::min(fewer.x.size(), guess.size()), guess.begin());
    return guess;
  }
} // namespace nsm
