// Exact references for the tests (method.md section 2): the linearly tapered
// bar A(x) = 1.5 - x with E = rho = L = 1, where u = c1 J0(w s) + c2 Y0(w s),
// s = 1.5 - x, and the uniform bar, where gamma(w) = tan(w) / w.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

namespace exact
{
  inline double j0(double z) { return std::cyl_bessel_j(0.0, z); }
  inline double j1(double z) { return std::cyl_bessel_j(1.0, z); }
  inline double y0(double z) { return std::cyl_neumann(0.0, z); }
  inline double y1(double z) { return std::cyl_neumann(1.0, z); }

  inline double tapered_clamped_free(double w)
  {
    return j0(1.5 * w) * y1(0.5 * w) - y0(1.5 * w) * j1(0.5 * w);
  }

  inline double tapered_clamped_clamped(double w)
  {
    return j0(1.5 * w) * y0(0.5 * w) - y0(1.5 * w) * j0(0.5 * w);
  }

  /// gamma(w) of the bar A(x) = a - x (a > 1): u(0) = 0, E A(L) u'(L) = 1.
  inline double tapered_receptance(double w, double a = 1.5)
  {
    const double b = a - 1; // A(L)
    if (w == 0)
      return std::log(a / b);
    // c1 J0(a w) + c2 Y0(a w) = 0;  b w (c1 J1(b w) + c2 Y1(b w)) = 1
    const double a11 = j0(a * w), a12 = y0(a * w);
    const double a21 = b * w * j1(b * w), a22 = b * w * y1(b * w);
    const double det = a11 * a22 - a12 * a21;
    const double c1 = -a12 / det, c2 = a11 / det;
    return c1 * j0(b * w) + c2 * y0(b * w);
  }

  inline double uniform_receptance(double w)
  {
    return w == 0 ? 1.0 : std::tan(w) / w;
  }

  /// The uniform bar's first nonsmooth mode (L = E = rho = A = 1, period T in
  /// (3, 4), Yoong, Thorin, Legrand 2018): at mid-contact, at rest, a tent
  /// with its peak u* at x* = (T - 2) / 2 and u(L) = g0, of energy
  /// g0^2 / (2 (T - 3)^2). The wall's force is the strain of the tent's right
  /// leg over a dwell of 4 - T centred on t = 0.
  struct UniformMode
  {
    UniformMode(double period, double gap)
      : T(period)
      , g0(gap)
      , x_peak((period - 2) / 2)
      , energy(gap * gap / (2 * (period - 3) * (period - 3)))
    {
      // (u*^2 / x* + (u* - g0)^2 / (1 - x*)) / 2 = energy.
      const double a = 1 / x_peak + 1 / (1 - x_peak), b = -2 * g0 / (1 - x_peak),
                   c = g0 * g0 / (1 - x_peak) - 2 * energy;
      peak  = (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a);
      force = (peak - g0) / (1 - x_peak);
    }

    /// Coefficient of cos(k 2 pi t / T) in the contact force (k = 0: mean).
    double force_harmonic(unsigned int k) const
    {
      const double dwell = 4 - T;
      return k == 0 ? force * dwell / T : 2 * force * std::sin(M_PI * k * dwell / T) / (M_PI * k);
    }

    double T, g0, x_peak, energy, peak = 0, force = 0;
  };

  /// The first `count` roots of f on (0, inf): sign changes on a fine grid,
  /// then bisection to machine precision.
  inline std::vector<double> roots(const std::function<double(double)> &f,
                                   unsigned int count,
                                   double       step = 1e-3)
  {
    std::vector<double> found;
    double a = step, fa = f(a);
    while (found.size() < count)
      {
        const double b = a + step, fb = f(b);
        if ((fa < 0) != (fb < 0))
          {
            double lo = a, hi = b, flo = fa;
            for (int i = 0; i < 200 && hi - lo > 4e-16 * hi; ++i)
              {
                const double mid = 0.5 * (lo + hi), fm = f(mid);
                if ((fm < 0) == (flo < 0))
                  lo = mid, flo = fm;
                else
                  hi = mid;
              }
            found.push_back(0.5 * (lo + hi));
          }
        a = b, fa = fb;
      }
    return found;
  }
} // namespace exact
