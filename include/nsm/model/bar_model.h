// The physical bar: material, length and the cross-section law A(x).
#pragma once

#include <nsm/scene/bar_parameters.h>

#include <memory>
#include <vector>

namespace dealii
{
  template <int dim>
  class FunctionParser;
}

namespace nsm
{
  /// The wave's travel time along a bar of one material, tau = L sqrt(rho /
  /// E) (the section plays no part): the clamped-free frequencies go like
  /// w_j ~ (j - 1/2) pi / tau.
  double travel_time(const BarParameters &bar);

  /// Where the internal resonances of clamped-free mode n crowd: w_j = k W
  /// with 2j - 1 = k (2n - 1) accumulate at (2n - 1) pi / (2 tau).
  double accumulation_frequency(const BarParameters &bar, unsigned int mode);

  class BarModel
  {
  public:
    /// Parses the cross-section expression; throws InputError if it is
    /// malformed or not positive at a fine sampling of [0, L].
    explicit BarModel(const BarParameters &bar);
    ~BarModel();

    double length() const { return length_; }
    double young_modulus() const { return young_modulus_; }
    double density() const { return density_; }

    /// nsm::travel_time of this bar.
    double travel_time() const;

    /// nsm::accumulation_frequency of this bar.
    double accumulation_frequency(unsigned int mode) const;

    /// A(x); throws InputError if A(x) <= 0 or not finite.
    double cross_section(double x) const;

  private:
    double                                     length_;
    double                                     young_modulus_;
    double                                     density_;
    std::string                                expression_;
    std::unique_ptr<dealii::FunctionParser<1>> section_;
  };
} // namespace nsm
