#include <nsm/spectrum.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

extern "C"
{
  void dsbgvx_(const char *, const char *, const char *, const int *,
               const int *, const int *, double *, const int *, double *,
               const int *, double *, const int *, const double *,
               const double *, const int *, const int *, const double *,
               int *, double *, double *, const int *, double *, int *, int *,
               int *, std::size_t, std::size_t, std::size_t);
  void dgbtrf_(const int *, const int *, const int *, const int *, double *,
               const int *, int *, int *);
  void dgbtrs_(const char *, const int *, const int *, const int *,
               const int *, const double *, const int *, const int *,
               double *, const int *, int *, std::size_t);
  double dlamch_(const char *, std::size_t);
}

namespace nsm
{
  namespace
  {
    /// K and M restricted to a set of DoFs, in LAPACK symmetric band storage.
    struct BandedPencil
    {
      int                 n = 0;
      int                 bandwidth = 0;
      std::vector<double> k; // (bandwidth + 1) x n, upper
      std::vector<double> m;
      std::vector<unsigned int> dofs;
      int                 contact_row = -1;

      double &entry(std::vector<double> &ab, int i, int j) // i <= j
      {
        return ab[(bandwidth + i - j) + j * (bandwidth + 1)];
      }
      double at(const std::vector<double> &ab, int i, int j) const
      {
        if (i > j)
          std::swap(i, j);
        if (j - i > bandwidth)
          return 0.0;
        return ab[(bandwidth + i - j) + j * (bandwidth + 1)];
      }
    };

    BandedPencil make_pencil(const Discretisation &d, const EndCondition ends)
    {
      BandedPencil p;
      p.dofs = d.free_dofs(ends == EndCondition::clamped_clamped);
      p.n    = p.dofs.size();
      std::vector<int> row_of(d.n_dofs(), -1);
      for (int i = 0; i < p.n; ++i)
        row_of[p.dofs[i]] = i;
      if (ends == EndCondition::clamped_free)
        p.contact_row = row_of[d.contact_dof()];

      for (int i = 0; i < p.n; ++i)
        for (auto it = d.stiffness().begin(p.dofs[i]);
             it != d.stiffness().end(p.dofs[i]);
             ++it)
          if (row_of[it->column()] >= 0)
            p.bandwidth = std::max(p.bandwidth, std::abs(row_of[it->column()] - i));

      p.k.assign((p.bandwidth + 1) * p.n, 0.0);
      p.m.assign((p.bandwidth + 1) * p.n, 0.0);
      for (int i = 0; i < p.n; ++i)
        for (auto it = d.stiffness().begin(p.dofs[i]);
             it != d.stiffness().end(p.dofs[i]);
             ++it)
          {
            const int j = row_of[it->column()];
            if (j >= i)
              {
                p.entry(p.k, i, j) = it->value();
                p.entry(p.m, i, j) = d.mass().el(p.dofs[i], it->column());
              }
          }
      return p;
    }

    /// Eigenvalues with indices [first, last] (1-based), or all below
    /// `upper` when last == 0.
    std::vector<double> banded_eigenvalues(const BandedPencil &p,
                                           int                 first,
                                           int                 last,
                                           double              upper)
    {
      std::vector<double> k = p.k, m = p.m;
      const int           ld = p.bandwidth + 1;
      // All of them: 'A' with abstol = 0 takes LAPACK's QR path (dsterf),
      // far faster than bisection; the refinement below restores accuracy.
      const bool   all    = first == 1 && last == p.n;
      const char   range  = all ? 'A' : last > 0 ? 'I' : 'V';
      const double lower  = -1.0;
      const double abstol = all ? 0.0 : 2 * dlamch_("S", 1);
      int                 found = 0, info = 0, ldq = 1, ldz = 1;
      std::vector<double> w(p.n), work(7 * p.n);
      std::vector<int>    iwork(5 * p.n), ifail(p.n);
      double              q = 0, z = 0;
      dsbgvx_("N", &range, "U", &p.n, &p.bandwidth, &p.bandwidth, k.data(),
              &ld, m.data(), &ld, &q, &ldq, &lower, &upper, &first, &last,
              &abstol, &found, w.data(), &z, &ldz, work.data(), iwork.data(),
              ifail.data(), &info, 1, 1, 1);
      if (info != 0)
        throw NumericalError("LAPACK dsbgvx failed (info = " +
                             std::to_string(info) +
                             ") on the generalised eigenproblem K phi = w^2 M phi");
      w.resize(found);
      return w;
    }

