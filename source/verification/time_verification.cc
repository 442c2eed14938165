#include <nsm/base/interruption.h>
#include <nsm/base/progress.h>
#include <nsm/model/mass_redistribution.h>
#include <nsm/verification/time_verification.h>

#include <algorithm>
#include <cmath>

namespace nsm
{
  namespace
  {
    dealii::SparseMatrix<double> copy_of(const dealii::SparseMatrix<double> &matrix)
    {
      dealii::SparseMatrix<double> copy(matrix.get_sparsity_pattern());
      copy.copy_from(matrix);
      return copy;
    }

    dealii::SparseMatrix<double> clamped_stiffness(const Discretisation &d)
    {
      dealii::SparseMatrix<double> stiffness = copy_of(d.stiffness());
      ContactTimeIntegrator::constrain_clamp(stiffness, d.clamped_dof());
      return stiffness;
    }
  } // namespace

  dealii::SparseMatrix<double> redistributed_mass(const Discretisation &d)
  {
    dealii::SparseMatrix<double> mass = copy_of(d.mass());
    redistribute_contact_mass(mass, d.contact_dof());
    return mass;
  }

  ContactTimeIntegrator::ContactTimeIntegrator(const Discretisation &discretisation,
                                               const ContactLaw     &law,
                                               const double          period,
                                               const unsigned int    steps_per_period)
    : law_(law)
    , dt_(period / steps_per_period)
    , steps_(steps_per_period)
    , contact_(discretisation.contact_dof())
    , clamp_(discretisation.clamped_dof())
    , mass_(redistributed_mass(discretisation))
    , stiffness_(clamped_stiffness(discretisation))
    , step_solver_(step_matrix())
    , static_solver_(stiffness_)
    , mass_solver_(inertia_matrix())
    , contact_response_(discretisation.n_dofs())
  {
    contact_response_[contact_] = 1;
    step_solver_.solve(contact_response_);
  }

  dealii::SparseMatrix<double> ContactTimeIntegrator::step_matrix() const
  {
    dealii::SparseMatrix<double> matrix = copy_of(mass_);
    matrix *= 4 / (dt_ * dt_);
    matrix.add(1.0, stiffness_);
    constrain_clamp(matrix, clamp_);
    return matrix;
  }

  dealii::SparseMatrix<double> ContactTimeIntegrator::inertia_matrix() const
  {
    dealii::SparseMatrix<double> matrix = copy_of(mass_);
    matrix.set(contact_, contact_, 1.0);
    constrain_clamp(matrix, clamp_);
    return matrix;
  }

  void ContactTimeIntegrator::constrain_clamp(dealii::SparseMatrix<double> &matrix, const unsigned int clamp)
  {
    for (auto e = matrix.begin(clamp); e != matrix.end(clamp); ++e)
      {
        if (e->column() != clamp)
          matrix.set(e->column(), clamp, 0.0);
        e->value() = e->column() == clamp ? 1.0 : 0.0;
      }
  }

  void ContactTimeIntegrator::make_admissible(dealii::Vector<double> &u) const
  {
    u[clamp_] = 0;
    // A compliant wall's spring holds any penetration.
    if (!law_.rigid() || !law_.penetrates(u[contact_]))
      return;
    dealii::Vector<double> shape(u.size());
    shape[contact_] = 1;
    static_solver_.solve(shape);
    u.add(law_.gap_at(u[contact_]) / shape[contact_], shape);
    u[contact_] = law_.gap(); // exactly on the wall, not one rounding beyond it
  }

  double ContactTimeIntegrator::energy(const dealii::Vector<double> &u, const dealii::Vector<double> &v) const
  {
    return (mass_.matrix_norm_square(v) + stiffness_.matrix_norm_square(u)) / 2 + law_.stored_energy(u[contact_]);
  }

