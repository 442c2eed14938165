#include <nsm/base/errors.h>
#include <nsm/verification/modal_flow.h>
#include <nsm/verification/time_verification.h>

#include <algorithm>
#include <cmath>

namespace nsm
{
  namespace
  {
    using Matrix = dealii::LAPACKFullMatrix<double>;

    /// The shortest step of the switch search, as a share of the lowest
    /// mode's period: a touch of the wall shorter than this can be missed.
    constexpr double min_step_share = 1e-9;
    /// Steps of one switch search before it is given up (a grazing contact
    /// that the search cannot resolve).
    constexpr unsigned long max_search_steps = 10000000;
    /// Bisections of a bracketed switch: to the last bit of double.
    constexpr unsigned int bisections = 64;
    /// Samples of the wall's force per stretch on the wall, for its maximum.
    constexpr unsigned int force_samples = 256;

    /// The submatrix of a sparse matrix on `dofs`, dense.
    Matrix restricted(const dealii::SparseMatrix<double> &m, const std::vector<unsigned int> &dofs)
    {
      std::vector<int> index(m.m(), -1);
      for (std::size_t i = 0; i < dofs.size(); ++i)
        index[dofs[i]] = int(i);
      Matrix result(dofs.size(), dofs.size());
      for (std::size_t i = 0; i < dofs.size(); ++i)
        for (auto e = m.begin(dofs[i]); e != m.end(dofs[i]); ++e)
          if (index[e->column()] >= 0)
            result(i, index[e->column()]) = e->value();
      return result;
    }

    /// y = A x.
    dealii::Vector<double> times(const Matrix &a, const dealii::Vector<double> &x)
    {
      dealii::Vector<double> y(a.m());
      a.vmult(y, x);
      return y;
    }
  } // namespace

  ModalFlow::ModalFlow(const Discretisation &discretisation, const ContactLaw &law)
    : law_(law)
    , contact_(discretisation.contact_dof())
    , clamp_(discretisation.clamped_dof())
  {
    if (!law.rigid())
      throw LogicError("ModalFlow: the exact flow follows a rigid wall's impacts only (the scene refuses "
                       "Output/Refine in time with Contact/Wall = compliant)");
    for (unsigned int i = 0; i < discretisation.n_dofs(); ++i)
      if (i != contact_ && i != clamp_)
        dofs_.push_back(i);
    mass_      = restricted(redistributed_mass(discretisation), dofs_);
    stiffness_ = restricted(discretisation.stiffness(), dofs_);
    coupling_.reinit(dofs_.size());
    for (std::size_t i = 0; i < dofs_.size(); ++i)
      coupling_[i] = discretisation.stiffness().el(dofs_[i], contact_);
    k_nn_     = discretisation.stiffness().el(contact_, contact_);
    free_     = make_regime(false);
    wall_     = make_regime(true);
    min_step_ = min_step_share * 2 * M_PI / free_.omega[0];
  }

  ModalFlow::Regime ModalFlow::make_regime(const bool on_wall) const
  {
    const std::size_t k = dofs_.size();
    Matrix            a(stiffness_), b(mass_);
    if (!on_wall) // the contact DoF condensed: K_II - K_IN K_NI / K_NN
      for (std::size_t i = 0; i < k; ++i)
        for (std::size_t j = 0; j < k; ++j)
          a(i, j) -= coupling_[i] * coupling_[j] / k_nn_;
    std::vector<dealii::Vector<double>> vectors(k, dealii::Vector<double>(k));
    a.compute_generalized_eigenvalues_symmetric(b, vectors); // Phi^T M~ Phi = I
    Regime r;
    r.modes.reinit(k, k);
    r.omega.reinit(k);
    for (std::size_t j = 0; j < k; ++j)
      {
        r.omega[j] = std::sqrt(a.eigenvalue(j).real());
        for (std::size_t i = 0; i < k; ++i)
          r.modes(i, j) = vectors[j][i];
      }
    r.projection.reinit(k, k);
    r.modes.Tmmult(r.projection, mass_);
    r.offset.reinit(k);
    r.weights.reinit(k);
    r.modes.Tvmult(r.weights, coupling_);
    if (on_wall)
      {
        // u_s = -K_II^{-1} K_IN g0; the force K_NI (u_s + Phi q) + K_NN g0.
        Matrix lu(stiffness_);
        lu.compute_lu_factorization();
        r.offset = coupling_;
        lu.solve(r.offset);
        r.offset *= -law_.gap();
        r.constant = coupling_ * r.offset + k_nn_ * law_.gap();
      }
    else
      {
        // u_N - g0 = -K_NI Phi q / K_NN - g0.
        r.weights /= -k_nn_;
        r.constant = -law_.gap();
      }
    return r;
  }

  bool ModalFlow::on_wall(const ModalState &state) const
  {
    return law_.penetrates(-(coupling_ * state.u) / k_nn_);
  }

  double ModalFlow::contact_displacement(const dealii::Vector<double> &u) const
  {
    return std::min(-(coupling_ * u) / k_nn_, law_.gap());
  }

  dealii::Vector<double> ModalFlow::nodal(const dealii::Vector<double> &u) const
  {
    dealii::Vector<double> result(dofs_.size() + 2);
    for (std::size_t i = 0; i < dofs_.size(); ++i)
      result[dofs_[i]] = u[i];
    result[contact_] = contact_displacement(u);
    return result;
  }

