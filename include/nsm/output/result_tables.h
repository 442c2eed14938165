// The CSV tables of one run's results: spectrum, receptance, backbone (with
// its verification in time), tongues and internal resonances.
#pragma once

#include <nsm/continuation/continuation.h>
#include <nsm/base/csv.h>
#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/output_parameters.h>
#include <nsm/verification/periodic_orbit.h>
#include <nsm/verification/time_verification.h>

#include <optional>
#include <vector>

namespace nsm
{
  class Discretisation;
  class Receptance;

  /// One entry per backbone point; empty for a point not verified in time.
  using Verifications = std::vector<std::optional<PointVerification>>;
  using RefinedOrbits = std::vector<std::optional<PeriodicOrbit>>;

  /// spectrum.csv: the first `modes` clamped-free and clamped-clamped
  /// eigenfrequencies.
  CsvTable spectrum_table(const Discretisation &d, unsigned int modes);

  /// receptance.csv: gamma and d gamma / d omega^2 at Output/Receptance
  /// frequencies.
  CsvTable receptance_table(const Receptance &receptance, const OutputParameters &output);

  /// backbone.csv: one row per point; energy_error_estimate if `estimates`
  /// (one per point, NaN: an empty cell) is not empty; the verification columns if
  /// `verifications` is not empty, the orbit columns if `orbits` is not empty
  /// (empty cells for a point not refined or whose orbit was not found), and
  /// max_displacement if `bar_amplitudes` (one per point) is not empty.
  CsvTable backbone_table(const Backbone &backbone, const std::vector<double> &estimates,
                          const Verifications &verifications, const RefinedOrbits &orbits,
                          const std::vector<double> &bar_amplitudes = {});

  /// harmonics.csv: per backbone point (its row in backbone.csv from 0) and
  /// harmonic, the contact force's and the contact end's displacement
  /// coefficients (hb's basis: cos k W t, or sin k W t where is_sine).
  CsvTable harmonics_table(HarmonicBalance &hb, const Backbone &backbone);

  /// tongues.csv: one row per tongue.
  CsvTable tongue_table(const Backbone &backbone);

  /// grazing.csv: the traced mode j, w_j and its grazing energy E_g =
  /// w_j^2 g0^2 / (2 phi_j(L)^2), the linear mode's energy with u(L) = g0
  /// (the plots' energy scale).
  CsvTable grazing_table(const Discretisation &discretisation, unsigned int mode, const ContactParameters &contact);

  /// resonances.csv: the internal resonances w_j / k in the range.
  CsvTable resonance_table(const std::vector<InternalResonance> &resonances);
} // namespace nsm
