#include <nsm/base/assertions.h>
#include <nsm/base/dense_lu.h>
#include <nsm/harmonic_balance/forced_harmonic_balance.h>
#include <nsm/harmonic_balance/trigonometric.h>
#include <nsm/harmonic_balance/trigonometric_series.h>

#include <algorithm>
#include <cmath>

namespace nsm
{
  namespace
  {
    /// Golden-section steps that refine the largest sample of |u| to the
    /// rounding of the series (the bracket shrinks by 0.618 per step, from
    /// two sample spacings: 2^-52 of it after 75).
    constexpr unsigned int refinement_steps = 80;
  } // namespace

  ForcedHarmonicBalance::ForcedHarmonicBalance(const HarmonicBalanceParameters &params,
                                               const ContactParameters         &contact,
                                               const DampedReceptance          &receptance)
    : receptance_(receptance)
    , harmonics_(params.harmonics)
    , law_(contact)
    , beta_(law_.rigid() ? 1.0 : 0.0)
    , gamma0_(receptance.undamped()(0.0).gamma)
    , force_scale_(law_.gap() / gamma0_)
    , functions_(harmonic_basis(harmonics_, /*with_sines=*/true))
    , active_set_(functions_, params.integration, active_set_samples(params))
  {}

  void ForcedHarmonicBalance::set_forcing(const double amplitude) { forcing_ = amplitude; }

  void ForcedHarmonicBalance::set_omega(const double omega)
  {
    if (omega == omega_)
      return;
    omega_ = omega;
    gamma_.assign(harmonics_ + 1, gamma0_);
    gamma_slope_.assign(harmonics_ + 1, 0.0);
    for (unsigned int k = 1; k <= harmonics_; ++k)
      {
        const DampedReceptance::Value value = receptance_.value(k * omega);
        gamma_[k]       = value.gamma;
        gamma_slope_[k] = double(k) * value.slope;
      }
    // At the contact end the drive's response is gamma_d(W), evaluated above.
    const DampedReceptance::Value drive =
      receptance_.distributed_drive() || harmonics_ == 0 ? receptance_.drive(omega) :
                                                          DampedReceptance::Value{gamma_[1], gamma_slope_[1]};
    drive_       = drive.gamma;
    drive_slope_ = drive.slope;
  }

  void ForcedHarmonicBalance::add_drive(const std::complex<double> &h, const double f, std::vector<double> &u) const
  {
    if (harmonics_ == 0)
      return;
    u[2] += f * h.real();
    u[1] -= f * h.imag();
  }

  std::vector<double> ForcedHarmonicBalance::apply(const std::vector<std::complex<double>> &values,
                                                  const std::vector<double>               &y) const
  {
    AssertDimension(y.size(), n_unknowns());
    Assert(values.size() == harmonics_ + 1,
           ExcPrecondition("ForcedHarmonicBalance: set_omega() before a solution is evaluated"));
    std::vector<double> u(y.size());
    u[0] = values[0].real() * y[0];
    for (unsigned int k = 1; k <= harmonics_; ++k)
      {
        const double a = y[2 * k], b = y[2 * k - 1]; // cos, sin
        const double gr = values[k].real(), gi = values[k].imag();
        u[2 * k]     = gr * a + gi * b;
        u[2 * k - 1] = gr * b - gi * a;
      }
    return u;
  }

