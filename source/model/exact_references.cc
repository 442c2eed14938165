#include <nsm/model/exact_references.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace nsm
{
  namespace
  {
    double j0(const double z) { return std::cyl_bessel_j(0.0, z); }
    double j1(const double z) { return std::cyl_bessel_j(1.0, z); }
    double y0(const double z) { return std::cyl_neumann(0.0, z); }
    double y1(const double z) { return std::cyl_neumann(1.0, z); }

    /// Root of f in [a, b], where f changes sign, to machine precision.
    template <typename F>
    double bisect(const F &f, double a, double b)
    {
      double fa = f(a);
      while (b - a > 4 * std::numeric_limits<double>::epsilon() * b)
        {
          const double m = 0.5 * (a + b), fm = f(m);
          if (m <= a || m >= b)
            break;
          if ((fm < 0) == (fa < 0))
            a = m, fa = fm;
          else
            b = m;
        }
      return 0.5 * (a + b);
    }
  } // namespace

  std::optional<ExactBar> ExactBar::of(const BarModel &bar)
  {
    const double L = bar.length(), a0 = bar.cross_section(0), aL = bar.cross_section(L);
    const double scale = std::max(a0, aL);
    for (unsigned int i = 0; i <= 64; ++i)
      {
        const double x = L * i / 64;
        if (std::abs(bar.cross_section(x) - (a0 + (aL - a0) * x / L)) > 1e-13 * scale)
          return std::nullopt;
      }
    const double taper = std::abs(aL - a0) / scale;
    if (taper > 1e-13 && taper < 1e-3)
      return std::nullopt;
    return ExactBar(bar, a0, aL);
  }

  ExactBar::ExactBar(const BarModel &bar, const double section_0, const double section_L)
    : length_(bar.length())
    , young_(bar.young_modulus())
    , wave_speed_(std::sqrt(bar.young_modulus() / bar.density()))
    , section_0_(section_0)
    , section_L_(section_L)
    , uniform_(std::abs(section_L - section_0) <= 1e-13 * std::max(section_0, section_L))
  {
    const double slope = std::abs(section_L - section_0) / length_;
    s_0_ = uniform_ ? 0 : section_0 / slope;
    s_L_ = uniform_ ? 0 : section_L / slope;
  }

  std::string ExactBar::name() const
  {
    return uniform_ ? "uniform (tan)" : "linear taper (Bessel)";
  }

  double ExactBar::clamped_free_determinant(const double k) const
  {
    return j0(k * s_0_) * y1(k * s_L_) - y0(k * s_0_) * j1(k * s_L_);
  }

  std::vector<double> ExactBar::clamped_free_frequencies(const unsigned int count) const
  {
    std::vector<double> w;
    if (uniform_)
      {
        for (unsigned int j = 1; j <= count; ++j)
          w.push_back((j - 0.5) * M_PI * wave_speed_ / length_);
        return w;
      }
    // Roots in k lie about pi / L apart: 32 grid steps between two of them.
    const double step = M_PI / (32 * length_);
    const auto   f    = [this](const double k) { return clamped_free_determinant(k); };
    for (double a = step, fa = f(a); w.size() < count; a += step)
      {
        const double fb = f(a + step);
        if ((fa < 0) != (fb < 0))
          w.push_back(wave_speed_ * bisect(f, a, a + step));
        fa = fb;
      }
    return w;
  }

  double ExactBar::receptance(const double omega) const
  {
    const double k = omega / wave_speed_;
    if (uniform_)
      return k == 0 ? length_ / (young_ * section_L_) :
                      std::tan(k * length_) / (young_ * section_L_ * k);
    const double slope = (section_L_ - section_0_) / length_;
    if (k == 0)
      return std::log(section_L_ / section_0_) / (young_ * slope);
    // u = c1 J0(k s) + c2 Y0(k s): u(0) = 0 and E A(L) u'(L) = 1, with
    // u' = sign(A') du/ds and d/ds J0(k s) = -k J1(k s).
    const double sign = slope > 0 ? 1 : -1;
    const double a11 = j0(k * s_0_), a12 = y0(k * s_0_);
    const double f   = -sign * young_ * section_L_ * k;
    const double a21 = f * j1(k * s_L_), a22 = f * y1(k * s_L_);
    const double det = a11 * a22 - a12 * a21;
    const double c1 = -a12 / det, c2 = a11 / det;
    return c1 * j0(k * s_L_) + c2 * y0(k * s_L_);
  }

  std::optional<double> ExactBar::first_mode_energy(const double omega, const ContactLaw &law) const
  {
    const double period = 2 * M_PI * wave_speed_ / (omega * length_);
    if (!knows_first_mode(law) || period <= 3 || period >= 4)
      return std::nullopt;
    const double gap = law.gap();
    return young_ * section_0_ * gap * gap / (2 * length_ * (period - 3) * (period - 3));
  }
} // namespace nsm
