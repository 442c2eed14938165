#include <nsm/model/banded_pencil.h>

#include <algorithm>
#include <cstdlib>

namespace nsm
{
  BandedPencil::BandedPencil(const Discretisation &d, const EndCondition ends)
    : dofs(d.free_dofs(ends == EndCondition::clamped_clamped))
  {
    n      = dofs.size();
    finite = n;
    // A row without mass (the contact DoF with Contact mass = redistributed)
    // has an infinite eigenvalue: M is semidefinite.
    for (const unsigned int dof : dofs)
      finite -= d.mass().diag_element(dof) == 0;
    std::vector<int> row_of(d.n_dofs(), -1);
    for (int i = 0; i < n; ++i)
      row_of[dofs[i]] = i;
    if (ends == EndCondition::clamped_free)
      contact_row = row_of[d.contact_dof()];

    for (int i = 0; i < n; ++i)
      for (auto it = d.stiffness().begin(dofs[i]); it != d.stiffness().end(dofs[i]); ++it)
        if (row_of[it->column()] >= 0)
          bandwidth = std::max(bandwidth, std::abs(row_of[it->column()] - i));

    k.assign((bandwidth + 1) * n, 0.0);
    m.assign((bandwidth + 1) * n, 0.0);
    for (int i = 0; i < n; ++i)
      for (auto it = d.stiffness().begin(dofs[i]); it != d.stiffness().end(dofs[i]); ++it)
        {
          const int j = row_of[it->column()];
          if (j >= i)
            {
              entry(k, i, j) = it->value();
              entry(m, i, j) = d.mass().el(dofs[i], it->column());
            }
        }
  }

  double BandedPencil::at(const std::vector<double> &ab, int i, int j) const
  {
    if (i > j)
      std::swap(i, j);
    if (j - i > bandwidth)
      return 0.0;
    return entry(ab, i, j);
  }

  std::vector<double> BandedPencil::mass_times(const std::vector<double> &x) const
  {
    std::vector<double> y(n, 0.0);
    for (int j = 0; j < n; ++j)
      for (int i = std::max(0, j - bandwidth); i <= j; ++i)
        {
          const double value = entry(m, i, j);
          y[i] += value * x[j];
          if (i != j)
            y[j] += value * x[i];
        }
    return y;
  }
} // namespace nsm
