// Backbone points refined in time: from every Refine every-th main point,
// the FE model's periodic orbit (periodic_orbit.h), and HB's energy error
// against it.
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/model/discretisation.h>
#include <nsm/verification/fields.h>
#include <nsm/verification/periodic_orbit.h>
#include <nsm/scene/output_parameters.h>

#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  class Progress;

  /// The largest DoF count a refinement accepts: its dense modes, tangents
  /// and monodromy matrix hold about 16 n^2 doubles (0.5 GiB at 2000) and
  /// take O(n^3) per Newton step.
  constexpr unsigned int max_refined_dofs = 2001;

  /// Shoots from a point's HB motion at t = 0, `field` (and, if that fails,
  /// from `fallback`, a nearby orbit's displacement, when not empty).
  PeriodicOrbit refine_point(const PeriodicField &field, const Discretisation &discretisation, const ContactLaw &law,
                             const OutputParameters &output, const dealii::Vector<double> &fallback);

  /// The orbits of every Refine every-th main point (empty for the others),
  /// each tried from its own HB point and then from the last orbit found.
  /// `known` (one slot per point, or empty): orbits of a stopped run, kept
  /// instead of shot again.
  std::vector<std::optional<PeriodicOrbit>> refine_backbone(HarmonicBalance      &hb,
                                                            const Discretisation &discretisation,
                                                            const Backbone       &backbone,
                                                            const OutputParameters  &output,
                                                            Progress             &progress,
                                                            std::vector<std::optional<PeriodicOrbit>> known = {});

  /// HB's energy error against the orbit, E_HB / E_orbit - 1.
  double hb_energy_error(const BackbonePoint &point, const PeriodicOrbit &orbit);

  /// "refinement in time: ..." for the run summary.
  std::string refinement_summary(const Backbone &backbone, const std::vector<std::optional<PeriodicOrbit>> &orbits,
                                 const OutputParameters &output);
} // namespace nsm
