#include <nsm/verification/modal_flow.h>
#include <nsm/verification/periodic_orbit.h>

#include <algorithm>
#include <cmath>

namespace nsm
{
  namespace
  {
    /// Newton steps before a shooting is given up.
    constexpr unsigned int max_newton_steps = 15;
    /// Rises of the damping before a step is given up.
    constexpr unsigned int max_damping_rises = 6;
    /// Singular values below this share of the largest are left out of the
    /// least-norm step: round-off of a Jacobian built from two dense
    /// eigenbases is about 1e-13 of its norm.
    constexpr double pseudo_inverse_cut = 1e-11;

    using Matrix = dealii::LAPACKFullMatrix<double>;

    /// k x columns, with the k x k identity from column `first` on.
    Matrix identity(const std::size_t k, const std::size_t columns, const std::size_t first)
    {
      Matrix m(k, columns);
      for (std::size_t i = 0; i < k; ++i)
        m(i, first + i) = 1;
      return m;
    }

    /// One shooting: the residual v(T/2), scaled by Omega g0, and (with the
    /// Jacobian) dv(T/2)/du(0), scaled by Omega.
    struct HalfPeriod
    {
      dealii::Vector<double> residual;
      Matrix                 jacobian;
      double                 size = 0; ///< max |residual|
      double                 merit = 0; ///< |residual|_2, which a Newton step lowers
    };

    HalfPeriod half_period(const ModalFlow &flow, const double omega, const dealii::Vector<double> &x,
                           const bool with_jacobian)
    {
      const std::size_t k = x.size();
      ModalState        s{x, dealii::Vector<double>(k)};
      ModalTangents     t{identity(k, k, 0), Matrix(k, k)};
      flow.advance(s, M_PI / omega, with_jacobian ? &t : nullptr);
      HalfPeriod h;
      h.residual = s.v;
      h.residual /= omega * flow.law().gap();
      h.size  = h.residual.linfty_norm();
      h.merit = h.residual.l2_norm();
      if (with_jacobian)
        {
          h.jacobian = t.dv;
          h.jacobian /= omega;
        }
      return h;
    }

    /// The Jacobian's singular value decomposition, for the steps.
    struct Decomposition
    {
      dealii::Vector<double> projected; ///< U^T r
      std::vector<double>    sigma;
      Matrix                 vt;
    };

    Decomposition decompose(HalfPeriod &h)
    {
      const std::size_t m = h.residual.size();
      h.jacobian.compute_svd();
      Decomposition d{dealii::Vector<double>(m), std::vector<double>(m), h.jacobian.get_svd_vt()};
      h.jacobian.get_svd_u().Tvmult(d.projected, h.residual);
      for (std::size_t i = 0; i < m; ++i)
        d.sigma[i] = h.jacobian.singular_value(i);
      return d;
    }

    /// The damped least-squares step -(J^T J + mu I)^{-1} J^T r (in units of
    /// g0); with mu = 0 the least-norm Newton step -J^+ r.
    dealii::Vector<double> damped_step(const Decomposition &d, const double mu, const double gap)
    {
      const std::size_t      m = d.sigma.size();
      dealii::Vector<double> scaled(m), step(m);
      for (std::size_t i = 0; i < m; ++i)
        if (d.sigma[i] > pseudo_inverse_cut * d.sigma[0])
          scaled[i] = -d.projected[i] * d.sigma[i] / (d.sigma[i] * d.sigma[i] + mu);
      d.vt.Tvmult(step, scaled);
      step *= gap;
      return step;
    }

    /// One whole period from the orbit's state at t = 0: its wall record,
    /// its periodicity and (if asked) its Floquet multipliers.
    void whole_period(const ModalFlow &flow, const double omega, const dealii::Vector<double> &x,
                      const OrbitSettings &settings, PeriodicOrbit &orbit)
    {
      const std::size_t k = x.size();
      ModalState        s{x, dealii::Vector<double>(k)};
      ModalTangents     t{identity(k, 2 * k, 0), identity(k, 2 * k, k)};
      const WallRecord  wall = flow.advance(s, 2 * M_PI / omega, settings.floquet ? &t : nullptr);
      orbit.contact_fraction  = wall.time_on_wall * omega / (2 * M_PI);
      orbit.max_contact_force = wall.max_force;
      orbit.switches          = wall.switches;
      dealii::Vector<double> change(s.u);
      change -= x;
      orbit.periodicity = change.linfty_norm() / flow.law().gap();
      if (!settings.floquet)
        return;
      Matrix monodromy(2 * k, 2 * k);
      for (std::size_t c = 0; c < 2 * k; ++c)
        for (std::size_t i = 0; i < k; ++i)
          {
            monodromy(i, c)     = t.du(i, c);
            monodromy(k + i, c) = t.dv(i, c);
          }
      monodromy.compute_eigenvalues();
      for (std::size_t i = 0; i < 2 * k; ++i)
        orbit.multipliers.push_back(monodromy.eigenvalue(i));
      std::sort(orbit.multipliers.begin(), orbit.multipliers.end(),
                [](const auto &a, const auto &b) { return std::abs(a - 1.0) < std::abs(b - 1.0); });
      for (const auto &m : orbit.multipliers)
        orbit.floquet_max = std::max(orbit.floquet_max, std::abs(m));
      orbit.stable = orbit.floquet_max <= 1 + settings.stability_margin;
    }

    /// Levenberg-Marquardt from x: the damping mu falls after a step that
    /// lowers |r| and rises until one does; near the orbit mu -> 0 and the
    /// steps are least-norm Newton steps. x becomes the last iterate.
    void shoot(const ModalFlow &flow, const double omega, const OrbitSettings &settings,
               dealii::Vector<double> &x, PeriodicOrbit &orbit)
    {
      HalfPeriod h  = half_period(flow, omega, x, true);
      double     mu = 0;
      for (; orbit.newton_steps < max_newton_steps; ++orbit.newton_steps)
        {
          const Decomposition d = decompose(h);
          orbit.isolation       = d.sigma.back();
          orbit.residual        = h.size;
          if (h.size <= settings.tolerance)
            {
              orbit.converged = true;
              return;
            }
          bool lower = false;
          for (unsigned int tries = 0; tries <= max_damping_rises && !lower; ++tries)
            {
              dealii::Vector<double> trial = x;
              trial += damped_step(d, mu, flow.law().gap());
              const double merit = half_period(flow, omega, trial, false).merit;
              lower = merit < h.merit;
              if (lower)
                x = trial;
              mu = lower ? mu / 10 : std::max(4 * mu, d.sigma.back() * d.sigma.back());
            }
          if (!lower)
            return;
          h = half_period(flow, omega, x, true);
        }
    }
  } // namespace

  PeriodicOrbit find_periodic_orbit(const Discretisation &discretisation, const ContactLaw &law, const double omega,
                                    const dealii::Vector<double> &guess, const OrbitSettings &settings)
  {
    const ModalFlow        flow(discretisation, law);
    dealii::Vector<double> x(flow.dofs().size());
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = guess[flow.dofs()[i]];
    PeriodicOrbit orbit;
    shoot(flow, omega, settings, x, orbit);
    orbit.displacement = flow.nodal(x);
    orbit.energy       = flow.strain_energy(x);
    if (orbit.converged)
      whole_period(flow, omega, x, settings, orbit);
    // An orbit that never reaches the wall is not a contact motion: near
    // grazing Newton can land on the bar at rest.
    if (orbit.converged && orbit.switches == 0)
      orbit.converged = false;
    return orbit;
  }
} // namespace nsm
