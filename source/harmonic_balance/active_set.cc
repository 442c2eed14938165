#include <nsm/harmonic_balance/constants.h>
#include <nsm/harmonic_balance/active_set.h>
#include <nsm/base/assertions.h>

#include <algorithm>
#include <cmath>

namespace nsm
{
  unsigned int active_set_samples(const HarmonicBalanceParameters &params)
  {
    constexpr unsigned int per_harmonic = harmonic_balance_constants::bracketing_samples_per_harmonic;
    return params.integration == Integration::sampled ? params.samples() :
                                                        per_harmonic * params.harmonics + per_harmonic;
  }

  namespace
  {
    /// Safeguarded Newton on a bracket [a, b] where f changes sign, from the
    /// regula falsi point, to root_tolerance in tau. f(x, &slope) returns f
    /// and sets f'.
    template <typename F>
    double bracketed_root(double a, double b, double fa, const double fb, const F &f)
    {
      double x = fb != fa ? a - fa * (b - a) / (fb - fa) : 0.5 * (a + b);
      if (!(x > a && x < b))
        x = 0.5 * (a + b);
      for (int it = 0; it < harmonic_balance_constants::root_iterations; ++it)
        {
          double       slope;
          const double fx = f(x, &slope);
          if (fx == 0)
            return x;
          if ((fx < 0) == (fa < 0))
            a = x, fa = fx;
          else
            b = x;
          const double newton = x - fx / slope;
          // Converged: x is then a bracket end itself, so the last step may
          // leave the bracket by a rounding error (testing for inside first
          // bisected it down to the tolerance, about 10 more evaluations per root).
          if (slope != 0 && std::abs(newton - x) <= harmonic_balance_constants::root_tolerance)
            return std::clamp(newton, a, b);
          const bool inside = slope != 0 && newton > a && newton < b;
          x                 = inside ? newton : 0.5 * (a + b);
          if (b - a <= harmonic_balance_constants::root_tolerance)
            return x;
        }
      return x;
    }
  } // namespace

  ActiveSet::ActiveSet(TrigonometricBasis basis, const Integration integration, const unsigned int samples)
    : basis_(std::move(basis))
    , integration_(integration)
    , samples_(samples)
    , sampler_(basis_, samples)
    , cached_gram_(basis_)
  {}

  double ActiveSet::value(const std::vector<double> &v, const double tau, double *slope) const
  {
    return TrigonometricSeries(basis_, v)(tau, slope);
  }

  std::vector<double> ActiveSet::roots(const std::vector<double> &v) const
  {
    return roots(v, TrigonometricSeries(basis_, v));
  }

  std::vector<double> ActiveSet::roots(const std::vector<double> &v, const TrigonometricSeries &series) const
  {
    std::vector<double> q;
    sampler_(v, q);

    // Between samples q departs from a sampled extremum by at most
    // |q''|max h^2 / 2 <= h^2 / 2 sum |v_i| k_i^2: only extrema closer to zero
    // than that can hide a crossing.
    const double h         = two_pi / samples_;
    double       curvature = 0;
    for (unsigned int i = 0; i < basis_.size(); ++i)
      curvature += std::abs(v[i]) * basis_.order[i] * basis_.order[i];
    const double reach = 0.5 * h * h * curvature;

    std::vector<double> found;
    for (unsigned int t = 0; t < samples_; ++t)
      {
        const unsigned int next = (t + 1) % samples_;
        if ((q[t] > 0) != (q[next] > 0))
          found.push_back(bracketed_root(t * h, t * h + h, q[t], q[next], series));
        crossings_near_extremum(series, q, t, reach, found);
      }
    for (double &r : found)
      r = std::fmod(r + two_pi, two_pi);
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end(),
                            [](double x, double y) { return std::abs(x - y) < harmonic_balance_constants::root_tolerance; }),
                found.end());
    return found;
  }

  void ActiveSet::crossings_near_extremum(const TrigonometricSeries &series, const std::vector<double> &q,
                                          const unsigned int t, const double reach,
                                          std::vector<double> &found) const
  {
    // An extremum towards zero between sign-consistent samples may still
    // cross zero (a contact shorter than a sample spacing).
    const unsigned int next = (t + 1) % samples_, prev = (t + samples_ - 1) % samples_;
    const bool peak   = q[t] <= 0 && q[prev] <= 0 && q[next] <= 0 && q[t] >= q[prev] && q[t] >= q[next];
    const bool trough = q[t] > 0 && q[prev] > 0 && q[next] > 0 && q[t] <= q[prev] && q[t] <= q[next];
    if (!(peak || trough) || std::abs(q[t]) > reach)
      return;
    // The parabola through the three samples estimates the extremum; only
    // one that comes within half of |q_t| of zero is searched exactly.
    const double curve = q[prev] - 2 * q[t] + q[next];
    const double apex  = curve != 0 ? q[t] - (q[next] - q[prev]) * (q[next] - q[prev]) / (8 * curve) : q[t];
    if (std::abs(apex) > 0.5 * std::abs(q[t]) && (apex > 0) == (q[t] > 0))
      return;
    const double h  = two_pi / samples_;
    double       lo = t * h - h, hi = t * h + h, s_lo, s_hi;
    series(lo, &s_lo);
    series(hi, &s_hi);
    if ((s_lo > 0) == (s_hi > 0))
      return;
    // q' with its own slope q'', for the extremum between samples.
    const auto dq_of = [&](double tau, double *slope) {
      const double e = harmonic_balance_constants::extremum_slope_step;
      double       d0, dp, dm;
      series(tau, &d0);
      if (slope)
        {
          series(tau + e, &dp);
          series(tau - e, &dm);
          *slope = (dp - dm) / (2 * e);
        }
      return d0;
    };
    const double extremum   = bracketed_root(lo, hi, s_lo, s_hi, dq_of);
    const double q_extremum = series(extremum, nullptr);
    if ((q_extremum > 0) == (q[t] > 0))
      return;
    found.push_back(bracketed_root(lo, extremum, q[prev], q_extremum, series));
    found.push_back(bracketed_root(extremum, hi, q_extremum, q[next], series));
  }

  void ActiveSet::gram_exact(const std::vector<double> &v) const
  {
    const TrigonometricSeries              series(basis_, v);
    const std::vector<double>              r = roots(v, series);
    std::vector<std::pair<double, double>> intervals;
    if (r.empty())
      {
        if (series(0.0, nullptr) > 0)
          intervals.emplace_back(0.0, two_pi);
      }
    else
      for (std::size_t i = 0; i < r.size(); ++i)
        {
          const double a = r[i], b = i + 1 < r.size() ? r[i + 1] : r[0] + two_pi;
          if (series(0.5 * (a + b), nullptr) > 0)
            intervals.emplace_back(a, b);
        }
    cached_gram_.set_intervals(intervals);
  }

  void ActiveSet::gram_sampled(const std::vector<double> &v) const
  {
    std::vector<double> q;
    sampler_(v, q);
    std::vector<unsigned int> active;
    for (unsigned int t = 0; t < samples_; ++t)
      if (q[t] > 0)
        active.push_back(t);
    cached_gram_.set_samples(active, samples_);
  }

  const StructuredGram &ActiveSet::gram(const std::vector<double> &v) const
  {
    AssertDimension(v.size(), basis_.size());
    if (v != cached_coefficients_)
      {
        if (integration_ == Integration::exact)
          gram_exact(v);
        else
          gram_sampled(v);
        cached_coefficients_ = v;
      }
    return cached_gram_;
  }
} // namespace nsm
