#include <nsm/harmonic_balance/trigonometric_series.h>

namespace nsm
{
  TrigonometricSeries::TrigonometricSeries(const TrigonometricBasis &basis, const std::vector<double> &v)
  {
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
    double       q[lanes] = {}, dq[lanes] = {};
    for (unsigned int k = 0; k < cos_.size(); k += lanes)
      {
        for (unsigned int l = 0; l < lanes; ++l)
          {
            q[l] += cos_[k + l] * c[l] + sin_[k + l] * s[l];
            dq[l] += k_sin_[k + l] * c[l] - k_cos_[k + l] * s[l];
          }
        for (unsigned int l = 0; l < lanes; ++l)
          {
            const double next = c[l] * step_c - s[l] * step_s;
            s[l]              = s[l] * step_c + c[l] * step_s;
            c[l]              = next;
          }
      }
    double value = 0, derivative = 0;
    for (unsigned int l = 0; l < lanes; ++l)
      value += q[l], derivative += dq[l];
    if (slope)
      *slope = derivative;
    return value;
  }
} // namespace nsm
