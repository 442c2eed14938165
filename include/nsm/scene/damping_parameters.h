// The Damping subsection: the viscous damping of the driven bar, C = alpha M +
// beta K plus one modal ratio for every mode (model/damped_receptance.h reads
// it). Only the forced response uses it; the backbone is conservative. It
// declares and parses its own entries; Scene (scene.h) composes the
// subsections.
#pragma once

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  struct DampingParameters
  {
    double modal_ratio    = 0; ///< zeta: 2 zeta w_j on mode j
    double rayleigh_alpha = 0; ///< C's share alpha M
    double rayleigh_beta  = 0; ///< C's share beta K

    /// The modal damping coefficient c_j of mode j (eigenvalue w_j^2): its
    /// modal equation is eta'' + c_j eta' + w_j^2 eta = phi_j^T f.
    double coefficient(double eigenvalue) const;

    bool any() const { return modal_ratio > 0 || rayleigh_alpha > 0 || rayleigh_beta > 0; }

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace nsm
