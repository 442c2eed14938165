// K and M of the clamped-free or clamped-clamped bar in LAPACK symmetric
// band storage (the 1D FE matrices have bandwidth p after Cuthill-McKee
// ordering), shared by the eigensolvers.
#pragma once

#include <nsm/model/discretisation.h>

#include <vector>

namespace nsm
{
  enum class EndCondition
  {
    clamped_free,
    clamped_clamped
  };

  /// K and M restricted to the free DoFs of an end condition, upper band
  /// storage, (bandwidth + 1) x n each.
  struct BandedPencil
  {
    BandedPencil(const Discretisation &discretisation, EndCondition ends);

    int                       n         = 0;
    /// Finite eigenvalues: n less the rows without mass.
    int                       finite    = 0;
    int                       bandwidth = 0;
    std::vector<double>       k;
    std::vector<double>       m;
    std::vector<unsigned int> dofs;
    /// The contact DoF's row (clamped-free only; -1 otherwise).
    int contact_row = -1;

    /// Entry (i, j) of a band matrix, i <= j <= i + bandwidth.
    double &entry(std::vector<double> &ab, int i, int j)
    {
      return ab[index(i, j)];
    }
    double entry(const std::vector<double> &ab, int i, int j) const { return ab[index(i, j)]; }
    /// Where entry (i, j), i <= j, sits in upper band storage.
    std::size_t index(int i, int j) const { return (bandwidth + i - j) + std::size_t(j) * (bandwidth + 1); }
    /// Entry (i, j), any order; 0 outside the band.
    double at(const std::vector<double> &ab, int i, int j) const;
    /// M x on the pencil's rows.
    std::vector<double> mass_times(const std::vector<double> &x) const;
  };
} // namespace nsm
