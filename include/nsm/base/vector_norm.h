// The Euclidean norm of a vector of doubles, summed in index order (so that a
// norm computed here and one computed by an older copy of this loop agree to
// the last bit).
#pragma once

#include <cmath>
#include <vector>

namespace nsm
{
  inline double two_norm(const std::vector<double> &v)
  {
    double sum = 0;
    for (const double r : v)
      sum += r * r;
    return std::sqrt(sum);
  }
} // namespace nsm
