#include <nsm/base/errors.h>
#include <nsm/model/sturm_sequence.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>

namespace nsm
{
  namespace
  {
    constexpr double round_off = std::numeric_limits<double>::epsilon();
  }

  int count_eigenvalues_below(const BandedPencil &p, const double sigma)
  {
    // K - sigma M = L D L^T without pivoting, row by row in the band. Row i
    // needs the rows i - b .. i - 1 only: L(i, k), k in [i - b, i), and d(i)
    // are held in rings of a power of two >= b + 1 rows.
    const int b = p.bandwidth;
    int       ring = 1;
    while (ring < b + 1)
      ring *= 2;
    const int           mask = ring - 1;
    std::vector<double> l(std::size_t(ring) * std::max(b, 1), 0.0), d(ring);
    auto L = [&](const int i, const int k) -> double & { return l[(i & mask) * b + (k - i + b)]; };
    int negative = 0;
    for (int i = 0; i < p.n; ++i)
      {
        const int first = std::max(0, i - b);
        for (int j = first; j <= i; ++j)
          {
            const std::size_t entry = p.index(j, i);
            double            s     = p.k[entry] - sigma * p.m[entry];
            for (int k = std::max(first, j - b); k < j; ++k)
              s -= L(i, k) * d[k & mask] * L(j, k);
            if (j < i)
              L(i, j) = s / d[j & mask];
            else
              {
                // A zero pivot (sigma an eigenvalue of a leading block) is
                // replaced by one at the rounding of the diagonal, as in
                // LAPACK's dlaebz.
                if (s == 0)
                  s = round_off * (std::abs(p.k[entry]) + std::abs(sigma * p.m[entry]));
                d[i & mask] = s;
                negative += s < 0;
              }
          }
      }
    return negative;
  }

  SturmBrackets::SturmBrackets(const BandedPencil &pencil, const double upper)
    : pencil_(pencil)
    , counts_{{0.0, 0}, {upper, count_eigenvalues_below(pencil, upper)}}
  {}

  int SturmBrackets::below(const double sigma)
  {
    return counts_[sigma] = count_eigenvalues_below(pencil_, sigma);
  }

  std::pair<double, double> SturmBrackets::bracket(const int j) const
  {
    const auto hi = std::find_if(counts_.begin(), counts_.end(), [j](const auto &c) { return c.second >= j; });
    return {std::prev(hi)->first, hi->first};
  }

  void SturmBrackets::isolate(const int j, const std::vector<double> &guesses)
  {
    auto next_guess = guesses.begin();
    for (;;)
      {
        const auto [lo, hi] = bracket(j);
        if (counts_.at(lo) == j - 1 && counts_.at(hi) == j)
          return;
        if (hi - lo <= 4 * round_off * hi)
          throw NumericalError("two eigenvalues w^2 agree to rounding near " + std::to_string(hi) +
                               ": they cannot be told apart");
        next_guess = std::find_if(next_guess, guesses.end(), [lo = lo, hi = hi](const double g) {
          return lo < g && g < hi;
        });
        below(next_guess != guesses.end() ? *next_guess++ : 0.5 * (lo + hi));
      }
  }
} // namespace nsm
