#include <nsm/harmonic_balance/constants.h>
#include <nsm/harmonic_balance/active_set.h>

#include <algorithm>
#include <cmath>

namespace nsm
{
  namespace
  {
    /// q(t_s) = sum_i v_i phi_i(t_s) on the samples (table row-major, one
    /// row of `samples` per basis function): contiguous axpys, built for AVX2
    /// and FMA where the processor has them (GCC function multiversioning).
    __attribute__((target_clones("arch=x86-64-v3", "default"))) void
    sample_series(const unsigned int n, const unsigned int samples, const double *__restrict v,
                  const double *__restrict table, double *__restrict q)
    {
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int t = 0; t < samples; ++t)
          q[t] += v[i] * table[std::size_t(i) * samples + t];
    }

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
  {
    const unsigned int harmonics = basis_.order.empty() ? 0 : basis_.order.back();
    top_ = 2 * harmonics + 1;
    table_.resize(basis_.size() * samples_);
    std::vector<double> c, s;
    for (unsigned int t = 0; t < samples_; ++t)
      {
        trig_table(two_pi * t / samples_, harmonics + 1, c, s);
        for (unsigned int i = 0; i < basis_.size(); ++i)
          table_[i * samples_ + t] = basis_.sine[i] ? s[basis_.order[i]] : c[basis_.order[i]];
      }
  }

  double ActiveSet::value(const std::vector<double> &v, const double tau, double *slope) const
  {
    // cos k tau and sin k tau by the angle-sum recurrence, basis functions
    // being ordered by k.
    const double c1 = std::cos(tau), s1 = std::sin(tau);
    double       c = 1, s = 0, q = 0, dq = 0;
    unsigned int k = 0;
    for (unsigned int i = 0; i < basis_.size(); ++i)
      {
        for (; k < basis_.order[i]; ++k)
          {
            const double next = c * c1 - s * s1;
            s = s * c1 + c * s1;
            c = next;
          }
        if (basis_.sine[i])
          q += v[i] * s, dq += v[i] * k * c;
        else
          q += v[i] * c, dq -= v[i] * k * s;
      }
    if (slope)
      *slope = dq;
    return q;
  }

