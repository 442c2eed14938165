// The Signorini law between the bar's end and the rigid wall, in one place:
// the gap, the contact force's sign convention and the augmented form the
// harmonic balance solves. The harmonic balance, the solution measures and
// the time integrator all ask it; a researcher who changes the law changes
// this unit (doc/architecture.md).
//
// With u the contact node's displacement, the gap is g = g0 - u and the law
// reads lambda >= 0, g >= 0, lambda g = 0, written as
//     -lambda + max(lambda - alpha g, 0) = 0.
// The receptance gamma gives the displacement of a contact force: u = -s
// gamma lambda, with s = +1 for the physical sign (the wall pushes the bar in
// -x) and s = -1 for the paper's eq. (5) read literally.
#pragma once

#include <nsm/scene/scene.h>

namespace nsm
{
  class ContactLaw
  {
  public:
    explicit ContactLaw(const Scene::Contact &contact);

    /// g0.
    double gap() const { return gap_; }
    double alpha() const { return alpha_; }
    /// s: +1 with the physical force sign, -1 with the paper's eq. (5).
    double sign() const { return sign_; }

    /// g = g0 - u.
    double gap_at(const double u) const { return gap_ - u; }

    /// The contact node lies beyond the wall.
    bool penetrates(const double u) const { return u > gap_; }

    /// With gamma = tan(theta) and the unknown c of one harmonic, lambda's
    /// coefficient is c cos(theta) and u's is -s c sin(theta), so that
    /// q = lambda - alpha g has the coefficient c D on it, with
    /// D = cos(theta) - s alpha sin(theta).
    double indicator_weight(const double cos, const double sin) const { return cos - sign_ * alpha_ * sin; }

    /// dD / dtheta.
    double indicator_weight_slope(const double cos, const double sin) const
    {
      return -sin - sign_ * alpha_ * cos;
    }

    /// u = -s gamma lambda: the displacement of a force lambda where the
    /// receptance is gamma.
    double displacement(const double gamma, const double force) const { return -sign_ * gamma * force; }

    /// u's coefficient -s c sin(theta) of a harmonic with unknown c.
    double displacement_coefficient(const double c, const double sin) const { return -sign_ * c * sin; }

  private:
    double gap_;
    double alpha_;
    double sign_;
  };
} // namespace nsm
