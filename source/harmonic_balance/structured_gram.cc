#include <nsm/harmonic_balance/structured_gram.h>
#include <nsm/base/assertions.h>

namespace nsm
{
  StructuredGram::StructuredGram(const TrigonometricBasis &basis)
    : basis_(basis)
    , cosines_only_(true)
  {
    const unsigned int top = 2 * (basis_.order.empty() ? 0 : basis_.order.back()) + 1;
    cos_integrals_.assign(top, 0.0);
    sin_integrals_.assign(top, 0.0);
    const unsigned int harmonics = basis_.order.empty() ? 0 : basis_.order.back() + 1;
    cosine_index_.assign(harmonics, -1);
    sine_index_.assign(harmonics, -1);
    for (unsigned int i = 0; i < basis_.size(); ++i)
      {
        norm_.push_back((basis_.order[i] == 0 ? 1.0 : 2.0) / two_pi);
        cosines_only_ = cosines_only_ && !basis_.sine[i] && basis_.order[i] == i;
        (basis_.sine[i] ? sine_index_ : cosine_index_)[basis_.order[i]] = int(i);
      }
  }

  void StructuredGram::set_intervals(const std::vector<std::pair<double, double>> &intervals)
  {
    // C_m = sum (sin m b - sin m a) / m and S_m = sum (cos m a - cos m b) / m
    // over the intervals [a, b]: every end's cos m t and sin m t by the
    // angle-sum recurrence, all ends side by side (independent chains), the
    // sign of each end in `weight`.
    const unsigned int  top = cos_integrals_.size(), ends = 2 * intervals.size();
    std::vector<double> c(ends, 1.0), s(ends, 0.0), c1(ends), s1(ends), weight(ends);
    double              measure = 0;
    for (std::size_t i = 0; i < intervals.size(); ++i)
      {
        const auto [a, b] = intervals[i];
        measure += b - a;
        c1[2 * i] = std::cos(a), s1[2 * i] = std::sin(a), weight[2 * i] = -1;
        c1[2 * i + 1] = std::cos(b), s1[2 * i + 1] = std::sin(b), weight[2 * i + 1] = 1;
      }
    cos_integrals_[0] = measure;
    sin_integrals_[0] = 0;
    for (unsigned int m = 1; m < top; ++m)
      {
        double sum_s = 0, sum_c = 0;
#pragma omp simd reduction(+ : sum_s, sum_c)
        for (unsigned int e = 0; e < ends; ++e)
          {
            const double next = c[e] * c1[e] - s[e] * s1[e];
            s[e]              = s[e] * c1[e] + c[e] * s1[e];
            c[e]              = next;
            sum_s += weight[e] * s[e];
            sum_c += weight[e] * c[e];
          }
        cos_integrals_[m] = sum_s / m;
        sin_integrals_[m] = -sum_c / m;
      }
    share_       = measure / two_pi;
    dense_valid_ = false;
  }

  void StructuredGram::set_samples(const std::vector<unsigned int> &active, const unsigned int samples)
  {
    // cos(m tau_s) = cos(2 pi ((m s) mod samples) / samples): one table of the
    // samples' angles serves every m.
    const unsigned int  top = cos_integrals_.size();
    std::vector<double> c(samples), s(samples);
    for (unsigned int t = 0; t < samples; ++t)
      c[t] = std::cos(two_pi * t / samples), s[t] = std::sin(two_pi * t / samples);
    const double weight = two_pi / samples;
    for (unsigned int m = 0; m < top; ++m)
      {
        double sum_c = 0, sum_s = 0;
        for (const unsigned int t : active)
          {
            const unsigned int angle = static_cast<unsigned int>((std::size_t(m) * t) % samples);
            sum_c += c[angle];
            sum_s += s[angle];
          }
        cos_integrals_[m] = weight * sum_c;
        sin_integrals_[m] = weight * sum_s;
      }
    share_       = double(active.size()) / samples;
    dense_valid_ = false;
  }

  void StructuredGram::fill(std::vector<double> &dense) const
  {
    const unsigned int n = basis_.size();
    dense.resize(std::size_t(n) * n);
    if (!cosines_only_)
      {
        // Per pair of orders (k, l) the four products' integrals at once,
        // each written where both functions are in the basis.
        const double *c = cos_integrals_.data(), *s = sin_integrals_.data();
        const int     harmonics = int(cosine_index_.size());
        for (int k = 0; k < harmonics; ++k)
          for (int l = 0; l < harmonics; ++l)
            {
              const int    d = k >= l ? k - l : l - k, sum = k + l;
              const double sgn = k >= l ? 1.0 : -1.0;
              const int    ck = cosine_index_[k], sk = sine_index_[k], cl = cosine_index_[l], sl = sine_index_[l];
              const auto   put = [&](const int i, const int j, const double g) {
                if (i >= 0 && j >= 0)
                  dense[std::size_t(i) * n + j] = 0.5 * norm_[i] * g;
              };
              put(ck, cl, c[d] + c[sum]);
              put(sk, sl, c[d] - c[sum]);
              put(sk, cl, s[sum] + sgn * s[d]);
              put(ck, sl, s[sum] - sgn * s[d]);
            }
        return;
      }
    const double *c = cos_integrals_.data();
    for (unsigned int i = 0; i < n; ++i)
      {
        double      *row = dense.data() + std::size_t(i) * n;
        const double h   = 0.5 * norm_[i];
        for (unsigned int j = 0; j < i; ++j)
          row[j] = h * (c[i - j] + c[i + j]);
        for (unsigned int j = i; j < n; ++j)
          row[j] = h * (c[j - i] + c[i + j]);
      }
  }

  const std::vector<double> &StructuredGram::dense() const
  {
    if (!dense_valid_)
      fill(dense_);
    dense_valid_ = true;
    return dense_;
  }

  void StructuredGram::multiply(const std::vector<double> &v, std::vector<double> &out) const
  {
    const unsigned int         n = basis_.size();
    AssertDimension(v.size(), n);
    const std::vector<double> &g = dense();
    out.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double *row = g.data() + std::size_t(i) * n;
        double        sum = 0;
#pragma omp simd reduction(+ : sum)
        for (unsigned int j = 0; j < n; ++j)
          sum += row[j] * v[j];
        out[i] = sum;
      }
  }
} // namespace nsm
