// A random dense system for the LU's tests and benchmark.
#pragma once

#include <random>
#include <utility>
#include <vector>

namespace testing_helpers
{
  /// A random n x n matrix (column-major) and vector, entries in [-1, 1].
  inline std::pair<std::vector<double>, std::vector<double>> random_system(const int n, const unsigned int seed)
  {
    std::mt19937                           engine(seed);
    std::uniform_real_distribution<double> uniform(-1, 1);
    std::vector<double>                    a(n * n), x(n);
    for (double &v : a)
      v = uniform(engine);
    for (double &v : x)
      v = uniform(engine);
    return {a, x};
  }
} // namespace testing_helpers
