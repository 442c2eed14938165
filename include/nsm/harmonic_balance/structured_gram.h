// The Gram matrix of the harmonic balance's trigonometric basis over a part A
// of the period, G_ij = P_i[phi_j on A], in the structured form its entries
// take. With C_m and S_m the integrals of cos m tau and sin m tau over A
// (m = 0..2M; for the sampled rule, sums over the samples in A times
// 2 pi / samples), the product identities (trigonometric.h) give, for basis
// functions of orders k and l,
//     cos k cos l: (C_|k-l| + C_k+l) / 2,    sin k sin l: (C_|k-l| - C_k+l) / 2,
//     sin k cos l: (S_k+l + sgn(k-l) S_|k-l|) / 2,
//     cos k sin l: (S_k+l - sgn(k-l) S_|k-l|) / 2,
// times the projection's norm (1 / 2 pi for k = 0, 1 / pi otherwise): a
// Toeplitz part in |k - l| plus a Hankel part in k + l. The 2 (2M + 1)
// numbers hold the n x n matrix, computed in O(M) per interval end (or per
// active sample); the matrix is formed from them once per active set.
#pragma once

#include <nsm/harmonic_balance/trigonometric.h>

#include <utility>
#include <vector>

namespace nsm
{
  class StructuredGram
  {
  public:
    explicit StructuredGram(const TrigonometricBasis &basis);

    /// A is the union of the intervals [a, b] (each at most a period long).
    void set_intervals(const std::vector<std::pair<double, double>> &intervals);
    /// A is the samples tau_s = 2 pi s / samples listed in `active`.
    void set_samples(const std::vector<unsigned int> &active, unsigned int samples);

    /// |A| / 2 pi.
    double share() const { return share_; }

    /// out = G v, from the dense matrix (formed once per active set: NOX
    /// asks for the Jacobian at the point of each residual but the last).
    void multiply(const std::vector<double> &v, std::vector<double> &out) const;
    /// G, row-major n x n, formed on the first call after set_*.
    const std::vector<double> &dense() const;
    /// G into `dense`, row-major n x n.
    void fill(std::vector<double> &dense) const;

  private:
    TrigonometricBasis  basis_;
    bool                cosines_only_; ///< the cosine basis: order[i] == i
    /// Per order k, the index of cos k tau and of sin k tau in the basis (-1: absent).
    std::vector<int>    cosine_index_, sine_index_;
    std::vector<double> norm_;         ///< the projection's norm per basis function
    std::vector<double> cos_integrals_, sin_integrals_;
    double              share_ = 0;
    mutable std::vector<double> dense_;
    mutable bool                dense_valid_ = false;
  };
} // namespace nsm
