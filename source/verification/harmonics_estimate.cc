#include <nsm/base/interruption.h>
#include <nsm/base/progress.h>
#include <nsm/base/text.h>
#include <nsm/continuation/branch_context.h>
#include <nsm/harmonic_balance/newton_solver.h>
#include <nsm/verification/harmonics_estimate.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// The 90th percentile the summary gives besides the median.
    constexpr double upper_share = 0.9;
    /// The stretches of the largest tenth named in the summary; more are counted.
    constexpr std::size_t max_spans_shown = 4;
  } // namespace

  SameMotionSolve::SameMotionSolve(HarmonicBalance &model, const HarmonicBalanceParameters &params)
    : model_(model)
    , tolerance_(params.tolerance)
    , full_steps_(model, params)
    , searching_(model, leap_parameters(params))
  {}

  NewtonResult SameMotionSolve::solve(const BackbonePoint &point, const std::vector<double> &guess)
  {
    NewtonResult r = full_steps_.solve(point.omega, guess);
    if (!r.converged)
      r = searching_.solve(point.omega, guess);
    return r;
  }

  double SameMotionSolve::energy_change(const BackbonePoint &point, const std::vector<double> &guess)
  {
    landed_elsewhere_    = false;
    const NewtonResult r = solve(point, guess);
    if (!r.converged || !(r.residual <= tolerance_))
      return std::numeric_limits<double>::quiet_NaN();
    model_.set_omega(point.omega);
    const PeriodicSolutionMeasures m = model_.measure(r.x);
    if (!(m.energy > 0 && m.contact_fraction > 0 &&
          std::abs(m.contact_fraction - point.measures.contact_fraction) <= same_motion_contact_change))
      {
        landed_elsewhere_ = true;
        return std::numeric_limits<double>::quiet_NaN();
      }
    return std::abs(m.energy / point.measures.energy - 1);
  }

  std::vector<std::size_t> spread_main_points(const Backbone &backbone, const std::size_t count)
  {
    std::vector<std::size_t> main;
    for (std::size_t i = 0; i < backbone.points.size(); ++i)
      if (backbone.points[i].branch == Branch::main)
        main.push_back(i);
    const std::size_t        n = std::min(count, main.size());
    std::vector<std::size_t> spread;
    for (std::size_t i = 0; i < n; ++i)
      spread.push_back(main[n == 1 ? 0 : i * (main.size() - 1) / (n - 1)]);
    return spread;
  }

  std::vector<double> estimate_energy_errors(const HarmonicBalance &hb, const BranchParameters &branch,
                                             const Backbone &backbone, Progress &progress,
                                             std::vector<bool> *elsewhere)
  {
    std::vector<double> estimates(backbone.points.size(), std::numeric_limits<double>::quiet_NaN());
    if (elsewhere != nullptr)
      elsewhere->assign(backbone.points.size(), false);
    if (branch.harmonic_balance.harmonics < 2)
      return estimates;
    HarmonicBalanceParameters fewer = branch.harmonic_balance;
    fewer.harmonics              = branch.harmonic_balance.harmonics / 2;
    HarmonicBalance model(fewer, branch.contact, hb.receptance());
    SameMotionSolve solve(model, fewer);
    for (std::size_t i = 0; i < estimates.size() && point_stop_signal() == 0; ++i)
      {
        const BackbonePoint &p = backbone.points[i];
        estimates[i] = solve.energy_change(p, std::vector<double>(p.x.begin(), p.x.begin() + model.n_unknowns()));
        if (elsewhere != nullptr)
          (*elsewhere)[i] = solve.landed_elsewhere();
        progress.update([&] { return "point " + std::to_string(i + 1) + " of " + std::to_string(estimates.size()); });
      }
    return estimates;
  }

  EstimateSummary summarise_estimates(const Backbone &backbone, const std::vector<double> &estimates,
                                      const std::vector<bool> &elsewhere)
  {
    EstimateSummary                         s;
    std::vector<std::pair<double, double>>  main; // (Omega, estimate) of each main point, NaN without one
    for (std::size_t i = 0; i < backbone.points.size(); ++i)
      if (backbone.points[i].branch == Branch::main)
        main.emplace_back(backbone.points[i].omega,
                          i < estimates.size() ? estimates[i] : std::numeric_limits<double>::quiet_NaN());
    s.main = main.size();
    for (std::size_t i = 0; i < elsewhere.size(); ++i)
      if (elsewhere[i] && backbone.points[i].branch == Branch::main)
        ++s.elsewhere;
    std::vector<double> found;
    for (const auto &[omega, e] : main)
      if (std::isfinite(e))
        found.push_back(e);
    s.estimated = found.size();
    if (found.empty())
      return s;
    std::sort(found.begin(), found.end());
    s.median = found[found.size() / 2];
    s.p90    = found[std::min(found.size() - 1, std::size_t(upper_share * found.size()))];
    // Runs of main points (in Omega) whose estimate reaches the 90th percentile.
    std::sort(main.begin(), main.end());
    bool open = false;
    for (const auto &[omega, e] : main)
      if (std::isfinite(e) && e >= s.p90)
        {
          if (open)
            s.upper_spans.back().second = omega;
          else
            s.upper_spans.emplace_back(omega, omega);
          open = true;
        }
      else if (std::isfinite(e))
        open = false;
    return s;
  }

  std::string estimate_summary(const EstimateSummary &summary, const unsigned int harmonics)
  {
    std::ostringstream s;
    s.precision(2);
    if (harmonics < 2)
      return "estimated energy error of these M = 1 points: none (with M / 2 = 0 no harmonic is left to compare)";
    s << "estimated energy error of these M = " << harmonics << " points, |E(M/2) / E(M) - 1| with E(M/2) solved "
      << "with M = " << harmonics / 2 << " at the same Omega: ";
    if (summary.estimated == 0)
      s << "none of " << summary.main << " main points";
    else
      {
        s << "median " << 100 * summary.median << " %, 90th percentile " << 100 * summary.p90 << " % over "
          << summary.estimated << " of " << summary.main << " main points; the largest tenth at Omega ";
        const std::size_t shown = std::min<std::size_t>(summary.upper_spans.size(), max_spans_shown);
        for (std::size_t i = 0; i < shown; ++i)
          {
            const auto &[from, to] = summary.upper_spans[i];
            s << (i > 0 ? ", " : "") << significant(from, 5);
            if (significant(to, 5) != significant(from, 5))
              s << " to " << significant(to, 5);
          }
        if (summary.upper_spans.size() > shown)
          s << " and " << summary.upper_spans.size() - shown << " more stretches";
      }
    if (summary.estimated < summary.main)
      {
        const std::size_t missing = summary.main - summary.estimated;
        s << "; " << missing << " without an estimate: with M = " << harmonics / 2
          << ", Newton from the point's own harmonics did not converge at " << missing - summary.elsewhere
          << " and converged on another motion (contact fraction more than " << same_motion_contact_change
          << " away) at " << summary.elsewhere;
      }
    return s.str();
  }
} // namespace nsm
