#include <nsm/base/errors.h>
#include <nsm/harmonic_balance/constants.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/harmonic_balance/trigonometric.h>
#include <nsm/base/assertions.h>

#include <chrono>
#include <cmath>

namespace nsm
{
  namespace
  {
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
  } // namespace

  HarmonicBalance::HarmonicBalance(const HarmonicBalanceParameters &params, const ContactParameters &contact,
                                   const Receptance &receptance)
    : receptance_(receptance)
    , harmonics_(params.harmonics)
    , basis_(params.basis)
    , integration_(params.integration)
    , law_(contact)
    , functions_(harmonic_basis(harmonics_, basis_ == HarmonicBasis::full))
    , active_set_(functions_, integration_, active_set_samples(params))
    , measures_(harmonics_)
  {
    gamma0_       = receptance(0.0).gamma;
    force_scale_  = law_.gap() / gamma0_;
    a_gamma0_     = law_.gap_weight() * gamma0_;
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
            w *= 1 + harmonic_balance_constants::pole_offset;
            value = receptance_(w);
          }
        const double g     = value.gamma;
        const double norm  = std::sqrt(1 + g * g);
        const double flip  = receptance_.poles_below(w) % 2 ? -1.0 : 1.0;
        HarmonicPhase &phase = phases_[k];
        phase.cos            = flip / norm;
        phase.sin            = flip * g / norm;
        phase.omega2         = w * w;
        phase.dtheta_domega2 = value.dgamma_domega2 / (norm * norm);
        phase.dtheta_domega  = phase.dtheta_domega2 * 2 * k * k * omega;
      }
  }

  std::vector<double> HarmonicBalance::contact_coefficients(const std::vector<double> &x) const
  {
    AssertDimension(x.size(), n_unknowns());
    Assert(phases_.size() == harmonics_ + 1,
           ExcPrecondition("HarmonicBalance: set_omega() before a solution is evaluated"));
    std::vector<double> v(n_unknowns());
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      {
        const HarmonicPhase &p = phases_[functions_.order[i]];
        v[i] = x[i] * law_.indicator_weight(p.cos, p.sin);
      }
    if (has_unfolding())
      v[1] = 0;
    v[0] -= a_gamma0_;
    return v;
  }

  void HarmonicBalance::evaluate(const std::vector<double> &x,
                                 std::vector<double>       *residual,
                                 std::vector<double>       *jacobian,
                                 std::vector<double>       *domega) const
  {
    const unsigned int n = n_unknowns();
    Assert(residual || jacobian || domega, ExcPrecondition("HarmonicBalance::evaluate: nothing asked"));
    const ScopedTimer  timer(jacobian || domega ? cost_.jacobian_seconds : cost_.residual_seconds);
    ++(jacobian || domega ? cost_.jacobians : cost_.residuals);
    const std::vector<double> v    = contact_coefficients(x);
    const StructuredGram     &gram = active_set_.gram(v);
    const auto is_unfolding = [&](unsigned int i) { return has_unfolding() && i == 1; };

    if (residual)
      {
        gram.multiply(v, *residual);
        for (unsigned int i = 0; i < n; ++i)
          (*residual)[i] = (is_unfolding(i) ? x[i] : x[i] * phases_[functions_.order[i]].cos) - (*residual)[i];
      }
    if (jacobian)
      {
        // J = diag(cos) - G diag(D), column-major.
        const std::vector<double> &dense = gram.dense();
        jacobian->resize(std::size_t(n) * n);
        for (unsigned int j = 0; j < n; ++j)
          {
            const HarmonicPhase &p = phases_[functions_.order[j]];
            const double d = is_unfolding(j) ? 0.0 : law_.indicator_weight(p.cos, p.sin);
            for (unsigned int i = 0; i < n; ++i)
              (*jacobian)[i + std::size_t(j) * n] = -dense[std::size_t(i) * n + j] * d;
            (*jacobian)[j + std::size_t(j) * n] += is_unfolding(j) ? 1.0 : p.cos;
          }
      }
    if (domega)
      {
        // dR/dW = -x sin(theta) dtheta/dW - G (dD/dW x).
        std::vector<double> w(n, 0.0);
        for (unsigned int i = 0; i < n; ++i)
          if (!is_unfolding(i))
            {
              const HarmonicPhase &p = phases_[functions_.order[i]];
              w[i] = law_.indicator_weight_slope(p.cos, p.sin) * p.dtheta_domega * x[i];
            }
        gram.multiply(w, *domega);
        for (unsigned int i = 0; i < n; ++i)
          {
            (*domega)[i] = -(*domega)[i];
            if (!is_unfolding(i))
              {
                const HarmonicPhase &p = phases_[functions_.order[i]];
                (*domega)[i] -= x[i] * p.sin * p.dtheta_domega;
              }
          }
      }
  }

  std::vector<double> HarmonicBalance::describing_guess() const
  {
    // With u = A cos(W t), the spring's first harmonic is a_1 = k A f(psi) / pi,
    // f(psi) = psi - sin(psi) cos(psi), cos(psi) = g0 / A; the first harmonic
    // balances where A = -s gamma_1 a_1, so f(psi) = pi / (-s gamma_1 k).
    const double target = M_PI / (-law_.sign() * phases_[1].sin / phases_[1].cos * law_.gap_weight());
    if (!(target > 0 && target < M_PI / 2))
      return {};
    double low = 0, high = M_PI / 2;
    for (int i = 0; i < 60; ++i)
      {
        const double psi = (low + high) / 2;
        (psi - std::sin(psi) * std::cos(psi) < target ? low : high) = psi;
      }
    const std::vector<double> a = law_.clipped_force_harmonics(law_.gap() / std::cos(low), harmonics_);
    std::vector<double>       x(n_unknowns(), 0.0);
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      if (!functions_.sine[i])
        x[i] = a[functions_.order[i]] / phases_[functions_.order[i]].cos / force_scale_; // c = a / cos(theta)
    return x;
  }

  std::vector<double> HarmonicBalance::grazing_guess() const
  {
    if (!law_.rigid())
      return describing_guess();
    // lambda = I delta(tau): a_0 = I / (2 pi), a_k = I / pi (cosines); the
    // displacement at tau = 0, -s sum gamma_k a_k, must equal the gap.
    double sum = 0;
    for (unsigned int k = 0; k <= harmonics_; ++k)
      sum += phases_[k].sin / phases_[k].cos / (k == 0 ? two_pi : M_PI);
    const double impulse = -law_.gap() / (law_.sign() * sum);
    if (!(impulse > 0) || !std::isfinite(impulse))
      return {};
    std::vector<double> x(n_unknowns(), 0.0);
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      if (!functions_.sine[i])
        {
          const double a = impulse / (functions_.order[i] == 0 ? two_pi : M_PI);
          x[i] = a / phases_[functions_.order[i]].cos / force_scale_; // c = a / cos(theta)
        }
    return x;
  }

  FourierCoefficients HarmonicBalance::coefficients(const std::vector<double> &x) const
  {
    AssertDimension(x.size(), n_unknowns());
    FourierCoefficients result;
    for (unsigned int i = 0; i < n_unknowns(); ++i)
      {
        const HarmonicPhase &p = phases_[functions_.order[i]];
        const double c = has_unfolding() && i == 1 ? 0.0 : force_scale_ * x[i];
        result.order.push_back(functions_.order[i]);
        result.is_sine.push_back(functions_.sine[i]);
        result.force.push_back(c * p.cos);
        result.displacement.push_back(law_.displacement_coefficient(c, p.sin));
      }
    return result;
  }

  std::vector<double> HarmonicBalance::coefficients_only(const std::vector<double> &x) const
  {
    AssertDimension(x.size(), n_unknowns());
    std::vector<double> coefficient(x);
    if (has_unfolding())
      coefficient[1] = 0;
    return coefficient;
  }

  std::vector<double> HarmonicBalance::harmonic_energies(const std::vector<double> &x) const
  {
    const std::vector<double> coefficient = coefficients_only(x);
    return measures_.harmonic_energies({functions_, phases_, coefficient, force_scale_, omega_});
  }

  double HarmonicBalance::contact_fraction(const std::vector<double> &x) const
  {
    return active_set_.gram(contact_coefficients(x)).share();
  }

  PeriodicSolutionMeasures HarmonicBalance::measure(const std::vector<double> &x) const
  {
    const std::vector<double> coefficient = coefficients_only(x);
    const PhasedSolution      solution{functions_, phases_, coefficient, force_scale_, omega_};
    PeriodicSolutionMeasures  result{};
    measures_.energy(solution, law_, result);
    measures_.force_and_gap(solution, active_set_, law_, result);
    result.contact_fraction = active_set_.gram(contact_coefficients(x)).share();
    return result;
  }
} // namespace nsm
