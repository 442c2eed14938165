#include <nsm/base/errors.h>
#include <nsm/model/spectrum.h>
#include <nsm/model/sturm_sequence.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <tuple>
#include <string>

extern "C"
{
  void dsbgvx_(const char *, const char *, const char *, const int *,
               const int *, const int *, double *, const int *, double *,
               const int *, double *, const int *, const double *,
               const double *, const int *, const int *, const double *,
               int *, double *, double *, const int *, double *, int *, int *,
               int *, std::size_t, std::size_t, std::size_t);
  void dpbtrf_(const char *, const int *, const int *, double *, const int *, int *,
               std::size_t);
  void dpbtrs_(const char *, const int *, const int *, const int *, const double *,
               const int *, double *, const int *, int *, std::size_t);
  double dlamch_(const char *, std::size_t);
}

namespace nsm
{
  namespace
  {
    /// Which matrix LAPACK factors by Cholesky. dsbgvx reduces the pencil
    /// to standard form with that factor, so an eigenvalue's absolute error
    /// is about eps times the largest eigenvalue of the reduced problem:
    /// - mass: K phi = lambda M phi, error eps lambda_max; accurate for the
    ///   high modes, but tiny cells (lambda_max ~ 1 / h_min^2) ruin the low
    ///   ones;
    /// - stiffness: M phi = mu K phi with mu = 1 / lambda, error eps / lambda_1;
    ///   accurate for the low modes whatever the smallest cell.
    enum class Factored
    {
      mass,
      stiffness
    };

    /// Eigenvalues lambda of K phi = lambda M phi, ascending: indices
    /// [first, last] (1-based), or all lambda <= upper when last == 0.
    std::vector<double> banded_eigenvalues(const BandedPencil &p,
                                           const Factored      form,
                                           int                 first,
                                           int                 last,
                                           const double        upper)
    {
      const bool inverse = form == Factored::stiffness;
      if (last == 0 && upper <= 0) // K is positive definite: no lambda <= 0
        return {};
      std::vector<double> a = inverse ? p.m : p.k, b = inverse ? p.k : p.m;
      const int           ld = p.bandwidth + 1;
      // All of them: 'A' with abstol = 0 takes LAPACK's QR path (dsterf),
      // far faster than bisection.
      const bool   all   = first == 1 && last == p.n;
      const char   range = all ? 'A' : last > 0 ? 'I' : 'V';
      // mu = 1 / lambda reverses the order: lambda indices [first, last] are
      // mu indices [n + 1 - last, n + 1 - first]; lambda <= upper is mu >= 1 / upper.
      if (inverse && range == 'I')
        std::tie(first, last) = std::make_pair(p.n + 1 - last, p.n + 1 - first);
      const double lower  = inverse ? 1.0 / upper : -1.0;
      const double top    = inverse ? std::numeric_limits<double>::max() : upper;
      const double abstol = all ? 0.0 : 2 * dlamch_("S", 1);
      int                 found = 0, info = 0, ldq = 1, ldz = 1;
      std::vector<double> w(p.n), work(7 * p.n);
      std::vector<int>    iwork(5 * p.n), ifail(p.n);
      double              q = 0, z = 0;
      dsbgvx_("N", &range, "U", &p.n, &p.bandwidth, &p.bandwidth, a.data(),
              &ld, b.data(), &ld, &q, &ldq, &lower, &top, &first, &last,
              &abstol, &found, w.data(), &z, &ldz, work.data(), iwork.data(),
              ifail.data(), &info, 1, 1, 1);
      if (info != 0)
        throw NumericalError("LAPACK dsbgvx failed (info = " +
                             std::to_string(info) +
                             ") on the generalised eigenproblem K phi = w^2 M phi");
      w.resize(found);
      if (inverse)
        {
          std::reverse(w.begin(), w.end());
          for (double &l : w)
            l = 1.0 / l;
        }
      return w;
    }

    /// The lowest `count` eigenvalues. Fewer than n / (10 p) by Sturm counts
    /// and Newton (near_modes), cheaper than LAPACK's O(n^2 p) band reduction;
    /// more from LAPACK, each from the form that is accurate for it: the
    /// stiffness form below sqrt(lambda_1 lambda_max), where the two forms'
    /// relative errors eps lambda / lambda_1 and eps lambda_max / lambda are
    /// equal, the mass form above. Bisection (ranges 'I') finds a few
    /// eigenvalues cheaply, QR (all of them) many: each form is asked only
    /// for its own share.
    std::vector<double> lowest_by_cost(const BandedPencil &p, const int count)
    {
      if (10 * count * std::max(p.bandwidth, 1) <= p.n)
        return lowest_eigenvalues(p, count);
      if (count < p.n)
        {
          std::vector<double> low = banded_eigenvalues(p, Factored::stiffness, 1, count, 0.0);
          // A Rayleigh quotient K_ii / M_ii bounds lambda_max from below: when
          // even that bound puts the split above every eigenvalue asked for,
          // the stiffness form serves them all without asking for lambda_max.
          double lambda_max = 0;
          for (int i = 0; i < p.n; ++i)
            lambda_max = std::max(lambda_max, p.at(p.k, i, i) / p.at(p.m, i, i));
          if (low.back() * low.back() <= low.front() * lambda_max)
            return low;
          lambda_max = banded_eigenvalues(p, Factored::mass, p.n, p.n, 0.0).at(0);
          const double              split = std::sqrt(low.front() * lambda_max);
          const std::vector<double> high  = banded_eigenvalues(p, Factored::mass, 1, count, 0.0);
          for (std::size_t j = 0; j < low.size(); ++j)
            if (low[j] > split)
              low[j] = high[j];
          return low;
        }
      std::vector<double> all      = banded_eigenvalues(p, Factored::mass, 1, p.n, 0.0);
      const double        lambda_1 = banded_eigenvalues(p, Factored::stiffness, 1, 1, 0.0).at(0);
      const double        split    = std::sqrt(lambda_1 * all.back());
      const int below = std::upper_bound(all.begin(), all.end(), split) - all.begin();
      if (below > 0)
        {
          const std::vector<double> low = banded_eigenvalues(p, Factored::stiffness, 1, below, 0.0);
          std::copy(low.begin(), low.end(), all.begin());
        }
      return all;
    }

