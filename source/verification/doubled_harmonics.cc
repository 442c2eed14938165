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
#include <utility>

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

  namespace
  {
    /// A point solved with 2 M harmonics from its own unknowns, and where
    /// that fails through 3 M / 2 first: |E(M) / E(2 M) - 1|, NaN where
    /// neither finds the same motion.
    class DoubledSolve
    {
    public:
      DoubledSolve(const BranchParameters &branch, const Receptance &gamma)
        : more_(with_harmonics(branch, 2 * branch.harmonic_balance.harmonics))
        , between_(with_harmonics(branch, branch.harmonic_balance.harmonics * 3 / 2))
        , doubled_(more_, branch.contact, gamma)
        , halfway_(between_, branch.contact, gamma)
        , solve_(doubled_, more_)
        , step_(halfway_, between_)
      {}

      double energy_change(const BackbonePoint &p)
      {
        const double change = solve_.energy_change(p, padded(p.x, doubled_.n_unknowns()));
        if (std::isfinite(change))
          return change;
        const NewtonResult r = step_.solve(p, padded(p.x, halfway_.n_unknowns()));
        return r.converged ? solve_.energy_change(p, padded(r.x, doubled_.n_unknowns())) : change;
      }

    private:
      static HarmonicBalanceParameters with_harmonics(const BranchParameters &branch, const unsigned int m)
      {
        HarmonicBalanceParameters p = branch.harmonic_balance;
        p.harmonics                 = m;
        return p;
      }

      HarmonicBalanceParameters more_, between_;
      HarmonicBalance           doubled_, halfway_;
      SameMotionSolve           solve_, step_;
    };

    /// The main branch's lowest and highest Omega.
    std::pair<double, double> main_range(const Backbone &backbone)
    {
      double low = std::numeric_limits<double>::infinity(), high = 0;
      for (const BackbonePoint &p : backbone.points)
        if (p.branch == Branch::main)
          {
            low  = std::min(low, p.omega);
            high = std::max(high, p.omega);
          }
      return {low, high};
    }
  } // namespace

  DoubledHarmonicsCheck check_with_doubled_harmonics(const Discretisation &model, const ReceptanceParameters &receptance,
                                                     const BranchParameters &branch, const Backbone &backbone,
                                                     const std::vector<double> &estimates, const double band)
  {
    DoubledHarmonicsCheck check;
    check.harmonics = 2 * branch.harmonic_balance.harmonics;
    const std::vector<std::size_t> sample = spread_main_points(backbone, doubled_samples);
    if (sample.empty())
      return check;
    const Receptance    gamma(model, receptance, 2 * band);
    DoubledSolve        doubled(branch, gamma);
    std::vector<double> changes, estimated;
    for (const std::size_t i : sample)
      {
        if (point_stop_signal() != 0)
          break;
        const double change = doubled.energy_change(backbone.points[i]);
        check.points.push_back(i);
        check.changes.push_back(change);
        if (!std::isfinite(change))
          continue;
        changes.push_back(change);
        if (i < estimates.size() && std::isfinite(estimates[i]))
          estimated.push_back(estimates[i]);
      }
    check.median_change   = median(changes);
    check.median_estimate = median(estimated);
    const auto [low, high] = main_range(backbone);
    check.resonances       = resonances_between(gamma.poles(), branch.harmonic_balance.harmonics, low, high);
    return check;
  }

  std::string doubled_harmonics_summary(const DoubledHarmonicsCheck &check)
  {
    std::ostringstream s;
    s.precision(2);
    s << "the estimate checked with 2M = " << check.harmonics << " harmonics at " << check.sampled()
      << " main points spread evenly, Newton from each point's own harmonics (through 3M/2 where 2M alone fails): ";
    if (check.found() == 0)
      return s.str() + "none found again on the same motion";
    s << "|E(M) / E(2M) - 1| median " << 100 * check.median_change << " % over the " << check.found()
      << " found again on the same motion";
    if (std::isfinite(check.median_estimate))
      s << ", where the estimate reads a median " << 100 * check.median_estimate << " %";
    s << "; " << counted(check.resonances, "resonance") << " w_j / k with " << check.harmonics / 2 << " < k <= "
      << check.harmonics << (check.resonances == 1 ? " lies" : " lie")
      << " on the main branch's range, which neither M / 2 nor M holds";
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
