// Closed-form references for the bars whose linear problem is solved
// exactly (method.md section 2): the uniform bar, by trigonometric functions,
// and the linearly tapered bar, by Bessel functions of order 0 and 1; and the
// uniform bar's first nonsmooth mode. Studies measure errors against them.
#pragma once

#include <nsm/model/bar_model.h>
#include <nsm/model/contact_law.h>

#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  class ExactBar
  {
  public:
    /// The exact solution of `bar` if A(x) is constant or linear in x (to
    /// 1e-13 relative on 65 samples), with a taper A(L) / A(0) outside
    /// [1 - 1e-3, 1 + 1e-3] for the Bessel form, which loses digits as the
    /// taper vanishes; none otherwise.
    static std::optional<ExactBar> of(const BarModel &bar);

    /// "uniform (tan)" or "linear taper (Bessel)".
    std::string name() const;

    /// The first `count` clamped-free eigenfrequencies.
    std::vector<double> clamped_free_frequencies(unsigned int count) const;

    /// gamma(w): the end displacement under a unit harmonic end force.
    double receptance(double omega) const;

    /// The energy of the uniform bar's first nonsmooth mode at Omega against
    /// the rigid wall of `law` with the physical force sign:
    /// E A g0^2 / (2 L (T' - 3)^2), T' = 2 pi c / (Omega L) in (3, 4). None for
    /// a taper, another wall or sign, or outside that range.
    std::optional<double> first_mode_energy(double omega, const ContactLaw &law) const;

    /// The bar is uniform and `law` a rigid wall with the physical sign: the
    /// first nonsmooth mode is known (in its range of Omega).
    bool knows_first_mode(const ContactLaw &law) const { return uniform_ && law.rigid() && law.sign() > 0; }

  private:
    ExactBar(const BarModel &bar, double section_0, double section_L);

    /// The clamped-free frequency equation in k = w / c; its roots are the
    /// eigenfrequencies over c.
    double clamped_free_determinant(double k) const;

    double length_, young_, wave_speed_;
    double section_0_, section_L_;
    bool   uniform_;
    double s_0_, s_L_; ///< Bessel argument scale: s = A(x) / |A'| at 0 and L
  };
} // namespace nsm
