// The law between the bar's end and the wall, in one place: the gap, the
// contact force's sign convention, the wall (rigid or compliant) and the
// form the harmonic balance solves. The harmonic balance, the solution
// measures, the time integrator and the references all ask it; a researcher
// who changes the law changes this unit (doc/method.md, "The wall").
//
// With u the contact node's displacement, the gap is g = g0 - u. The rigid
// wall's law, lambda >= 0, g >= 0, lambda g = 0, and the compliant wall's,
// lambda = k max(-g, 0), are both written
//     -lambda + max(beta lambda - a g, 0) = 0,
// with (beta, a) = (1, alpha) for the rigid wall and (0, k) for the compliant
// one. The receptance gamma gives the displacement of a contact force:
// u = -s gamma lambda, with s = +1 for the physical sign (the wall pushes the
// bar in -x) and s = -1 for the paper's eq. (5) read literally.
#pragma once

#include <nsm/scene/contact_parameters.h>

#include <string>
#include <vector>

namespace nsm
{
  class ContactLaw
  {
  public:
    explicit ContactLaw(const ContactParameters &contact);

    /// g0.
    double gap() const { return gap_; }
    /// a: alpha for the rigid wall, k for the compliant one.
    double gap_weight() const { return gap_weight_; }
    /// s: +1 with the physical force sign, -1 with the paper's eq. (5).
    double sign() const { return sign_; }
    bool   rigid() const { return rigid_; }

    /// g = g0 - u.
    double gap_at(const double u) const { return gap_ - u; }

    /// The contact node lies beyond the wall's undeformed face.
    bool penetrates(const double u) const { return u > gap_; }

    /// With gamma = tan(theta) and the unknown c of one harmonic, lambda's
    /// coefficient is c cos(theta) and u's is -s c sin(theta), so that
    /// q = beta lambda - a g has the coefficient c D on it, with
    /// D = beta cos(theta) - s a sin(theta).
    double indicator_weight(const double cos, const double sin) const
    {
      return force_weight_ * cos - sign_ * gap_weight_ * sin;
    }

    /// dD / dtheta.
    double indicator_weight_slope(const double cos, const double sin) const
    {
      return -force_weight_ * sin - sign_ * gap_weight_ * cos;
    }

    /// u = -s gamma lambda: the displacement of a force lambda where the
    /// receptance is gamma.
    double displacement(const double gamma, const double force) const { return -sign_ * gamma * force; }

    /// u's coefficient -s c sin(theta) of a harmonic with unknown c.
    double displacement_coefficient(const double c, const double sin) const { return -sign_ * c * sin; }

    /// The force f (positive along +x) that the wall adds to a time step
    /// whose contact node would reach u free of it, where a unit force moves
    /// that node by `response` in the step: the node then ends at
    /// u + f response, on the wall's face for the rigid wall, and for the
    /// compliant one where f = -k (u_end - g0). 0 where u does not penetrate.
    double step_force(const double u, const double response) const
    {
      return penetrates(u) ? gap_at(u) / (response + compliance_) : 0.0;
    }

    /// d step_force / du: the wall's force's change with the free motion.
    double step_force_slope(const double u, const double response) const
    {
      return penetrates(u) ? -1 / (response + compliance_) : 0.0;
    }

    /// The energy the wall stores at displacement u: k max(u - g0, 0)^2 / 2
    /// (0 for the rigid wall).
    double stored_energy(const double u) const
    {
      return rigid() || !penetrates(u) ? 0.0 : 0.5 * gap_weight_ * gap_at(u) * gap_at(u);
    }

    /// "Contact/Wall stiffness = k is ... times the bar's static end
    /// stiffness 1 / gamma(0)" (compliant wall; gamma0 = gamma(0)).
    std::string stiffness_note(double gamma0) const;

    /// The cosine coefficients a_0..a_M of a compliant wall's force under
    /// u = amplitude cos(tau), amplitude > g0: the clipped cosine
    /// k max(amplitude cos(tau) - g0, 0), in closed form.
    std::vector<double> clipped_force_harmonics(double amplitude, unsigned int harmonics) const;

  private:
    bool   rigid_;
    double gap_;
    double force_weight_; ///< beta: 1 rigid, 0 compliant
    double gap_weight_;   ///< a: alpha rigid, k compliant
    double compliance_;   ///< 1 / k; 0 for the rigid wall
    double sign_;
  };
} // namespace nsm
