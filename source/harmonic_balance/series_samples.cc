#include <nsm/harmonic_balance/series_samples.h>
#include <nsm/base/assertions.h>

#include <fftw3.h>

#include <cstring>
#include <mutex>
#include <stdexcept>

namespace nsm
{
  namespace
  {
    /// FFTW's planner is not thread-safe; its plans, once made, are.
    std::mutex &planner_mutex()
    {
      static std::mutex mutex;
      return mutex;
    }
  } // namespace

  /// The plan and its arrays (FFTW's aligned allocation).
  struct SeriesSamples::Plan
  {
    explicit Plan(const unsigned int samples)
    {
      const std::lock_guard<std::mutex> lock(planner_mutex());
      spectrum = fftw_alloc_complex(samples / 2 + 1);
      values   = fftw_alloc_real(samples);
      // FFTW_ESTIMATE: a plan at once, without trial transforms (made once
      // per harmonic balance; FFTW_MEASURE would cost more than it saves).
      plan = fftw_plan_dft_c2r_1d(int(samples), spectrum, values, FFTW_ESTIMATE);
      if (!plan)
        throw std::runtime_error("FFTW could not plan a transform of size " + std::to_string(samples));
    }
    ~Plan()
    {
      const std::lock_guard<std::mutex> lock(planner_mutex());
      fftw_destroy_plan(plan);
      fftw_free(spectrum);
      fftw_free(values);
    }
    fftw_complex *spectrum;
    double       *values;
    fftw_plan     plan;
  };

  SeriesSamples::SeriesSamples(TrigonometricBasis basis, const unsigned int samples)
    : basis_(std::move(basis))
    , samples_(samples)
    , plan_(std::make_unique<Plan>(samples))
  {}

  SeriesSamples::~SeriesSamples() = default;

  void SeriesSamples::operator()(const std::vector<double> &v, std::vector<double> &q) const
  {
    AssertDimension(v.size(), basis_.size());
    fftw_complex *c = plan_->spectrum;
    std::memset(c, 0, sizeof(fftw_complex) * (samples_ / 2 + 1));
    for (unsigned int i = 0; i < basis_.size(); ++i)
      {
        const unsigned int k = basis_.order[i];
        if (k == 0)
          c[0][0] += v[i];
        else if (basis_.sine[i])
          c[k][1] -= 0.5 * v[i];
        else
          c[k][0] += 0.5 * v[i];
      }
    // The c2r transform overwrites its input: the spectrum is rebuilt above
    // on every call.
    fftw_execute(plan_->plan);
    q.assign(plan_->values, plan_->values + samples_);
  }
} // namespace nsm
