#include <nsm/harmonic_balance/trigonometric.h>
#include <nsm/verification/forced_time_verification.h>

#include <algorithm>
#include <cmath>
#include <complex>

namespace nsm
{
  namespace
  {
    /// Each mode's state and its weights.
    struct Mode
    {
      double residue, drive, eigenvalue, damping;
      double q, v, a;
    };

    /// The modes at t = 0 from the wall's force's harmonics p (the forced
    /// harmonic balance's basis) and the drive F at W: q_j = Re (sum_k r_j
    /// P_k / d_jk + s_j F / d_j1).
    std::vector<Mode> initial_modes(const DampedReceptance &receptance, const std::vector<double> &p,
                                    const double omega, const double forcing)
    {
      const ModalData    &modes = receptance.undamped().modes();
      std::vector<Mode>   result;
      const unsigned int  harmonics = (p.size() - 1) / 2;
      for (unsigned int j = 0; j < modes.eigenvalues.size(); ++j)
        {
          const double r = modes.contact_residues[j], s = receptance.drive_weights()[j];
          const double l = modes.eigenvalues[j], c = receptance.coefficients()[j];
          Mode         m{r, s, l, c, r * p[0] / l, 0, 0};
          for (unsigned int k = 1; k <= harmonics; ++k)
            {
              const double         w = k * omega;
              std::complex<double> force(r * p[2 * k], -r * p[2 * k - 1]);
              if (k == 1)
                force += s * forcing;
              const std::complex<double> response = force / std::complex<double>(l - w * w, c * w);
              m.q += response.real();
              m.v += (std::complex<double>(0, w) * response).real();
            }
          result.push_back(m);
        }
      return result;
    }

    /// The wall's force's series at tau = 0.
    double value_at_zero(const std::vector<double> &p)
    {
      double sum = p[0];
      for (std::size_t i = 2; i < p.size(); i += 2)
        sum += p[i];
      return sum;
    }
  } // namespace

  unsigned int steady_state_periods(const DampedReceptance &receptance, const double omega, const unsigned int limit)
  {
    const double rate = receptance.slowest_decay();
    if (!(rate > 0))
      return limit;
    const double periods =
      std::ceil(std::log(1 / forced_verification_constants::transient_share) / (rate * two_pi / omega));
    return periods >= limit ? limit : std::max(1u, static_cast<unsigned int>(periods));
  }

  ForcedVerification verify_forced_point(const ForcedHarmonicBalance &hb, const std::vector<double> &x,
                                         const unsigned int steps, const unsigned int periods)
  {
    const DampedReceptance &receptance = hb.receptance();
    const ContactLaw       &law        = hb.law();
    const double            omega = hb.omega(), forcing = hb.forcing();
    const double            far   = receptance.undamped().remainder(0).gamma;
    const DampedReceptance::DriveFactors drive_far = receptance.drive_far_static();
    const double            dt    = two_pi / omega / steps;
    const std::vector<double> start = hb.wall_force(x);
    std::vector<Mode>       modes = initial_modes(receptance, start, omega, forcing);
    double                  force = value_at_zero(start);
    for (Mode &m : modes)
      m.a = m.residue * force + m.drive * forcing - m.damping * m.v - m.eigenvalue * m.q;

    std::vector<double> previous(steps, 0.0), current(steps, 0.0);
    ForcedVerification  result{0, 0, 0, periods};
    std::vector<double> constant(modes.size()), slope(modes.size());
    for (unsigned int period = 0; period < periods; ++period)
      {
        const bool last = period + 1 == periods;
        double     energy = 0;
        for (unsigned int n = 0; n < steps; ++n)
          {
            // Per mode, q_{n+1} = A_j + B_j P_{n+1} (Newmark, average
            // acceleration), the drive's term in A_j.
            const double t     = (double(period) * steps + n + 1) * dt;
            const double drive = forcing * std::cos(omega * t);
            double u_free = drive_far.cross * drive, response = far;
            for (std::size_t j = 0; j < modes.size(); ++j)
              {
                const Mode  &m         = modes[j];
                const double predicted = m.q + dt * m.v + dt * dt / 4 * m.a;
                const double rest      = m.damping * (m.v + dt / 2 * m.a) + m.eigenvalue * predicted;
                const double scale     = 1 + m.damping * dt / 2 + m.eigenvalue * dt * dt / 4;
                constant[j]            = predicted - dt * dt / 4 * (rest - m.drive * drive) / scale;
                slope[j]               = dt * dt / 4 * m.residue / scale;
                u_free += constant[j];
                response += slope[j];
              }
            force    = law.step_force(u_free, response);
            double u = u_free + response * force;
            if (law.rigid() && force != 0)
              u = law.gap(); // on the wall's face, not one rounding beyond it
            for (std::size_t j = 0; j < modes.size(); ++j)
              {
                Mode        &m = modes[j];
                const double q = constant[j] + slope[j] * force;
                const double a = 4 / (dt * dt) * (q - m.q - dt * m.v) - m.a;
                m.v += dt / 2 * (m.a + a);
                m.q = q;
                m.a = a;
              }
            current[n] = u;
            if (last)
              {
                double e = 0.5 * (far * force * force + 2 * drive_far.cross * force * drive +
                                  drive_far.self * drive * drive) +
                           law.stored_energy(u);
                for (const Mode &m : modes)
                  if (m.residue > 0)
                    e += 0.5 * (m.v * m.v + m.eigenvalue * m.q * m.q) / m.residue;
                energy += e;
                result.tip_amplitude = std::max(result.tip_amplitude, std::abs(u));
                if (periods > 1)
                  result.drift = std::max(result.drift, std::abs(u - previous[n]) / law.gap());
              }
          }
        if (last)
          result.energy = energy / steps;
        previous.swap(current);
      }
    return result;
  }
} // namespace nsm