  std::vector<double> ForcedHarmonicBalance::wall_force(const std::vector<double> &x) const
  {
    std::vector<double> p(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      p[i] = -law_.sign() * force_scale_ * x[i];
    return p;
  }

  std::vector<double> ForcedHarmonicBalance::displacement(const std::vector<double> &x) const
  {
    std::vector<double> u = apply_receptance(wall_force(x));
    add_drive(drive_, forcing_, u);
    return u;
  }

  std::vector<double> ForcedHarmonicBalance::contact_coefficients(const std::vector<double> &x) const
  {
    // q = beta lambda - a (g0 - u), scaled by F_s: g0 / F_s = gamma(0).
    const std::vector<double> u = displacement(x);
    const double              a = law_.gap_weight();
    std::vector<double>       v(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      v[i] = beta_ * x[i] + a * u[i] / force_scale_;
    v[0] -= a * gamma0_;
    return v;
  }

  void ForcedHarmonicBalance::evaluate(const std::vector<double> &x,
                                       std::vector<double>       *residual,
                                       std::vector<double>       *jacobian,
                                       std::vector<double>       *domega) const
  {
    const unsigned int        n    = n_unknowns();
    const std::vector<double> v    = contact_coefficients(x);
    const StructuredGram     &gram = active_set_.gram(v);
    if (residual)
      {
        gram.multiply(v, *residual);
        for (unsigned int i = 0; i < n; ++i)
          (*residual)[i] = x[i] - (*residual)[i];
      }
    if (jacobian)
      {
        // Column j of J: e_j - G B e_j, B = beta I - a s Gamma (dv/dx), whose
        // column j has two entries: those of j's harmonic k (rows 2k - 1 and
        // 2k; row 0 for k = 0).
        const std::vector<double> &dense = gram.dense();
        const double               a     = law_.gap_weight() * law_.sign();
        jacobian->assign(std::size_t(n) * n, 0.0);
        for (unsigned int j = 0; j < n; ++j)
          {
            double      *column = &(*jacobian)[std::size_t(j) * n];
            const auto   add    = [&](const unsigned int l, const double b) {
              for (unsigned int i = 0; i < n; ++i)
                column[i] -= dense[std::size_t(i) * n + l] * b;
            };
            if (j == 0)
              add(0, beta_ - a * gamma0_);
            else
              {
                const unsigned int k = (j + 1) / 2, sine = 2 * k - 1, cosine = 2 * k;
                const double gr = gamma_[k].real(), gi = gamma_[k].imag();
                // Gamma e_cos = (g_r, -g_i) on (cos, sin); Gamma e_sin = (g_i, g_r).
                const bool   is_sine = j == sine;
                add(cosine, (j == cosine ? beta_ : 0.0) - a * (is_sine ? gi : gr));
                add(sine, (is_sine ? beta_ : 0.0) - a * (is_sine ? gr : -gi));
              }
            column[j] += 1;
          }
      }
    if (domega)
      {
        // dv/dW = a (dGamma/dW P + F dH_d/dW e_cos1) / F_s at fixed x.
        std::vector<double> dv = apply(gamma_slope_, wall_force(x));
        add_drive(drive_slope_, forcing_, dv);
        for (double &d : dv)
          d *= law_.gap_weight() / force_scale_;
        gram.multiply(dv, *domega);
        for (double &d : *domega)
          d = -d;
      }
  }

  std::vector<double> ForcedHarmonicBalance::dforcing(const std::vector<double> &x) const
  {
    std::vector<double> dv(n_unknowns(), 0.0), result;
    add_drive(drive_, 1.0, dv);
    for (double &d : dv)
      d *= law_.gap_weight() / force_scale_;
    active_set_.gram(contact_coefficients(x)).multiply(dv, result);
    for (double &d : result)
      d = -d;
    return result;
  }

  double ForcedHarmonicBalance::largest_magnitude(const std::vector<double> &coefficients) const
  {
    std::vector<double> samples;
    active_set_.sample(coefficients, samples);
    unsigned int best = 0;
    for (unsigned int s = 1; s < samples.size(); ++s)
      if (std::abs(samples[s]) > std::abs(samples[best]))
        best = s;
    const double              spacing = two_pi / samples.size();
    const TrigonometricSeries series(functions_, coefficients);
    const auto                size = [&](double tau) { return std::abs(series(tau, nullptr)); };
    double       low = (best - 1.0) * spacing, high = (best + 1.0) * spacing;
    const double ratio = (std::sqrt(5.0) - 1) / 2;
    double       c = high - ratio * (high - low), d = low + ratio * (high - low);
    double       size_c = size(c), size_d = size(d);
    // Each step keeps one inner point and its size, and evaluates one new.
    for (unsigned int step = 0; step < refinement_steps; ++step)
      if (size_c > size_d)
        {
          high   = d;
          d      = c;
          size_d = size_c;
          c      = high - ratio * (high - low);
          size_c = size(c);
        }
      else
        {
          low    = c;
          c      = d;
          size_c = size_d;
          d      = low + ratio * (high - low);
          size_d = size(d);
        }
    return std::max(std::abs(samples[best]), size((low + high) / 2));
  }

  double ForcedHarmonicBalance::compliant_wall_energy(const std::vector<double> &u) const
  {
    if (law_.rigid())
      return 0;
    std::vector<double> samples;
    active_set_.sample(u, samples);
    double sum = 0;
    for (const double value : samples)
      sum += law_.stored_energy(value);
    return sum / samples.size();
  }

  double ForcedHarmonicBalance::contact_fraction(const std::vector<double> &x) const
  {
    return active_set_.gram(contact_coefficients(x)).share();
  }

  bool ForcedHarmonicBalance::stable(const std::vector<double> &x) const
  {
    std::vector<double> jacobian;
    evaluate(x, nullptr, &jacobian);
    const int        n = n_unknowns();
    std::vector<int> pivots(n);
    return lu_factor(n, jacobian.data(), pivots.data()) && lu_determinant_sign(n, jacobian.data(), pivots.data()) > 0;
  }

  ForcedMeasures ForcedHarmonicBalance::measure(const std::vector<double> &x) const
  {
    ForcedMeasures            m;
    const std::vector<double> p = wall_force(x);
    const std::vector<double> u = displacement(x);
    // Parseval per harmonic: a static P_0 stores gamma(0) P_0^2 / 2; a
    // harmonic |P_k|^2 / 4 times the damped receptance's energy factor, and
    // the first the drive's cross and self terms besides.
    m.energy           = 0.5 * gamma0_ * p[0] * p[0];
    m.dissipated_power = 0;
    for (unsigned int k = 1; k <= harmonics_; ++k)
      {
        const double size = p[2 * k] * p[2 * k] + p[2 * k - 1] * p[2 * k - 1];
        m.energy += 0.25 * size * receptance_.energy_factor(k * omega_);
        m.dissipated_power += 0.5 * size * receptance_.dissipation_factor(k * omega_);
      }
    if (harmonics_ > 0)
      {
        const DampedReceptance::DriveFactors energy = receptance_.drive_energy_factors(omega_);
        const DampedReceptance::DriveFactors power  = receptance_.drive_dissipation_factors(omega_);
        const double                         f = forcing_, cross = 2 * f * p[2];
        m.energy += 0.25 * (cross * energy.cross + f * f * energy.self);
        m.dissipated_power += 0.5 * (cross * power.cross + f * f * power.self);
      }
    m.energy += compliant_wall_energy(u);
    m.tip_amplitude = largest_magnitude(u);
    if (harmonics_ > 0)
      {
        // The drive's power, F W / 2 times the sine coefficient of f^T u:
        // H_d applied to the wall's first harmonic (as Gamma's block), and
        // the drive's own share.
        const double load_sine = drive_.real() * p[1] - drive_.imag() * p[2] -
                                 forcing_ * receptance_.drive_self(omega_).imag();
        m.phase       = std::atan2(u[1], u[2]);
        m.input_power = 0.5 * forcing_ * omega_ * load_sine;
      }
    m.contact_fraction = contact_fraction(x);
    std::vector<double> force(x.size()), samples;
    for (unsigned int i = 0; i < x.size(); ++i)
      force[i] = force_scale_ * x[i];
    active_set_.sample(force, samples);
    m.max_contact_force = samples.empty() ? 0.0 : *std::max_element(samples.begin(), samples.end());
    return m;
  }
} // namespace nsm