  std::vector<double> ActiveSet::roots(const std::vector<double> &v) const
  {
    std::vector<double> q(samples_, 0.0);
    sample_series(basis_.size(), samples_, v.data(), table_.data(), q.data());

    // Between samples q departs from a sampled extremum by at most
    // |q''|max h^2 / 2 <= h^2 / 2 sum |v_i| k_i^2: only extrema closer to zero
    // than that can hide a crossing.
    const double h         = two_pi / samples_;
    double       curvature = 0;
    for (unsigned int i = 0; i < basis_.size(); ++i)
      curvature += std::abs(v[i]) * basis_.order[i] * basis_.order[i];
    const double reach = 0.5 * h * h * curvature;

    const auto          q_of = [&](double tau, double *slope) { return value(v, tau, slope); };
    std::vector<double> found;
    for (unsigned int t = 0; t < samples_; ++t)
      {
        const unsigned int next = (t + 1) % samples_;
        if ((q[t] > 0) != (q[next] > 0))
          found.push_back(bracketed_root(t * h, t * h + h, q[t], q[next], q_of));
        crossings_near_extremum(v, q, t, reach, found);
      }
    for (double &r : found)
      r = std::fmod(r + two_pi, two_pi);
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end(),
                            [](double x, double y) { return std::abs(x - y) < harmonic_balance_constants::root_tolerance; }),
                found.end());
    return found;
  }

  void ActiveSet::crossings_near_extremum(const std::vector<double> &v, const std::vector<double> &q,
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
    value(v, lo, &s_lo);
    value(v, hi, &s_hi);
    if ((s_lo > 0) == (s_hi > 0))
      return;
    const auto q_of = [&](double tau, double *slope) { return value(v, tau, slope); };
    // q' with its own slope q'', for the extremum between samples.
    const auto dq_of = [&](double tau, double *slope) {
      const double e = harmonic_balance_constants::extremum_slope_step;
      double       d0, dp, dm;
      value(v, tau, &d0);
      if (slope)
        {
          value(v, tau + e, &dp);
          value(v, tau - e, &dm);
          *slope = (dp - dm) / (2 * e);
        }
      return d0;
    };
    const double extremum   = bracketed_root(lo, hi, s_lo, s_hi, dq_of);
    const double q_extremum = value(v, extremum, nullptr);
    if ((q_extremum > 0) == (q[t] > 0))
      return;
    found.push_back(bracketed_root(lo, extremum, q[prev], q_extremum, q_of));
    found.push_back(bracketed_root(extremum, hi, q_extremum, q[next], q_of));
  }

  double ActiveSet::gram_exact(const std::vector<double> &v, std::vector<double> &gram) const
  {
    const unsigned int n = basis_.size(), top = top_;
    const std::vector<double> r = roots(v);
    std::vector<std::pair<double, double>> intervals;
    if (r.empty())
      {
        if (value(v, 0.0, nullptr) > 0)
          intervals.emplace_back(0.0, two_pi);
      }
    else
      for (std::size_t i = 0; i < r.size(); ++i)
        {
          const double a = r[i], b = i + 1 < r.size() ? r[i + 1] : r[0] + two_pi;
          if (value(v, 0.5 * (a + b), nullptr) > 0)
            intervals.emplace_back(a, b);
        }

    // Integrals of cos m tau and sin m tau over the active set.
    std::vector<double> ic(top, 0.0), is(top, 0.0), ca, sa, cb, sb;
    double              measure = 0;
    for (const auto &[a, b] : intervals)
      {
        measure += b - a;
        trig_table(a, top, ca, sa);
        trig_table(b, top, cb, sb);
        ic[0] += b - a;
        for (unsigned int m = 1; m < top; ++m)
          {
            ic[m] += (sb[m] - sa[m]) / m;
            is[m] += (ca[m] - cb[m]) / m;
          }
      }
    gram.assign(n * n, 0.0);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double norm = (basis_.order[i] == 0 ? 1.0 : 2.0) / two_pi;
        for (unsigned int j = 0; j < n; ++j)
          product_terms(basis_.sine[i], basis_.order[i], basis_.sine[j], basis_.order[j],
                        [&](bool sine_term, int m, double coefficient) {
                          gram[i * n + j] += norm * coefficient * (sine_term ? is[m] : ic[m]);
                        });
      }
    return measure / two_pi;
  }

  double ActiveSet::gram_sampled(const std::vector<double> &v, std::vector<double> &gram) const
  {
    const unsigned int        n = basis_.size();
    std::vector<unsigned int> active;
    for (unsigned int t = 0; t < samples_; ++t)
      {
        double q = 0;
        for (unsigned int i = 0; i < n; ++i)
          q += v[i] * table_[i * samples_ + t];
        if (q > 0)
          active.push_back(t);
      }
    gram.assign(n * n, 0.0);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double norm = (basis_.order[i] == 0 ? 1.0 : 2.0) / samples_;
        for (unsigned int j = i; j < n; ++j)
          {
            double sum = 0;
            for (const unsigned int t : active)
              sum += table_[i * samples_ + t] * table_[j * samples_ + t];
            gram[i * n + j] = norm * sum;
            gram[j * n + i] = (basis_.order[j] == 0 ? 1.0 : 2.0) / samples_ * sum;
          }
      }
    return double(active.size()) / samples_;
  }

  double ActiveSet::gram(const std::vector<double> &v, std::vector<double> &gram) const
  {
    if (v != cached_coefficients_)
      {
        cached_fraction_ = integration_ == Integration::exact ?
                             gram_exact(v, cached_gram_) :
                             gram_sampled(v, cached_gram_);
        cached_coefficients_ = v;
      }
    gram = cached_gram_;
    return cached_fraction_;
  }
} // namespace nsm
