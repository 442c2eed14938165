#include <nsm/model/near_modes.h>
#include <nsm/base/errors.h>
#include <nsm/model/shifted_factor.h>
#include <nsm/model/sturm_sequence.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numeric>
#include <string>

namespace nsm
{
  namespace
  {
    constexpr double eps = std::numeric_limits<double>::epsilon();

    double mass_norm_squared(const BandedPencil &p, const std::vector<double> &x)
    {
      const std::vector<double> mx = p.mass_times(x);
      return std::inner_product(x.begin(), x.end(), mx.begin(), 0.0);
    }

    /// The mode of the eigenvalue nearest the factor's shift, unnormalised:
    /// two steps of inverse iteration from a start vector with no special
    /// direction, each dividing another mode's share by |lambda_k - shift| /
    /// |lambda_j - shift| (at least 1e6 at the shifts `eigenvalue` leaves),
    /// which tells apart nearly equal eigenvalues (a mode confined to a small
    /// cell) that 1/gamma cannot.
    std::vector<double> inverse_iteration(const BandedPencil &p, const ShiftedFactor<double> &factor)
    {
      std::vector<double> x(p.n);
      for (int i = 0; i < p.n; ++i)
        x[i] = 1 + 0.5 * std::sin(1.7 * i + 0.3);
      for (int step = 0; step < 2; ++step)
        {
          x = p.mass_times(x);
          factor.solve(x);
        }
      return x;
    }

    /// phi_j(L)^2 of the mass-normalised mode.
    double residue(const BandedPencil &p, const ShiftedFactor<double> &factor)
    {
      const std::vector<double> x = inverse_iteration(p, factor);
      return x[p.contact_row] * x[p.contact_row] / mass_norm_squared(p, x);
    }

    /// lambda_j from its isolating bracket: Newton's method on 1/g,
    /// sigma + g / g', g = h_r and g' = h^T M h for h = (K - sigma M)^{-1} e_r
    /// (on the contact row, g = gamma), whose simple zeros are the eigenvalues
    /// where phi_j(r) != 0, with quadratic convergence; where a step leaves the
    /// bracket or is not half the step before last (a mode nearly absent from
    /// row r), a Sturm count at sigma narrows the bracket and its midpoint is
    /// tried, as in Numerical Recipes' rtsafe. A step below 1e-8 sigma is the
    /// last: the error it leaves, about step^2 / (lambda_{j+1} - lambda_j), is
    /// at the rounding of lambda_j. `factor` is left at a shift from which
    /// inverse iteration divides every other mode's share by at least 1e6 per
    /// step.
    double eigenvalue(const BandedPencil   &p,
                      SturmBrackets        &sturm,
                      const int             j,
                      const double          guess,
                      const int             row,
                      ShiftedFactor<double> &factor)
    {
      auto [lo, hi]   = sturm.bracket(j);
      double sigma    = guess > 0 ? std::clamp(guess, lo, hi) : 0.5 * (lo + hi);
      double previous = hi - lo, older = hi - lo;
      for (int iteration = 0; iteration < 200; ++iteration)
        {
          factor.factor(sigma);
          std::vector<double> h(p.n, 0.0);
          h[row] = 1.0;
          factor.solve(h);
          const double step = h[row] / mass_norm_squared(p, h);
          double       next = sigma + step;
          if (lo < next && next < hi && std::abs(step) <= 1e-8 * sigma)
            {
              // The neighbours lie outside (lo, hi): inverse iteration at
              // sigma divides their share by min(next - lo, hi - next) / |step|
              // per step. Below 1e6, a factor at next.
              if (std::abs(step) > 1e-6 * std::min(next - lo, hi - next))
                factor.factor(next);
              return next;
            }
          if (!(lo < next && next < hi) || std::abs(step) > 0.5 * older)
            {
              (sturm.below(sigma) >= j ? hi : lo) = sigma;
              if (hi - lo <= 4 * eps * hi)
                return 0.5 * (lo + hi);
              next = 0.5 * (lo + hi);
            }
          older    = previous;
          previous = std::abs(next - sigma);
          sigma    = next;
        }
      throw NumericalError("no convergence to eigenvalue " + std::to_string(j));
    }

