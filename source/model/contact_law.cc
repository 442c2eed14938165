#include <nsm/model/contact_law.h>

#include <cmath>
#include <sstream>

namespace nsm
{
  ContactLaw::ContactLaw(const ContactParameters &contact)
    : rigid_(contact.wall == Wall::rigid)
    , gap_(contact.gap)
    , force_weight_(rigid_ ? 1.0 : 0.0)
    , gap_weight_(rigid_ ? contact.alpha : contact.stiffness)
    , compliance_(rigid_ ? 0.0 : 1.0 / contact.stiffness)
    , sign_(contact.sign == ForceSign::physical ? 1.0 : -1.0)
  {}

  std::string ContactLaw::stiffness_note(const double gamma0) const
  {
    std::ostringstream s;
    s.precision(6);
    s << "Contact/Wall stiffness = " << gap_weight_ << " is " << gap_weight_ * gamma0
      << " times the bar's static end stiffness 1 / gamma(0)";
    return s.str();
  }

  std::vector<double> ContactLaw::clipped_force_harmonics(const double amplitude, const unsigned int harmonics) const
  {
    // a_n = (2 k A / pi) int_0^psi (cos(t) - cos(psi)) cos(n t) dt, cos(psi) = g0 / A.
    const double        psi = std::acos(gap_ / amplitude), c = gap_ / amplitude;
    const double        scale = 2 * gap_weight_ * amplitude / M_PI;
    std::vector<double> a(harmonics + 1);
    a[0] = scale / 2 * (std::sin(psi) - psi * c);
    for (unsigned int n = 1; n <= harmonics; ++n)
      {
        const double first = n == 1 ? psi / 2 : std::sin((n - 1) * psi) / (2 * (n - 1.0));
        a[n] = scale * (first + std::sin((n + 1) * psi) / (2 * (n + 1.0)) - c * std::sin(n * psi) / n);
      }
    return a;
  }
} // namespace nsm
