// The active set {tau : q(tau) > 0} of a trigonometric series
// q = sum_i v_i phi_i on the harmonic balance's basis, and the Gram matrix of
// the basis over it, G_ij = P_i[phi_j on {q > 0}]: the projection of the
// Signorini law max(q, 0) (harmonic_balance.h).
//
// Both rules sample q by FFT (series_samples.h). The exact rule finds the
// roots of q (bracketed on the samples, then refined on the series,
// trigonometric_series.h) and integrates cos m tau and sin m tau between them
// in closed form; the sampled rule sums them over the samples where q > 0. The
// Gram matrix follows from those integrals (structured_gram.h).
#pragma once

#include <nsm/harmonic_balance/series_samples.h>
#include <nsm/harmonic_balance/structured_gram.h>
#include <nsm/harmonic_balance/trigonometric.h>
#include <nsm/harmonic_balance/trigonometric_series.h>
#include <nsm/scene/harmonic_balance_parameters.h>

#include <vector>

namespace nsm
{
  /// The sampled rule's Time samples, or the exact rule's bracketing grid.
  unsigned int active_set_samples(const HarmonicBalanceParameters &params);

  class ActiveSet
  {
  public:
    /// samples: the sampled rule's points per period, or the exact rule's
    /// bracketing grid.
    ActiveSet(TrigonometricBasis basis, Integration integration, unsigned int samples);

    unsigned int n_samples() const { return samples_; }
    /// A series on the basis with coefficients v at the samples
    /// tau_s = 2 pi s / samples.
    void sample(const std::vector<double> &v, std::vector<double> &q) const { sampler_(v, q); }

    /// The Gram matrix over {q > 0}, in structured form (its share() is the
    /// share of the period where q > 0). The last v's result is kept: NOX
    /// asks for the residual and the Jacobian at one point separately.
    const StructuredGram &gram(const std::vector<double> &v) const;

    /// q(tau), and q'(tau) if slope is given.
    double value(const std::vector<double> &v, double tau, double *slope) const;
    /// Roots of q in [0, 2 pi), sorted.
    std::vector<double> roots(const std::vector<double> &v) const;

  private:
    /// Adds to `found` the two roots of q around sample t when q has an
    /// extremum there towards zero that the samples q (of v) do not show
    /// crossing it; `reach` bounds how far q departs between samples.
    /// roots(v), with the series of v already made.
    std::vector<double> roots(const std::vector<double> &v, const TrigonometricSeries &series) const;
    void crossings_near_extremum(const TrigonometricSeries &series, const std::vector<double> &q, unsigned int t,
                                 double reach, std::vector<double> &found) const;
    void gram_exact(const std::vector<double> &v) const;
    void gram_sampled(const std::vector<double> &v) const;

    TrigonometricBasis  basis_;
    Integration         integration_;
    unsigned int        samples_;
    SeriesSamples       sampler_;

    mutable std::vector<double> cached_coefficients_;
    mutable StructuredGram      cached_gram_;
  };
} // namespace nsm
