// A real trigonometric series q = sum_i v_i phi_i on the harmonic balance's
// basis at the samples tau_s = 2 pi s / N of a period, s = 0..N-1, by one
// complex-to-real FFT (FFTW) of size N: O(N log N) instead of the O(N M) of
// summing the basis functions sample by sample. With a_k and b_k the
// coefficients of cos k tau and sin k tau,
//     q(tau_s) = a_0 + sum_{k>=1} Re[(a_k - i b_k) e^{i k tau_s}],
// the inverse DFT of the Hermitian spectrum c_0 = a_0, c_k = (a_k - i b_k) / 2.
// Needs N > 2M (no aliasing), which both integration rules meet.
#pragma once

#include <nsm/harmonic_balance/trigonometric.h>

#include <memory>
#include <vector>

namespace nsm
{
  class SeriesSamples
  {
  public:
    SeriesSamples(TrigonometricBasis basis, unsigned int samples);
    ~SeriesSamples();
    SeriesSamples(const SeriesSamples &) = delete;
    SeriesSamples &operator=(const SeriesSamples &) = delete;

    /// q at the samples (q resized to N).
    void operator()(const std::vector<double> &v, std::vector<double> &q) const;

  private:
    struct Plan;
    TrigonometricBasis    basis_;
    unsigned int          samples_;
    std::unique_ptr<Plan> plan_;
  };
} // namespace nsm
