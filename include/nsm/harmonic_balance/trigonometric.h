// The real trigonometric basis of the harmonic balance in tau = W t, and the
// identities its integrals rest on. Shared by the active set's Gram matrix and
// the energy of a solution (solution_measures.h).
#pragma once

#include <cmath>
#include <cstdlib>
#include <vector>

namespace nsm
{
  constexpr double two_pi = 2 * M_PI;

  /// Basis function i is cos(order[i] tau), or sin(order[i] tau) where
  /// sine[i]; ordered by order.
  struct TrigonometricBasis
  {
    /// Bytes, not std::vector<bool>: the root search reads them in its
    /// inner loop.
    std::vector<unsigned char> sine;
    std::vector<unsigned int> order;

    unsigned int size() const { return order.size(); }
  };

  /// The harmonic balance's basis up to harmonic M: 1, then per k its cosine,
  /// after its sine if with_sines (the full basis).
  inline TrigonometricBasis harmonic_basis(const unsigned int harmonics, const bool with_sines)
  {
    TrigonometricBasis functions{{false}, {0}};
    for (unsigned int k = 1; k <= harmonics; ++k)
      {
        if (with_sines)
          {
            functions.sine.push_back(true);
            functions.order.push_back(k);
          }
        functions.sine.push_back(false);
        functions.order.push_back(k);
      }
    return functions;
  }

  /// cos(m t) and sin(m t) for m = 0..count-1 by the angle-sum recurrence.
  inline void trig_table(const double t, const unsigned int count, std::vector<double> &c, std::vector<double> &s)
  {
    c.resize(count);
    s.resize(count);
    const double c1 = std::cos(t), s1 = std::sin(t);
    c[0] = 1, s[0] = 0;
    for (unsigned int m = 1; m < count; ++m)
      {
        c[m] = c[m - 1] * c1 - s[m - 1] * s1;
        s[m] = s[m - 1] * c1 + c[m - 1] * s1;
      }
  }

  /// Calls add(is_sine, m, coefficient) for the expansion of the product
  /// of two basis functions (cos or sin of k tau and l tau) in cos / sin m tau.
  template <typename Add>
  void product_terms(const bool sine_k, const int k, const bool sine_l, const int l, Add &&add)
  {
    const int d = std::abs(k - l), sgn = k >= l ? 1 : -1;
    if (!sine_k && !sine_l)
      add(false, d, 0.5), add(false, k + l, 0.5);
    else if (sine_k && sine_l)
      add(false, d, 0.5), add(false, k + l, -0.5);
    else if (sine_k) // sin k cos l = (sin(k + l) + sin(k - l)) / 2
      add(true, k + l, 0.5), add(true, d, 0.5 * sgn);
    else // cos k sin l = (sin(k + l) - sin(k - l)) / 2
      add(true, k + l, 0.5), add(true, d, -0.5 * sgn);
  }
} // namespace nsm