  double ModalFlow::strain_energy(const dealii::Vector<double> &u) const
  {
    const double u_n = contact_displacement(u);
    return (u * times(stiffness_, u)) / 2 + u_n * (coupling_ * u) + k_nn_ * u_n * u_n / 2;
  }

  double ModalFlow::kinetic_energy(const dealii::Vector<double> &v) const
  {
    return (v * times(mass_, v)) / 2;
  }

  void ModalFlow::amplitudes(const Regime &r, const ModalState &state, dealii::Vector<double> &a,
                             dealii::Vector<double> &b) const
  {
    dealii::Vector<double> shifted(state.u);
    shifted -= r.offset;
    a = times(r.projection, shifted);
    b = times(r.projection, state.v);
    for (std::size_t j = 0; j < b.size(); ++j)
      b[j] /= r.omega[j];
  }

  double ModalFlow::switch_function(const Regime &r, const dealii::Vector<double> &a, const dealii::Vector<double> &b,
                                    const double s) const
  {
    double e = r.constant;
    for (std::size_t j = 0; j < a.size(); ++j)
      e += r.weights[j] * (a[j] * std::cos(r.omega[j] * s) + b[j] * std::sin(r.omega[j] * s));
    return e;
  }

  double ModalFlow::next_switch(const Regime &r, const dealii::Vector<double> &a, const dealii::Vector<double> &b,
                                const double duration, const bool just_switched) const
  {
    // |de/dt| <= L: a step of -e / L cannot pass a root.
    double rate = 0;
    for (std::size_t j = 0; j < a.size(); ++j)
      rate += std::abs(r.weights[j]) * r.omega[j] * std::hypot(a[j], b[j]);
    double s = 0, e = switch_function(r, a, b, 0);
    if (e > 0 && !just_switched)
      return 0;
    e = std::min(e, 0.0);
    for (unsigned long count = 0; count < max_search_steps; ++count)
      {
        const double next = std::min(s + std::max(-e / rate, min_step_), duration);
        const double e_next = switch_function(r, a, b, next);
        if (e_next > 0)
          {
            double low = s, high = next;
            for (unsigned int i = 0; i < bisections && high - low > 0; ++i)
              {
                const double middle = (low + high) / 2;
                if (middle <= low || middle >= high)
                  break;
                (switch_function(r, a, b, middle) > 0 ? high : low) = middle;
              }
            return high;
          }
        if (next >= duration)
          return duration;
        s = next;
        e = e_next;
      }
    throw NumericalError("exact time integration: a contact switch could not be located (grazing contact)");
  }

  double ModalFlow::largest_force(const Regime &r, const dealii::Vector<double> &a, const dealii::Vector<double> &b,
                                  const double tau) const
  {
    double largest = 0;
    for (unsigned int i = 0; i <= force_samples; ++i)
      largest = std::max(largest, -switch_function(r, a, b, tau * i / force_samples));
    return largest;
  }

  void ModalFlow::move(const Regime &r, ModalState &state, ModalTangents *tangents, const double tau) const
  {
    dealii::Vector<double> a, b;
    amplitudes(r, state, a, b);
    const std::size_t      k = a.size();
    dealii::Vector<double> q(k), rate(k), c(k), s(k);
    for (std::size_t j = 0; j < k; ++j)
      {
        c[j]    = std::cos(r.omega[j] * tau);
        s[j]    = std::sin(r.omega[j] * tau);
        q[j]    = a[j] * c[j] + b[j] * s[j];
        rate[j] = r.omega[j] * (b[j] * c[j] - a[j] * s[j]);
      }
    state.u = times(r.modes, q);
    state.u += r.offset;
    state.v = times(r.modes, rate);
    if (!tangents)
      return;
    const std::size_t m = tangents->du.n();
    Matrix            da(k, m), dq(k, m), dq_new(k, m), dr_new(k, m);
    r.projection.mmult(da, tangents->du);
    r.projection.mmult(dq, tangents->dv); // d(Phi^T M~ v) = omega db
    for (std::size_t j = 0; j < k; ++j)
      for (std::size_t col = 0; col < m; ++col)
        {
          const double x = da(j, col), y = dq(j, col);
          dq_new(j, col) = x * c[j] + y * s[j] / r.omega[j];
          dr_new(j, col) = -r.omega[j] * x * s[j] + y * c[j];
        }
    r.modes.mmult(tangents->du, dq_new);
    r.modes.mmult(tangents->dv, dr_new);
  }

  WallRecord ModalFlow::advance(ModalState &state, const double duration, ModalTangents *tangents) const
  {
    WallRecord record;
    bool       wall = on_wall(state), just_switched = false;
    for (double t = 0; t < duration;)
      {
        const Regime          &r = wall ? wall_ : free_;
        dealii::Vector<double> a, b;
        amplitudes(r, state, a, b);
        const double tau = next_switch(r, a, b, duration - t, just_switched);
        if (wall)
          {
            record.time_on_wall += tau;
            record.max_force = std::max(record.max_force, largest_force(r, a, b, tau));
          }
        move(r, state, tangents, tau);
        t += tau;
        just_switched = t < duration;
        if (just_switched)
          {
            wall = !wall;
            ++record.switches;
          }
      }
    return record;
  }
} // namespace nsm