    /// LU factors of K - sigma M in LAPACK general band storage.
    class ShiftedLU
    {
    public:
      ShiftedLU(const BandedPencil &p, const double sigma)
        : n_(p.n)
        , kl_(p.bandwidth)
        , ld_(3 * p.bandwidth + 1)
        , lu_(ld_ * n_, 0.0)
        , pivots_(n_)
      {
        for (int j = 0; j < n_; ++j)
          for (int i = std::max(0, j - kl_); i <= std::min(n_ - 1, j + kl_); ++i)
            lu_[(2 * kl_ + i - j) + j * ld_] = p.at(p.k, i, j) - sigma * p.at(p.m, i, j);
        int info = 0;
        dgbtrf_(&n_, &n_, &kl_, &kl_, lu_.data(), &ld_, pivots_.data(), &info);
        singular_ = info != 0;
      }
      bool singular() const { return singular_; }
      void solve(std::vector<double> &b) const
      {
        const int one = 1;
        int       info = 0;
        dgbtrs_("N", &n_, &kl_, &kl_, &one, lu_.data(), &ld_, pivots_.data(),
                b.data(), &n_, &info, 1);
      }

    private:
      int                 n_, kl_, ld_;
      std::vector<double> lu_;
      std::vector<int>    pivots_;
      bool                singular_ = false;
    };

    std::vector<double> banded_product(const BandedPencil       &p,
                                       const std::vector<double> &ab,
                                       const std::vector<double> &x)
    {
      // Upper band storage: column j holds A(i, j) for j - bandwidth <= i <= j.
      const int           ld = p.bandwidth + 1;
      std::vector<double> y(p.n, 0.0);
      for (int j = 0; j < p.n; ++j)
        {
          const double *column = &ab[j * ld + p.bandwidth - j];
          y[j] += column[j] * x[j];
          for (int i = std::max(0, j - p.bandwidth); i < j; ++i)
            {
              y[i] += column[i] * x[j];
              y[j] += column[i] * x[i];
            }
        }
      return y;
    }

    double dot(const std::vector<double> &a, const std::vector<double> &b)
    {
      double s = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        s += a[i] * b[i];
      return s;
    }

    /// Refines an eigenvalue and returns the mass-normalised mode's value at
    /// the contact row: two steps of inverse iteration shifted at the LAPACK
    /// eigenvalue; the Rayleigh update sigma + 1 / (x^T M y) corrects the
    /// eigenvalue by a quantity that is itself small, so it keeps full
    /// relative accuracy even for the low modes.
    double refine_eigenpair(const BandedPencil &p, double &eigenvalue)
    {
      double sigma = eigenvalue;
      ShiftedLU lu(p, sigma);
      // An exactly zero pivot: shift off the eigenvalue by a growing amount.
      for (double shift = 1e-13; lu.singular() && shift < 1e-7; shift *= 10)
        {
          sigma = eigenvalue * (1 + shift);
          lu    = ShiftedLU(p, sigma);
        }
      if (lu.singular())
        throw NumericalError("K - w^2 M is singular at the eigenvalue " +
                             std::to_string(eigenvalue) +
                             " and near it: inverse iteration failed");
      std::vector<double> x(p.n, 1.0);
      if (p.contact_row >= 0)
        {
          std::fill(x.begin(), x.end(), 0.0);
          x[p.contact_row] = 1.0;
        }
      for (int step = 0; step < 2; ++step)
        {
          const std::vector<double> mx = banded_product(p, p.m, x);
          std::vector<double>       y  = mx;
          lu.solve(y);
          const std::vector<double> my = banded_product(p, p.m, y);
          if (step == 1)
            eigenvalue = sigma + dot(x, mx) / dot(x, my);
          const double norm = std::sqrt(dot(y, my));
          for (double &v : y)
            v /= norm;
          x = std::move(y);
        }
      return p.contact_row >= 0 ? x[p.contact_row] : 0.0;
    }
  } // namespace

  ModalData compute_spectrum(const Discretisation &discretisation,
                             const EndCondition    ends,
                             unsigned int          count,
                             const bool            with_contact_residues)
  {
    const BandedPencil pencil = make_pencil(discretisation, ends);
    if (count == 0 || count > static_cast<unsigned int>(pencil.n))
      count = pencil.n;
    ModalData data;
    data.eigenvalues = banded_eigenvalues(pencil, 1, count, 0.0);
    if (with_contact_residues)
      data.contact_residues.resize(count);
    for (unsigned int j = 0; j < count; ++j)
      {
        const double phi = refine_eigenpair(pencil, data.eigenvalues[j]);
        if (with_contact_residues)
          data.contact_residues[j] = phi * phi;
      }
    return data;
  }

  std::vector<double> eigenvalues_below(const Discretisation &discretisation,
                                        const EndCondition    ends,
                                        const double          omega_max)
  {
    return banded_eigenvalues(make_pencil(discretisation, ends),
                              0,
                              0,
                              omega_max * omega_max);
  }
} // namespace nsm