  double ContactTimeIntegrator::step(dealii::Vector<double> &u, dealii::Vector<double> &v,
                                     dealii::Vector<double> &a) const
  {
    // Newmark, average acceleration, equilibrium at t_{n+1}:
    // (4/dt^2 M~ + K) u_{n+1} = M~ (4/dt^2 (u_n + dt v_n) + a_n) + lambda_{n+1} e_N.
    dealii::Vector<double> predicted(u), next(u.size());
    predicted.add(dt_, v);
    predicted *= 4 / (dt_ * dt_);
    predicted += a;
    mass_.vmult(next, predicted);
    next[clamp_] = 0;
    step_solver_.solve(next);
    // Free of the wall unless that puts the contact DoF beyond it; then
    // lambda is the wall's force at the step's end (ContactLaw::step_force).
    const double lambda = law_.step_force(next[contact_], contact_response_[contact_]);
    if (lambda != 0)
      {
        next.add(lambda, contact_response_);
        if (law_.rigid())
          next[contact_] = law_.gap(); // exactly on the wall, not one rounding beyond it
      }
    // a_{n+1} = 4/dt^2 (u_{n+1} - u_n - dt v_n) - a_n, v_{n+1} = v_n + dt/2 (a_n + a_{n+1})
    dealii::Vector<double> acceleration(next);
    acceleration -= u;
    acceleration.add(-dt_, v);
    acceleration *= 4 / (dt_ * dt_);
    acceleration -= a;
    v.add(dt_ / 2, a, dt_ / 2, acceleration);
    a.swap(acceleration);
    u.swap(next);
    return lambda;
  }

  dealii::Vector<double> ContactTimeIntegrator::initial_acceleration(const dealii::Vector<double> &u) const
  {
    // M~ a_0 = -K u_0 on the DoFs with inertia; the contact DoF has none.
    dealii::Vector<double> a(u.size());
    stiffness_.vmult(a, u);
    a *= -1;
    a[contact_] = 0;
    a[clamp_]   = 0;
    mass_solver_.solve(a);
    return a;
  }

  TimeVerification ContactTimeIntegrator::run(const dealii::Vector<double> &u0,
                                              const dealii::Vector<double> &v0,
                                              const unsigned int            periods) const
  {
    dealii::Vector<double> u(u0), v(v0), a = initial_acceleration(u0);
    v[clamp_] = 0;
    const double     e0 = energy(u, v);
    TimeVerification result{0, 0, 0, 0, 0, e0};
    unsigned long    in_contact = 0;
    const auto       defect = [&] {
      double d = 0;
      for (unsigned int i = 0; i < u.size(); ++i)
        d = std::max(d, std::abs(u[i] - u0[i]));
      return d / law_.gap();
    };
    for (unsigned int p = 0; p < periods; ++p)
      {
        for (unsigned int n = 0; n < steps_; ++n)
          {
            const double lambda = step(u, v, a);
            result.impulse += -lambda * dt_;
            in_contact += lambda < 0;
          }
        if (p == 0)
          result.periodicity_defect = defect();
      }
    result.periodicity_defect_end = defect();
    result.energy_drift           = (energy(u, v) - e0) / e0;
    result.impulse /= periods;
    result.contact_fraction = double(in_contact) / (double(steps_) * periods);
    return result;
  }

  PointVerification verify_in_time(const PeriodicField &field, const Discretisation &discretisation,
                                   const ContactLaw &law, const OutputParameters &o)
  {
    const ContactTimeIntegrator integrator(discretisation, law, field.period(), o.verify_steps);
    dealii::Vector<double>      u = field.displacement(0.0);
    integrator.make_admissible(u);
    PointVerification result{integrator.run(u, field.velocity(0.0), o.verify_periods), 0, false};
    // The HB's impulse per period: T times the mean contact force.
    const FourierCoefficients &c = field.coefficients();
    for (std::size_t i = 0; i < c.order.size(); ++i)
      if (c.order[i] == 0)
        result.impulse_ratio = result.time.impulse / (field.period() * c.force[i]);
    result.verified = result.time.periodicity_defect <= o.verify_tolerance;
    return result;
  }

  std::vector<std::optional<PointVerification>> verify_backbone(
    HarmonicBalance                                     &hb,
    const Discretisation                                &discretisation,
    const Backbone                                      &backbone,
    const OutputParameters                                 &o,
    Progress                                            &progress,
    const std::vector<std::optional<PointVerification>> &known)
  {
    std::vector<std::optional<PointVerification>> results(backbone.points.size());
    // A stop asked for leaves the remaining points unverified (empty cells).
    for (std::size_t i = 0; i < results.size() && point_stop_signal() == 0; ++i)
      if (i % o.verify_every == 0 || (o.fields_every > 0 && i % o.fields_every == 0))
        {
          if (i < known.size() && known[i])
            {
              results[i] = known[i];
              continue;
            }
          const PeriodicField field(hb, discretisation, backbone.points[i]);
          results[i] = verify_in_time(field, discretisation, hb.law(), o);
          progress.update([&] {
            return "point " + std::to_string(i + 1) + " of " + std::to_string(results.size());
          });
        }
    return results;
  }
} // namespace nsm
