#include <nsm/base/interruption.h>
#include <nsm/base/text.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/model/receptance.h>
#include <nsm/verification/doubled_harmonics.h>
#include <nsm/verification/harmonics_estimate.h>
#include <nsm/harmonic_balance/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// Main points solved with 2 M: as many as the band check solves on its
    /// judge, for the same reason (a median one point near a tongue does not
    /// decide) at a cost of a few per cent of the run.
    constexpr std::size_t doubled_samples = 15;

    double median(std::vector<double> values)
    {
      if (values.empty())
        return std::numeric_limits<double>::quiet_NaN();
      std::sort(values.begin(), values.end());
      return values[values.size() / 2];
    }

    /// x with the harmonics it lacks set to zero (n unknowns).
    std::vector<double> padded(const std::vector<double> &x, const std::size_t n)
    {
      std::vector<double> guess(n, 0.0);
      std::copy(x.begin(), x.end(), guess.begin());
      return guess;
    }

    /// The resonances w_j / k, M < k <= 2 M, in [low, high].
    std::size_t resonances_between(const std::vector<double> &poles, const unsigned int harmonics, const double low,
                                   const double high)
    {
      std::size_t count = 0;
      for (const double l : poles)
        for (unsigned int k = harmonics + 1; k <= 2 * harmonics; ++k)
          {
            const double w = std::sqrt(l) / k;
            count += (w >= low && w <= high) ? 1 : 0;
          }
      return count;
    }
  } // namespace

  DoubledHarmonicsCheck check_with_doubled_harmonics(const Discretisation &model, const ReceptanceParameters &receptance,
                                                     const BranchParameters &branch, const Backbone &backbone,
                                                     const std::vector<double> &estimates, const double band)
  {
    DoubledHarmonicsCheck check;
    const unsigned int    harmonics = branch.harmonic_balance.harmonics;
    check.harmonics                 = 2 * harmonics;
    const std::vector<std::size_t> sample = spread_main_points(backbone, doubled_samples);
    if (sample.empty())
      return check;
    HarmonicBalanceParameters more = branch.harmonic_balance, between = branch.harmonic_balance;
    more.harmonics                 = 2 * harmonics;
    between.harmonics              = harmonics + harmonics / 2;
    const Receptance gamma(model, receptance, 2 * band);
    HarmonicBalance  doubled(more, branch.contact, gamma), halfway(between, branch.contact, gamma);
    SameMotionSolve  solve(doubled, more), step(halfway, between);
    std::vector<double> changes, estimated;
    for (const std::size_t i : sample)
      {
        if (point_stop_signal() != 0)
          break;
        const BackbonePoint &p = backbone.points[i];
        ++check.sampled;
        double change = solve.energy_change(p, padded(p.x, doubled.n_unknowns()));
        if (!std::isfinite(change))
          if (const NewtonResult r = step.solve(p, padded(p.x, halfway.n_unknowns())); r.converged)
            change = solve.energy_change(p, padded(r.x, doubled.n_unknowns()));
        check.points.push_back(i);
        check.changes.push_back(change);
        if (!std::isfinite(change))
          continue;
        changes.push_back(change);
        if (i < estimates.size() && std::isfinite(estimates[i]))
          estimated.push_back(estimates[i]);
      }
    check.found           = changes.size();
    check.median_change   = median(changes);
    check.median_estimate = median(estimated);
    double low = std::numeric_limits<double>::infinity(), high = 0;
    for (const BackbonePoint &p : backbone.points)
      if (p.branch == Branch::main)
        {
          low  = std::min(low, p.omega);
          high = std::max(high, p.omega);
        }
    check.resonances = resonances_between(gamma.poles(), harmonics, low, high);
    return check;
  }

  std::string doubled_harmonics_summary(const DoubledHarmonicsCheck &check)
  {
    std::ostringstream s;
    s.precision(2);
    s << "the estimate checked with 2M = " << check.harmonics << " harmonics at " << check.sampled
      << " main points spread evenly, Newton from each point's own harmonics (through 3M/2 where 2M alone fails): ";
    if (check.found == 0)
      return s.str() + "none found again on the same motion";
    s << "|E(M) / E(2M) - 1| median " << 100 * check.median_change << " % over the " << check.found
      << " found again on the same motion";
    if (std::isfinite(check.median_estimate))
      s << ", where the estimate reads a median " << 100 * check.median_estimate << " %";
    s << "; " << check.resonances << " resonances w_j / k with " << check.harmonics / 2 << " < k <= "
      << check.harmonics << " lie on the main branch's range, which neither M / 2 nor M holds";
    return s.str();
  }

  std::string doubled_harmonics_warning(const DoubledHarmonicsCheck &check)
  {
    if (!(check.median_change > under_read_factor * check.median_estimate))
      return "";
    std::ostringstream s;
    s.precision(2);
    s << "the estimate under-reads: with 2M = " << check.harmonics << " the energies move by a median "
      << 100 * check.median_change << " %, more than " << under_read_factor << " times the estimate's "
      << 100 * check.median_estimate << " % at the same points; harmonics above M = " << check.harmonics / 2
      << " matter on this branch: raise Harmonic balance/Harmonics";
    return s.str();
  }
} // namespace nsm
