#include <nsm/harmonic_balance/trigonometric.h>
#include <nsm/verification/forced_modal_steps.h>

#include <cmath>
#include <complex>

namespace nsm
{
  namespace
  {
    /// Newmark's average acceleration over one step of dt for a mode of
    /// damping c and eigenvalue l (scale = 1 + c dt / 2 + l dt^2 / 4):
    /// q_{n+1} without the wall's force's share, the force `load` (the
    /// drive's, or 0 for a tangent) in it.
    double step_constant(const double q, const double v, const double a, const double damping,
                         const double eigenvalue, const double load, const double dt, const double scale)
    {
      const double h         = dt * dt / 4;
      const double predicted = q + dt * v + h * a;
      const double rest      = damping * (v + dt / 2 * a) + eigenvalue * predicted;
      return predicted - h * (rest - load) / scale;
    }

    /// The step's end from q_{n+1}: a_{n+1} and v_{n+1} by Newmark.
    void advance(double &q, double &v, double &a, const double q_next, const double dt)
    {
      const double a_next = 4 / (dt * dt) * (q_next - q - dt * v) - a;
      v += dt / 2 * (a + a_next);
      q = q_next;
      a = a_next;
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

  ForcedModalSteps::ForcedModalSteps(const ForcedHarmonicBalance &hb, const std::vector<double> &x,
                                     const unsigned int steps)
    : law_(hb.law())
    , omega_(hb.omega())
    , forcing_(hb.forcing())
    , far_(hb.receptance().undamped().remainder(0).gamma)
    , dt_(two_pi / hb.omega() / steps)
    , drive_far_(hb.receptance().drive_far_static())
  {
    // The modes at t = 0 from the wall's force's harmonics p and the drive
    // F at W: q_j = Re (sum_k r_j P_k / d_jk + s_j F / d_j1), and the
    // accelerations that the equation of motion gives with P(0).
    const DampedReceptance   &receptance = hb.receptance();
    const ModalData          &modes      = receptance.undamped().modes();
    const std::vector<double> p          = hb.wall_force(x);
    const unsigned int        harmonics  = (p.size() - 1) / 2;
    force_                               = value_at_zero(p);
    drive_                               = forcing_;
    u_                                   = far_ * force_ + drive_far_.cross * drive_;
    for (unsigned int j = 0; j < modes.eigenvalues.size(); ++j)
      {
        const double r = modes.contact_residues[j], s = receptance.drive_weights()[j];
        const double l = modes.eigenvalues[j], c = receptance.coefficients()[j];
        Mode         m{r, s, l, c, r * p[0] / l, 0, 0};
        for (unsigned int k = 1; k <= harmonics; ++k)
          {
            const double         w = k * omega_;
            std::complex<double> force(r * p[2 * k], -r * p[2 * k - 1]);
            if (k == 1)
              force += s * forcing_;
            const std::complex<double> response = force / std::complex<double>(l - w * w, c * w);
            m.q += response.real();
            m.v += (std::complex<double>(0, w) * response).real();
          }
        m.a = r * force_ + s * forcing_ - c * m.v - l * m.q;
        u_ += m.q;
        modes_.push_back(m);
      }
    // Newmark's scale 1 + c dt / 2 + w^2 dt^2 / 4 per mode, the response
    // B_j = dt^2 / 4 r_j / scale of q_{n+1} to P_{n+1}, and u(L)'s, far +
    // sum_j B_j: the same at every step.
    const double h = dt_ * dt_ / 4;
    response_      = far_;
    for (const Mode &m : modes_)
      {
        scale_.push_back(1 + m.damping * dt_ / 2 + m.eigenvalue * h);
        slope_.push_back(h * m.residue / scale_.back());
        response_ += slope_.back();
      }
    constant_.resize(modes_.size());
  }

  std::vector<double> ForcedModalSteps::state() const
  {
    std::vector<double> z(2 * modes_.size());
    for (std::size_t j = 0; j < modes_.size(); ++j)
      {
        z[j]                 = modes_[j].q;
        z[modes_.size() + j] = modes_[j].v;
      }
    return z;
  }

  void ForcedModalSteps::restart(const std::vector<double> &z)
  {
    // u(L, 0) = sum_j q_j + far P + h F, and the wall's force is the one
    // that balances it: the step's closed form with the static response.
    step_        = 0;
    drive_       = forcing_;
    double u_free = drive_far_.cross * drive_;
    for (std::size_t j = 0; j < modes_.size(); ++j)
      {
        modes_[j].q = z[j];
        modes_[j].v = z[modes_.size() + j];
        u_free += modes_[j].q;
      }
    force_ = law_.step_force(u_free, far_);
    u_     = u_free + far_ * force_;
    for (Mode &m : modes_)
      m.a = m.residue * force_ + m.drive * drive_ - m.damping * m.v - m.eigenvalue * m.q;
  }

  ForcedModalSteps::Tangent ForcedModalSteps::start_tangent(const unsigned int j, const bool velocity) const
  {
    const std::size_t n = modes_.size();
    Tangent           d{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
    (velocity ? d.v : d.q)[j] = 1;
    // u(L, 0) = sum_k q_k + far P + h F: the wall's force moves with the
    // free motion sum_k q_k as a step's does with the static response.
    const double dforce = velocity ? 0.0 : law_.step_force_slope(u_ - far_ * force_, far_);
    for (std::size_t k = 0; k < n; ++k)
      d.a[k] = modes_[k].residue * dforce - modes_[k].damping * d.v[k] - modes_[k].eigenvalue * d.q[k];
    return d;
  }

  double ForcedModalSteps::step(std::vector<Tangent> *tangents)
  {
    // Per mode, q_{n+1} = A_j + B_j P_{n+1} (Newmark, average
    // acceleration), the drive's term in A_j.
    const double dt = dt_;
    ++step_;
    drive_          = forcing_ * std::cos(omega_ * double(step_) * dt);
    const double response = response_;
    double       u_free   = drive_far_.cross * drive_;
    for (std::size_t j = 0; j < modes_.size(); ++j)
      {
        const Mode &m = modes_[j];
        constant_[j]  = step_constant(m.q, m.v, m.a, m.damping, m.eigenvalue, m.drive * drive_, dt, scale_[j]);
        u_free += constant_[j];
      }
    force_ = law_.step_force(u_free, response);
    u_     = u_free + response * force_;
    if (law_.rigid() && force_ != 0)
      u_ = law_.gap(); // on the wall's face, not one rounding beyond it
    if (tangents)
      {
        const double        dforce = law_.step_force_slope(u_free, response);
        std::vector<double> dconstant(modes_.size());
        for (Tangent &d : *tangents)
          {
            double du_free = 0;
            for (std::size_t j = 0; j < modes_.size(); ++j)
              {
                const Mode &m = modes_[j];
                dconstant[j]  = step_constant(d.q[j], d.v[j], d.a[j], m.damping, m.eigenvalue, 0.0, dt, scale_[j]);
                du_free += dconstant[j];
              }
            const double df = dforce * du_free;
            for (std::size_t j = 0; j < modes_.size(); ++j)
              advance(d.q[j], d.v[j], d.a[j], dconstant[j] + slope_[j] * df, dt);
          }
      }
    for (std::size_t j = 0; j < modes_.size(); ++j)
      {
        Mode &m = modes_[j];
        advance(m.q, m.v, m.a, constant_[j] + slope_[j] * force_, dt);
      }
    return u_;
  }

  double ForcedModalSteps::energy() const
  {
    double e = 0.5 * (far_ * force_ * force_ + 2 * drive_far_.cross * force_ * drive_ +
                      drive_far_.self * drive_ * drive_) +
               law_.stored_energy(u_);
    for (const Mode &m : modes_)
      if (m.residue > 0)
        e += 0.5 * (m.v * m.v + m.eigenvalue * m.q * m.q) / m.residue;
    return e;
  }
} // namespace nsm
