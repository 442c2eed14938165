// Mode fields: the displacement u(x, t) over one period rebuilt from the
// harmonics, u(x, t) = sum_i u_i(x) phi_i(W t), each u_i a receptance field.
#pragma once

#include <nsm/continuation/continuation.h>
#include <nsm/model/discretisation.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/model/receptance.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace nsm
{
  class PeriodicField
  {
  public:
    /// u_i = h_k (b_i / gamma_k), with h_k = (K - (kW)^2 M)^{-1} e_N: the
    /// receptance field scaled to the contact displacement, bounded at a pole
    /// of gamma (where b_i stays finite); near a zero of gamma, where b_i and
    /// gamma_k both vanish, the same u_i is -s h_k a_i (hb's contact law).
    PeriodicField(HarmonicBalance &hb, const Discretisation &discretisation, const BackbonePoint &point);

    double omega() const { return point_.omega; }
    double period() const;
    const BackbonePoint       &point() const { return point_; }
    const FourierCoefficients &coefficients() const { return coefficients_; }

    /// Nodal values (DoF vector of the 1D mesh) at time t.
    dealii::Vector<double> displacement(double t) const;
    dealii::Vector<double> velocity(double t) const;

    /// Value at one DoF, for the space-time mesh.
    double displacement(unsigned int dof, double t) const;
    double velocity(unsigned int dof, double t) const;

    /// max |u| over the DoFs and the times s T / samples, s = 0 .. samples - 1.
    double max_displacement(unsigned int samples) const;

    double contact_force(double t) const;
    double contact_displacement(double t) const;

  private:
    /// phi_i(W t), or with derivative = true d phi_i / dt.
    std::vector<double> basis(double t, bool derivative) const;
    /// sum_i u_i phi_i (or phi_i') at t, as nodal values.
    dealii::Vector<double> nodal(double t, bool derivative) const;
    /// sum_i c_i phi_i (or phi_i') at t.
    double series(const std::vector<double> &coefficients, double t, bool derivative) const;
    /// u_i at one DoF, for every harmonic i.
    std::vector<double> dof_values(unsigned int dof) const;

    BackbonePoint                       point_;
    FourierCoefficients                 coefficients_;
    std::vector<dealii::Vector<double>> harmonic_fields_;
  };
} // namespace nsm
