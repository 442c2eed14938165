// Benchmark (not a test): the Newton step's dense LU solve (base/dense_lu.h) at
// the Jacobian's sizes for M = 40, 80, 160 and 320 (cosine basis):
// microseconds per solve of a random system (the copy of the matrix
// included), min / median / max over 5 runs of many solves each.
#include <nsm/base/dense_lu.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "random_system.h"

int main()
{
  std::printf("| n | us per solve: min | median | max | GFlop/s at the median |\n|---|---|---|---|---|\n");
  for (const int n : {41, 81, 161, 321})
    {
      const auto [a, b] = testing_helpers::random_system(n, 1);
      const int           solves = 100000000 / (n * n * n) + 1;
      std::vector<double> times;
      for (int run = 0; run < 5; ++run)
        {
          const auto start = std::chrono::steady_clock::now();
          for (int r = 0; r < solves; ++r)
            {
              std::vector<double> lu = a, x = b;
              nsm::dense_solve(n, lu.data(), x.data());
            }
          times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / solves);
        }
      std::sort(times.begin(), times.end());
      std::printf("| %d | %.1f | %.1f | %.1f | %.1f |\n", n, 1e6 * times[0], 1e6 * times[2], 1e6 * times[4],
                  2.0 / 3 * n * n * n / times[2] * 1e-9);
    }
}
