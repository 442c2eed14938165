// A real trigonometric series q(tau) = sum_i v_i phi_i(tau) on the harmonic
// balance's basis, evaluated with its slope where the active set's root
// search asks (hundreds of times per residual at high M).
//
// The coefficients are gathered per order k into a_k (cosine) and b_k
// (sine); cos k tau and sin k tau come from the angle-sum recurrence in
// `lanes` independent chains, k = lane + lanes * block, each rotated by
// lanes * tau per block: the chains vectorise, and each takes M / lanes
// rotations instead of M.
#pragma once

#include <nsm/harmonic_balance/trigonometric.h>

#include <vector>

namespace nsm
{
  class TrigonometricSeries
  {
  public:
    TrigonometricSeries(const TrigonometricBasis &basis, const std::vector<double> &v);

    /// q(tau), and q'(tau) if slope is given.
    double operator()(double tau, double *slope) const;

  private:
    static constexpr unsigned int lanes = 8;
    /// Per order k (zero-padded to whole blocks of lanes): a_k, b_k, k a_k, k b_k.
    std::vector<double> cos_, sin_, k_cos_, k_sin_;
  };
} // namespace nsm
