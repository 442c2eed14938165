// Adaptive refinement driven by the receptance fields over a frequency band.
#pragma once

#include <nsm/model/discretisation.h>

#include <string>
#include <vector>

namespace nsm
{
  class Progress;

  /// The band's sample frequencies: `count` midpoints of [0, band_max].
  std::vector<double> band_frequencies(double band_max, unsigned int count = 16);

  /// Refines until gamma of degree p and p + 1 agree to the tolerance over
  /// the band (relative to the largest |gamma| there) or the steps run out.
  /// Cells are marked by the Kelly indicators of h(w), each sample frequency
  /// weighted equally. Returns one line per step for the run summary, and
  /// reports them to `progress` as they come.
  std::vector<std::string> refine_adaptively(Discretisation              &discretisation,
                                             const DiscretisationParameters &params,
                                             double                       band_max,
                                             Progress                    *progress = nullptr);
} // namespace nsm
