#include <nsm/harmonic_balance/trigonometric_series.h>
#include <nsm/base/vector_clones.h>
#include <nsm/base/assertions.h>

namespace nsm
{
  TrigonometricSeries::TrigonometricSeries(const TrigonometricBasis &basis, const std::vector<double> &v)
  {
    AssertDimension(v.size(), basis.size());
    const unsigned int harmonics = basis.order.empty() ? 0 : basis.order.back();
    const unsigned int size      = (harmonics / lanes + 1) * lanes;
    cos_.assign(size, 0.0);
    sin_.assign(size, 0.0);
    for (unsigned int i = 0; i < basis.size(); ++i)
      (basis.sine[i] ? sin_ : cos_)[basis.order[i]] += v[i];
    k_cos_.resize(size);
    k_sin_.resize(size);
    for (unsigned int k = 0; k < size; ++k)
      k_cos_[k] = k * cos_[k], k_sin_[k] = k * sin_[k];
  }

  namespace
  {
    /// The sums over the blocks of `lanes` orders, the lanes' chains rotated
    /// by lanes * tau per block; built for AVX2 and FMA where the processor
    /// has them (GCC function multiversioning).
    template <unsigned int lanes>
    NSM_CLONES_AVX2 void
    block_sums(const unsigned int size, const double *__restrict a, const double *__restrict b,
               const double *__restrict ka, const double *__restrict kb, const double *c0, const double *s0,
               const double step_c, const double step_s, double *value, double *slope)
    {
      // Local lanes: the compiler keeps them in vector registers.
      double c[lanes], s[lanes], q[lanes] = {}, dq[lanes] = {};
      for (unsigned int l = 0; l < lanes; ++l)
        c[l] = c0[l], s[l] = s0[l];
      for (unsigned int k = 0; k < size; k += lanes)
        {
          for (unsigned int l = 0; l < lanes; ++l)
            {
              q[l] += a[k + l] * c[l] + b[k + l] * s[l];
              dq[l] += kb[k + l] * c[l] - ka[k + l] * s[l];
              const double next = c[l] * step_c - s[l] * step_s;
              s[l]              = s[l] * step_c + c[l] * step_s;
              c[l]              = next;
            }
        }
      double v = 0, d = 0;
      for (unsigned int l = 0; l < lanes; ++l)
        v += q[l], d += dq[l];
      *value = v, *slope = d;
    }
  } // namespace

  double TrigonometricSeries::operator()(const double tau, double *slope) const
  {
    const double c1 = std::cos(tau), s1 = std::sin(tau);
    double       c[lanes], s[lanes];
    c[0] = 1, s[0] = 0;
    for (unsigned int l = 1; l < lanes; ++l)
      {
        c[l] = c[l - 1] * c1 - s[l - 1] * s1;
        s[l] = s[l - 1] * c1 + c[l - 1] * s1;
      }
    const double step_c = c[lanes - 1] * c1 - s[lanes - 1] * s1; // cos(lanes tau)
    const double step_s = s[lanes - 1] * c1 + c[lanes - 1] * s1;
    double value, derivative;
    block_sums<lanes>(cos_.size(), cos_.data(), sin_.data(), k_cos_.data(), k_sin_.data(), c, s, step_c, step_s,
                      &value, &derivative);
    if (slope)
      *slope = derivative;
    return value;
  }
} // namespace nsm