    /// The frequencies found so far are nearly evenly spaced (a bar): the
    /// next one extrapolated, and shifts half a spacing either side of it.
    std::vector<double> guesses(const std::vector<double> &lambda)
    {
      if (lambda.empty())
        return {};
      const double w       = std::sqrt(lambda.back());
      const double spacing = w - (lambda.size() > 1 ? std::sqrt(lambda[lambda.size() - 2]) : 0.0);
      return {std::pow(w + spacing, 2), std::pow(w + 1.5 * spacing, 2), std::pow(w + 0.5 * spacing, 2)};
    }
  } // namespace

  ModalData modes_below(const BandedPencil &p, const double upper)
  {
    SturmBrackets         sturm(p, upper);
    ShiftedFactor<double> factor(p);
    ModalData             near;
    for (int j = 1; j <= sturm.total(); ++j)
      {
        const std::vector<double> trials = guesses(near.eigenvalues);
        sturm.isolate(j, trials);
        near.eigenvalues.push_back(
          eigenvalue(p, sturm, j, trials.empty() ? 0.0 : trials.front(), p.contact_row, factor));
        near.contact_residues.push_back(residue(p, factor));
      }
    return near;
  }

  std::vector<double> mode_shape(const BandedPencil &p, const double lambda)
  {
    ShiftedFactor<double> factor(p);
    factor.factor(lambda);
    std::vector<double> x     = inverse_iteration(p, factor);
    const double        scale = 1 / std::sqrt(mass_norm_squared(p, x));
    for (double &v : x)
      v *= scale;
    return x;
  }

  std::vector<double> lowest_eigenvalues(const BandedPencil &p, const int count)
  {
    if (count > p.finite)
      throw NumericalError("asked for " + std::to_string(count) + " eigenvalues of a pencil with " +
                           std::to_string(p.finite) + " finite ones");
    double upper = 1;
    while (count_eigenvalues_below(p, upper) < count)
      upper *= 16;
    SturmBrackets         sturm(p, upper);
    ShiftedFactor<double> factor(p);
    std::vector<double>   lambda;
    for (int j = 1; j <= count; ++j)
      {
        const std::vector<double> trials = guesses(lambda);
        sturm.isolate(j, trials);
        lambda.push_back(eigenvalue(p, sturm, j, trials.empty() ? 0.0 : trials.front(), p.n - 1, factor));
      }
    return lambda;
  }

  std::vector<double> far_mode_series(const BandedPencil &p,
                                      const ModalData    &near,
                                      const double        upper,
                                      const double        limit,
                                      const unsigned int  terms)
  {
    // F = gamma - sum_near r_j / (lambda_j - s) is analytic for |s| < upper.
    // Its Taylor coefficients are the trapezoidal sums over `points` points
    // of a circle of radius R: rounding delta in F costs delta (limit / R)^m
    // in the series on |s| <= limit, and the aliased terms (R / upper)^points,
    // which enough points bring below eps. R lies mid-gap between near poles,
    // about sqrt(limit upper), so that F is not the difference of large
    // near-pole values.
    const std::vector<double> &lambda = near.eigenvalues;
    const auto   above  = std::upper_bound(lambda.begin(), lambda.end(), std::sqrt(limit * upper));
    const double radius = 0.5 * ((above == lambda.begin() ? 0.0 : *std::prev(above)) +
                                 (above == lambda.end() ? upper : *above));
    const int points = 2 * int(std::ceil(0.5 * std::max<double>(terms, std::log(eps) / std::log(radius / upper))));
    std::vector<double>                 sums(terms, 0.0);
    ShiftedFactor<std::complex<double>> factor(p);
    for (int q = 0; q <= points / 2; ++q)
      {
        const std::complex<double>        s = std::polar(radius, 2 * M_PI * q / points);
        std::vector<std::complex<double>> h(p.n, 0.0);
        h[p.contact_row] = 1.0;
        factor.factor(s); // off the real axis but at q = 0, mid-gap there: regular
        factor.solve(h);
        std::complex<double> f = h[p.contact_row];
        for (std::size_t j = 0; j < lambda.size(); ++j)
          f -= near.contact_residues[j] / (lambda[j] - s);
        // The points q and points - q are conjugate, as are their values.
        const double weight = (q == 0 || q == points / 2) ? 1.0 : 2.0;
        std::complex<double> power = 1.0;
        for (unsigned int m = 0; m < terms; ++m, power /= s)
          sums[m] += weight * std::real(f * power);
      }
    for (double &c : sums)
      c /= points;
    return sums;
  }
} // namespace nsm
