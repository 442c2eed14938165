#include <nsm/harmonic_balance.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

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

    constexpr double two_pi = 2 * M_PI;

    /// Adds the wall time of its scope to a counter.
    class ScopedTimer
    {
    public:
      explicit ScopedTimer(double &seconds)
        : seconds_(seconds)
        , start_(std::chrono::steady_clock::now())
      {}
      ~ScopedTimer()
      {
        seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      }

    private:
      double                               &seconds_;
      std::chrono::steady_clock::time_point start_;
    };

    /// cos(m t) and sin(m t) for m = 0..count-1 by the angle-sum recurrence.
    void trig_table(const double t, const unsigned int count,
                    std::vector<double> &c, std::vector<double> &s)
    {
      c.resize(count);
      s.resize(count);
      const double c1 = std::cos(t), s1 = std::sin(t);
      c[0] = 1, s[0] = 0;
      for (unsigned int m = 1; m < count; ++m)
        {
          c[m] = c[m - 1] * c1 - s[m - 1] * s1;
          s[m] = s[m - 1] * c1 + c[m - 1] * s1;
        }
    }

    /// Calls add(is_sine, m, coefficient) for the expansion of the product
    /// of two basis functions (cos or sin of k tau and l tau) in cos / sin m tau.
    template <typename Add>
    void product_terms(const bool sine_k, const int k, const bool sine_l, const int l, Add &&add)
    {
      const int    d = std::abs(k - l), sgn = k >= l ? 1 : -1;
      if (!sine_k && !sine_l)
        add(false, d, 0.5), add(false, k + l, 0.5);
      else if (sine_k && sine_l)
        add(false, d, 0.5), add(false, k + l, -0.5);
      else if (sine_k) // sin k cos l = (sin(k + l) + sin(k - l)) / 2
        add(true, k + l, 0.5), add(true, d, 0.5 * sgn);
      else // cos k sin l = (sin(k + l) - sin(k - l)) / 2
        add(true, k + l, 0.5), add(true, d, -0.5 * sgn);
    }
  } // namespace

  HarmonicBalance::HarmonicBalance(const Scene &scene, const Receptance &receptance)
    : receptance_(receptance)
    , harmonics_(scene.harmonic_balance.harmonics)
    , basis_(scene.harmonic_balance.basis)
    , integration_(scene.harmonic_balance.integration)
    , sign_(scene.contact.sign == ForceSign::physical ? 1.0 : -1.0)
    , alpha_(scene.contact.alpha)
    , gap_(scene.contact.gap)
  {
    gamma0_       = receptance(0.0).gamma;
    force_scale_  = gap_ / gamma0_;
    alpha_gamma0_ = alpha_ * gamma0_;

    kinds_.push_back(cosine);
    orders_.push_back(0);
    for (unsigned int k = 1; k <= harmonics_; ++k)
      {
        if (basis_ == HarmonicBasis::full)
          {
            kinds_.push_back(sine);
            orders_.push_back(k);
          }
        kinds_.push_back(cosine);
        orders_.push_back(k);
      }

    // The exact rule samples q only to bracket its roots: 8 points per
    // period of the highest harmonic, plus the extremum checks in roots().
    samples_ = integration_ == Integration::sampled ? scene.time_samples() :
                                                      8 * harmonics_ + 8;
    table_.resize(n_unknowns() * samples_);
    std::vector<double> c, s;
    const unsigned int  top = 2 * harmonics_ + 1, points = 4 * top;
    energy_cos_.resize(top * points);
    energy_sin_.resize(top * points);
    for (unsigned int t = 0; t < points; ++t)
      {
        trig_table(two_pi * t / points, top, c, s);
        for (unsigned int m = 0; m < top; ++m)
          {
            energy_cos_[m * points + t] = c[m];
            energy_sin_[m * points + t] = s[m];
          }
      }
    for (unsigned int t = 0; t < samples_; ++t)
      {
        trig_table(two_pi * t / samples_, harmonics_ + 1, c, s);
        for (unsigned int i = 0; i < n_unknowns(); ++i)
          table_[i * samples_ + t] = kinds_[i] == sine ? s[orders_[i]] : c[orders_[i]];
      }
  }

  void HarmonicBalance::set_omega(const double omega)
  {
    if (omega == omega_)
      return;
    const ScopedTimer timer(cost_.receptance_seconds);
    cost_.frequencies += harmonics_ + 1;
    omega_ = omega;
    phases_.resize(harmonics_ + 1);
    for (unsigned int k = 0; k <= harmonics_; ++k)
      {
        double w = k * omega;
        ReceptanceValue value;
        try
          {
            value = receptance_(w);
          }
        catch (const NumericalError &)
          {
            // Exactly on a pole: theta is continuous there, so a frequency
            // 1e-13 off it gives theta to that accuracy.
            w *= 1 + 1e-13;
            value = receptance_(w);
          }
        const double g     = value.gamma;
        const double norm  = std::sqrt(1 + g * g);
        const double flip  = receptance_.poles_below(w) % 2 ? -1.0 : 1.0;
        Phase       &phase = phases_[k];
        phase.cos            = flip / norm;
        phase.sin            = flip * g / norm;
        phase.omega2         = w * w;
        phase.dtheta_domega2 = value.dgamma_domega2 / (norm * norm);
        phase.dtheta_domega  = phase.dtheta_domega2 * 2 * k * k * omega;
      }
  }

  std::vector<double> HarmonicBalance::contact_coefficients(const std::vector<double> &x) const
  {
    std::vector<double> v(n_unknowns());
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      {
        const Phase &p = phases_[orders_[i]];
        v[i] = x[i] * (p.cos - sign_ * alpha_ * p.sin);
      }
    if (has_unfolding())
      v[1] = 0;
    v[0] -= alpha_gamma0_;
    return v;
  }

  double HarmonicBalance::value(const std::vector<double> &v, const double tau, double *slope) const
  {
    // cos k tau and sin k tau by the angle-sum recurrence, basis functions
    // being ordered by k.
    const double c1 = std::cos(tau), s1 = std::sin(tau);
    double       c = 1, s = 0, q = 0, dq = 0;
    unsigned int k = 0;
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      {
        for (; k < orders_[i]; ++k)
          {
            const double next = c * c1 - s * s1;
            s = s * c1 + c * s1;
            c = next;
          }
        if (kinds_[i] == sine)
          q += v[i] * s, dq += v[i] * k * c;
        else
          q += v[i] * c, dq -= v[i] * k * s;
      }
    if (slope)
      *slope = dq;
    return q;
  }

  std::vector<double> HarmonicBalance::roots(const std::vector<double> &v) const
  {
    std::vector<double> q(samples_, 0.0);
    sample_series(n_unknowns(), samples_, v.data(), table_.data(), q.data());

    const double h = two_pi / samples_;
    // Safeguarded Newton on a bracket [a, b] where f changes sign, from the
    // regula falsi point; 1e-13 in tau leaves the Gram integrals exact to
    // far below any Newton tolerance.
    const auto refine = [&](double a, double b, double fa, const double fb, const auto &f) {
      double x = fb != fa ? a - fa * (b - a) / (fb - fa) : 0.5 * (a + b);
      if (!(x > a && x < b))
        x = 0.5 * (a + b);
      for (int it = 0; it < 60; ++it)
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
          // bisected it down to 1e-13, about 10 more evaluations per root).
          if (slope != 0 && std::abs(newton - x) <= 1e-13)
            return std::clamp(newton, a, b);
          const bool inside = slope != 0 && newton > a && newton < b;
          x                 = inside ? newton : 0.5 * (a + b);
          if (b - a <= 1e-13)
            return x;
        }
      return x;
    };
    const auto q_of = [&](double tau, double *slope) { return value(v, tau, slope); };
    // q' with its own slope q'', for the extremum between samples.
    const auto dq_of = [&](double tau, double *slope) {
      const double e = 1e-6;
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

    // Between samples q departs from a sampled extremum by at most
    // |q''|max h^2 / 2 <= h^2 / 2 sum |v_i| k_i^2: only extrema closer to zero
    // than that can hide a crossing.
    double curvature = 0;
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      curvature += std::abs(v[i]) * orders_[i] * orders_[i];
    const double reach = 0.5 * h * h * curvature;

    std::vector<double> found;
    for (unsigned int t = 0; t < samples_; ++t)
      {
        const unsigned int next = (t + 1) % samples_, prev = (t + samples_ - 1) % samples_;
        const double       a = t * h, b = a + h;
        if ((q[t] > 0) != (q[next] > 0))
          found.push_back(refine(a, b, q[t], q[next], q_of));
        // An extremum towards zero between sign-consistent samples may still
        // cross zero (a contact shorter than a sample spacing).
        const bool peak   = q[t] <= 0 && q[prev] <= 0 && q[next] <= 0 && q[t] >= q[prev] && q[t] >= q[next];
        const bool trough = q[t] > 0 && q[prev] > 0 && q[next] > 0 && q[t] <= q[prev] && q[t] <= q[next];
        if (!(peak || trough) || std::abs(q[t]) > reach)
          continue;
        // The parabola through the three samples estimates the extremum; only
        // one that comes within half of |q_t| of zero is searched exactly.
        const double curve = q[prev] - 2 * q[t] + q[next];
        const double apex  = curve != 0 ? q[t] - (q[next] - q[prev]) * (q[next] - q[prev]) / (8 * curve) : q[t];
        if (std::abs(apex) > 0.5 * std::abs(q[t]) && (apex > 0) == (q[t] > 0))
          continue;
        double lo = a - h, hi = b, s_lo, s_hi;
        value(v, lo, &s_lo);
        value(v, hi, &s_hi);
        if ((s_lo > 0) == (s_hi > 0))
          continue;
        const double extremum = refine(lo, hi, s_lo, s_hi, dq_of);
        const double q_extremum = value(v, extremum, nullptr);
        if ((q_extremum > 0) != (q[t] > 0))
          {
            found.push_back(refine(lo, extremum, q[prev], q_extremum, q_of));
            found.push_back(refine(extremum, hi, q_extremum, q[next], q_of));
          }
      }
    for (double &r : found)
      r = std::fmod(r + two_pi, two_pi);
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end(),
                            [](double x, double y) { return std::abs(x - y) < 1e-13; }),
                found.end());
    return found;
  }

  double HarmonicBalance::active_gram_exact(const std::vector<double> &v, std::vector<double> &gram) const
  {
    const unsigned int n = n_unknowns(), top = 2 * harmonics_ + 1;
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
        const double norm = (orders_[i] == 0 ? 1.0 : 2.0) / two_pi;
        for (unsigned int j = 0; j < n; ++j)
          product_terms(kinds_[i] == sine, orders_[i], kinds_[j] == sine, orders_[j],
                        [&](bool sine_term, int m, double coefficient) {
                          gram[i * n + j] += norm * coefficient * (sine_term ? is[m] : ic[m]);
                        });
      }
    return measure / two_pi;
  }

  double HarmonicBalance::active_gram_sampled(const std::vector<double> &v, std::vector<double> &gram) const
  {
    const unsigned int        n = n_unknowns();
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
        const double norm = (orders_[i] == 0 ? 1.0 : 2.0) / samples_;
        for (unsigned int j = i; j < n; ++j)
          {
            double sum = 0;
            for (const unsigned int t : active)
              sum += table_[i * samples_ + t] * table_[j * samples_ + t];
            gram[i * n + j] = norm * sum;
            gram[j * n + i] = (orders_[j] == 0 ? 1.0 : 2.0) / samples_ * sum;
          }
      }
    return double(active.size()) / samples_;
  }

  double HarmonicBalance::active_gram(const std::vector<double> &v, std::vector<double> &gram) const
  {
    if (v != cached_coefficients_)
      {
        cached_fraction_ = integration_ == Integration::exact ?
                             active_gram_exact(v, cached_gram_) :
                             active_gram_sampled(v, cached_gram_);
        cached_coefficients_ = v;
      }
    gram = cached_gram_;
    return cached_fraction_;
  }

  void HarmonicBalance::evaluate(const std::vector<double> &x,
                                 std::vector<double>       *residual,
                                 std::vector<double>       *jacobian,
                                 std::vector<double>       *domega) const
  {
    const unsigned int n = n_unknowns();
    const ScopedTimer  timer(jacobian || domega ? cost_.jacobian_seconds : cost_.residual_seconds);
    ++(jacobian || domega ? cost_.jacobians : cost_.residuals);
    const std::vector<double> v = contact_coefficients(x);
    std::vector<double>       gram;
    active_gram(v, gram);
    const auto is_unfolding = [&](unsigned int i) { return has_unfolding() && i == 1; };

    if (residual)
      {
        residual->assign(n, 0.0);
        for (unsigned int i = 0; i < n; ++i)
          {
            double projection = 0;
            for (unsigned int j = 0; j < n; ++j)
              projection += gram[i * n + j] * v[j];
            (*residual)[i] = (is_unfolding(i) ? x[i] : x[i] * phases_[orders_[i]].cos) - projection;
          }
      }
    if (jacobian)
      {
        jacobian->assign(n * n, 0.0);
        for (unsigned int j = 0; j < n; ++j)
          {
            const Phase &p = phases_[orders_[j]];
            const double d = is_unfolding(j) ? 0.0 : p.cos - sign_ * alpha_ * p.sin;
            for (unsigned int i = 0; i < n; ++i)
              (*jacobian)[i + j * n] = -gram[i * n + j] * d;
            (*jacobian)[j + j * n] += is_unfolding(j) ? 1.0 : p.cos;
          }
      }
    if (domega)
      {
        domega->assign(n, 0.0);
        for (unsigned int i = 0; i < n; ++i)
          {
            if (is_unfolding(i))
              continue;
            const Phase &p = phases_[orders_[i]];
            (*domega)[i] -= x[i] * p.sin * p.dtheta_domega;
            const double dd = (-p.sin - sign_ * alpha_ * p.cos) * p.dtheta_domega;
            for (unsigned int r = 0; r < n; ++r)
              (*domega)[r] -= gram[r * n + i] * dd * x[i];
          }
      }
  }

  std::vector<double> HarmonicBalance::grazing_guess() const
  {
    // lambda = I delta(tau): a_0 = I / (2 pi), a_k = I / pi (cosines); the
    // displacement at tau = 0, -s sum gamma_k a_k, must equal the gap.
    double sum = 0;
    for (unsigned int k = 0; k <= harmonics_; ++k)
      sum += phases_[k].sin / phases_[k].cos / (k == 0 ? two_pi : M_PI);
    const double impulse = -gap_ / (sign_ * sum);
    if (!(impulse > 0) || !std::isfinite(impulse))
      return {};
    std::vector<double> x(n_unknowns(), 0.0);
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      if (kinds_[i] == cosine)
        {
          const double a = impulse / (orders_[i] == 0 ? two_pi : M_PI);
          x[i] = a / phases_[orders_[i]].cos / force_scale_; // c = a / cos(theta)
        }
    return x;
  }

  FourierCoefficients HarmonicBalance::coefficients(const std::vector<double> &x) const
  {
    FourierCoefficients result;
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      {
        const Phase &p = phases_[orders_[i]];
        const double c = has_unfolding() && i == 1 ? 0.0 : force_scale_ * x[i];
        result.order.push_back(orders_[i]);
        result.is_sine.push_back(kinds_[i] == sine);
        result.force.push_back(c * p.cos);
        result.displacement.push_back(-sign_ * c * p.sin);
      }
    return result;
  }

  std::vector<double> HarmonicBalance::harmonic_energies(const std::vector<double> &x) const
  {
    // a^2 (gamma + 2 w^2 gamma') / 4 per cosine or sine (a_0^2 gamma(0) / 2),
    // in the angle variables a^2 gamma = c^2 sin cos, a^2 gamma' = c^2 dtheta/dw^2.
    std::vector<double> energies(harmonics_ + 1, 0.0);
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      {
        if (has_unfolding() && i == 1)
          continue;
        const Phase &p = phases_[orders_[i]];
        const double c = force_scale_ * x[i];
        energies[orders_[i]] += c * c * (p.sin * p.cos + 2 * p.omega2 * p.dtheta_domega2) /
                                (orders_[i] == 0 ? 2.0 : 4.0);
      }
    return energies;
  }

  double HarmonicBalance::contact_fraction(const std::vector<double> &x) const
  {
    std::vector<double> gram;
    return active_gram(contact_coefficients(x), gram);
  }

  PeriodicSolutionMeasures HarmonicBalance::measure(const std::vector<double> &x) const
  {
    const unsigned int  n = n_unknowns(), top = 2 * harmonics_ + 1;
    const double        f2 = force_scale_ * force_scale_, w2 = omega_ * omega_;
    std::vector<double> coefficient(n);
    for (unsigned int i = 0; i < n; ++i)
      coefficient[i] = has_unfolding() && i == 1 ? 0.0 : x[i];

    // Energy over the period as a trigonometric polynomial: with h_k the
    // receptance field, h_k^T M h_l = (gamma_k - gamma_l) / (w_k^2 - w_l^2),
    // which in the angle variables reads sin(theta_k - theta_l) / (...).
    std::vector<double> ec(top, 0.0), es(top, 0.0);
    const auto add = [&](double weight) {
      return [&, weight](bool sine, int m, double c) { (sine ? es : ec)[m] += weight * c; };
    };
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const Phase &p = phases_[orders_[i]], &q = phases_[orders_[j]];
          const double cc = coefficient[i] * coefficient[j] * f2;
          double       mass, stiffness;
          if (orders_[i] == orders_[j])
            {
              mass      = p.dtheta_domega2;
              stiffness = p.sin * p.cos + p.omega2 * p.dtheta_domega2;
            }
          else
            {
              const double d = p.omega2 - q.omega2;
              mass      = (p.sin * q.cos - p.cos * q.sin) / d;
              stiffness = (p.omega2 * p.sin * q.cos - q.omega2 * p.cos * q.sin) / d;
            }
          // strain: phi_i phi_j; kinetic: W^2 phi_i' phi_j' (derivatives in tau).
          product_terms(kinds_[i] == sine, orders_[i], kinds_[j] == sine, orders_[j],
                        add(0.5 * cc * stiffness));
          const double ki = orders_[i], kj = orders_[j];
          const double sign_i = kinds_[i] == sine ? 1.0 : -1.0, sign_j = kinds_[j] == sine ? 1.0 : -1.0;
          product_terms(kinds_[i] != sine, orders_[i], kinds_[j] != sine, orders_[j],
                        add(0.5 * cc * w2 * mass * ki * kj * sign_i * sign_j));
        }

    PeriodicSolutionMeasures result{};
    result.energy = ec[0];
    const unsigned int  points = 4 * top;
    std::vector<double> e(points, 0.0);
    for (unsigned int m = 0; m < top; ++m)
      for (unsigned int t = 0; t < points; ++t)
        e[t] += ec[m] * energy_cos_[m * points + t] + es[m] * energy_sin_[m * points + t];
    const double e_min = *std::min_element(e.begin(), e.end());
    const double e_max = *std::max_element(e.begin(), e.end());
    result.energy_spread = (e_max - e_min) / result.energy;

    // Contact force and gap at the samples.
    double lambda_max = -std::numeric_limits<double>::max(), lambda_min = -lambda_max;
    double gap_min = lambda_min, complementarity = 0;
    for (unsigned int t = 0; t < samples_; ++t)
      {
        double lambda = 0, u = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            const Phase &p = phases_[orders_[i]];
            lambda += coefficient[i] * p.cos * table_[i * samples_ + t];
            u -= sign_ * coefficient[i] * p.sin * table_[i * samples_ + t];
          }
        lambda *= force_scale_, u *= force_scale_;
        const double g = gap_ - u;
        lambda_max = std::max(lambda_max, lambda), lambda_min = std::min(lambda_min, lambda);
        gap_min = std::min(gap_min, g);
        complementarity = std::max(complementarity, std::abs(lambda * g));
      }
    std::vector<double> gram;
    result.contact_fraction    = active_gram(contact_coefficients(x), gram);
    result.max_contact_force   = lambda_max;
    result.min_force           = lambda_min / lambda_max;
    result.min_gap             = gap_min / gap_;
    result.max_complementarity = complementarity / (lambda_max * gap_);
    return result;
  }
} // namespace nsm
