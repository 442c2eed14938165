#include <nsm/verification/fields.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace nsm
{
  PeriodicField::PeriodicField(HarmonicBalance &hb, const Discretisation &discretisation, const BackbonePoint &point)
    : point_(point)
  {
    hb.set_omega(point.omega);
    coefficients_ = hb.coefficients(point.x);
    std::map<unsigned int, dealii::Vector<double>> fields; // one solve per k
    for (std::size_t i = 0; i < coefficients_.order.size(); ++i)
      {
        const unsigned int k = coefficients_.order[i];
        if (!fields.count(k))
          fields[k] = hb.receptance().field(k * point.omega);
        const dealii::Vector<double> &h     = fields[k];
        const double                  gamma = h[discretisation.contact_dof()];
        dealii::Vector<double>        u(h);
        u *= std::abs(gamma) >= 1 ? coefficients_.displacement[i] / gamma :
                                    hb.law().displacement(1.0, coefficients_.force[i]);
        harmonic_fields_.push_back(std::move(u));
      }
  }

  double PeriodicField::period() const
  {
    return 2 * M_PI / point_.omega;
  }

  std::vector<double> PeriodicField::basis(const double t, const bool derivative) const
  {
    const double        w = point_.omega;
    std::vector<double> phi(coefficients_.order.size());
    for (std::size_t i = 0; i < phi.size(); ++i)
      {
        const double k = coefficients_.order[i], a = k * w * t;
        if (derivative)
          phi[i] = coefficients_.is_sine[i] ? k * w * std::cos(a) : -k * w * std::sin(a);
        else
          phi[i] = coefficients_.is_sine[i] ? std::sin(a) : std::cos(a);
      }
    return phi;
  }

  dealii::Vector<double> PeriodicField::nodal(const double t, const bool derivative) const
  {
    const std::vector<double> phi = basis(t, derivative);
    dealii::Vector<double>    sum(harmonic_fields_[0].size());
    for (std::size_t i = 0; i < phi.size(); ++i)
      sum.add(phi[i], harmonic_fields_[i]);
    return sum;
  }

  double PeriodicField::series(const std::vector<double> &coefficients,
                               const double               t,
                               const bool                 derivative) const
  {
    const std::vector<double> phi = basis(t, derivative);
    double                    sum = 0;
    for (std::size_t i = 0; i < phi.size(); ++i)
      sum += phi[i] * coefficients[i];
    return sum;
  }

  dealii::Vector<double> PeriodicField::displacement(const double t) const
  {
    return nodal(t, false);
  }

  double PeriodicField::max_displacement(const unsigned int samples) const
  {
    double largest = 0;
    for (unsigned int s = 0; s < samples; ++s)
      largest = std::max(largest, displacement(s * period() / samples).linfty_norm());
    return largest;
  }

  dealii::Vector<double> PeriodicField::velocity(const double t) const
  {
    return nodal(t, true);
  }

  double PeriodicField::displacement(const unsigned int dof, const double t) const
  {
    return series(dof_values(dof), t, false);
  }

  double PeriodicField::velocity(const unsigned int dof, const double t) const
  {
    return series(dof_values(dof), t, true);
  }

  std::vector<double> PeriodicField::dof_values(const unsigned int dof) const
  {
    std::vector<double> values;
    for (const dealii::Vector<double> &u : harmonic_fields_)
      values.push_back(u[dof]);
    return values;
  }

  double PeriodicField::contact_force(const double t) const
  {
    return series(coefficients_.force, t, false);
  }

  double PeriodicField::contact_displacement(const double t) const
  {
    return series(coefficients_.displacement, t, false);
  }
} // namespace nsm
