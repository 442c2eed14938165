// Sturm counts of the pencil (K, M): how many eigenvalues lie below a shift,
// the negative pivots of K - sigma M = L D L^T (Sylvester's law of inertia),
// O(n p^2) each; remembered, they bracket every eigenvalue.
#pragma once

#include <nsm/model/banded_pencil.h>

#include <map>
#include <utility>
#include <vector>

namespace nsm
{
  /// The number of eigenvalues of K phi = lambda M phi below sigma.
  int count_eigenvalues_below(const BandedPencil &pencil, double sigma);

  class SturmBrackets
  {
  public:
    /// Counts at 0 and at `upper`: the eigenvalues below `upper` are those
    /// bracketed.
    SturmBrackets(const BandedPencil &pencil, double upper);

    /// The count at sigma, remembered.
    int below(double sigma);
    /// How many eigenvalues lie below `upper`.
    int total() const { return counts_.rbegin()->second; }
    /// The narrowest (lo, hi) the counts give with below(lo) < j <= below(hi)
    /// (j from 1).
    std::pair<double, double> bracket(int j) const;
    /// Narrows the bracket of lambda_j until it holds lambda_j alone, trying
    /// the guesses first, then bisecting. Throws NumericalError if two
    /// eigenvalues agree to rounding.
    void isolate(int j, const std::vector<double> &guesses);

  private:
    const BandedPencil  &pencil_;
    std::map<double, int> counts_;
  };
} // namespace nsm