    /// gamma(0) = e_N^T K^{-1} e_N from a band Cholesky factor of K (its
    /// upper band storage is LAPACK's).
    double static_receptance(const BandedPencil &p)
    {
      std::vector<double> factor = p.k;
      const int           ld = p.bandwidth + 1, one = 1;
      int                 info = 0;
      dpbtrf_("U", &p.n, &p.bandwidth, factor.data(), &ld, &info, 1);
      if (info != 0)
        throw NumericalError("the stiffness matrix K is not positive definite: no static receptance");
      std::vector<double> x(p.n, 0.0);
      x[p.contact_row] = 1.0;
      dpbtrs_("U", &p.n, &p.bandwidth, &one, factor.data(), &ld, x.data(), &p.n, &info, 1);
      return x[p.contact_row];
    }

    /// The residues r_j = phi_j(L)^2 of gamma(w) = sum_j r_j / (lambda_j - w^2)
    /// from the spectra alone. gamma is a ratio of determinants,
    /// gamma = gamma(0) (prod lambda_i / prod mu_k) prod (mu_k - w^2) / prod (lambda_i - w^2),
    /// with lambda the clamped-free eigenvalues (its poles) and mu the
    /// clamped-clamped ones (its zeros), which interlace. Pairing each mu_k
    /// with its neighbour lambda makes every factor of r_j a ratio near 1:
    /// r_j = gamma(0) lambda_j prod_k (1 - lambda_j / mu_k) / (1 - lambda_j / lambda_k'),
    /// k' = k below j and k + 1 from j on.
    std::vector<double> contact_residues(const std::vector<double> &lambda,
                                         const std::vector<double> &mu,
                                         const double               gamma0,
                                         const std::size_t          count)
    {
      std::vector<double> r(count);
      for (std::size_t j = 0; j < count; ++j)
        {
          double product  = gamma0 * lambda[j];
          int    exponent = 0;
          for (std::size_t k = 0; k < mu.size(); ++k)
            {
              // Without inertia at the contact DoF the last pole is infinite
              // and its factor 1.
              const std::size_t i    = k < j ? k : k + 1;
              const double      pole = i < lambda.size() ? lambda[i] : std::numeric_limits<double>::infinity();
              product *= (1 - lambda[j] / mu[k]) / (1 - lambda[j] / pole);
              int e;
              product = std::frexp(product, &e); // no overflow over thousands of factors
              exponent += e;
            }
          r[j] = std::ldexp(product, exponent);
        }
      return r;
    }
  } // namespace

  ModalData compute_spectrum(const Discretisation &discretisation,
                             const EndCondition    ends,
                             unsigned int          count,
                             const bool            with_contact_residues)
  {
    const BandedPencil pencil(discretisation, ends);
    if (count == 0 || count > static_cast<unsigned int>(pencil.finite))
      count = pencil.finite;
    ModalData data;
    data.eigenvalues = lowest_by_cost(pencil, count);
    if (with_contact_residues)
      {
        // Residues need every pole and zero, whatever `count`.
        const std::vector<double> lambda =
          count == static_cast<unsigned int>(pencil.finite) ? data.eigenvalues :
                                                              lowest_by_cost(pencil, pencil.finite);
        const BandedPencil clamped(discretisation, EndCondition::clamped_clamped);
        data.contact_residues = contact_residues(lambda,
                                                 lowest_by_cost(clamped, clamped.n),
                                                 static_receptance(pencil),
                                                 count);
      }
    return data;
  }

  std::vector<double> eigenvalues_below(const BandedPencil &pencil, const double omega_max)
  {
    const double upper = omega_max * omega_max;
    if (upper <= 0)
      return {};
    // A few (the poles of a band on a fine mesh) by Sturm counts and Newton,
    // O(n p^2) each, instead of LAPACK's O(n^2 p) band reduction (83 s
    // against 0.92 s on FE_Q(10) x 4000 with a band of 87.5: doc/accuracy-and-cost.md).
    const int count = count_eigenvalues_below(pencil, upper);
    if (count == 0)
      return {};
    if (10 * count * std::max(pencil.bandwidth, 1) <= pencil.n)
      return lowest_eigenvalues(pencil, count);
    return banded_eigenvalues(pencil, Factored::stiffness, 0, 0, upper);
  }
} // namespace nsm
