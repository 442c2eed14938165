// The value of one function of the trigonometric basis, for the tests that
// check the active set and the Gram matrix against quadrature.
#pragma once

#include <nsm/harmonic_balance/trigonometric.h>

#include <cmath>

namespace testing_helpers
{
  /// phi_i(tau): cos(k tau) or sin(k tau), k = b.order[i].
  inline double basis_value(const nsm::TrigonometricBasis &b, const unsigned int i, const double tau)
  {
    return b.sine[i] ? std::sin(b.order[i] * tau) : std::cos(b.order[i] * tau);
  }
} // namespace testing_helpers
