// What one run of a study's row measures: the references it compares
// with, and the run itself, its stages timed.
#pragma once

#include <nsm/continuation/continuation.h>
#include <nsm/model/exact_references.h>
#include <nsm/study/study_parameters.h>
#include <nsm/study/study_row.h>
#include <nsm/verification/stage_runner.h>

#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  /// The values a row's measures compare with, computed once per row and
  /// outside the timed stages, so that the costs are the run's alone: the
  /// bar's exact spectrum, receptance and mode where known, else the fine
  /// backbone reference's points.
  struct RowReference
  {
    std::string                        name = "none";
    bool                               exact_bar = false;
    std::vector<double>                frequencies; ///< the first Spectrum modes clamped-free ones
    std::vector<double>                gammas;      ///< at the Receptance frequencies
    std::vector<std::optional<double>> energies, forces, fractions; ///< at the Backbone omegas
    std::optional<ExactBar>            mode_bar; ///< knows the first mode's energy at any Omega
  };

  /// What one run measured; empty optionals were not measured.
  struct RowMeasures
  {
    unsigned int          dofs = 0, cells = 0, hb_unknowns = 0, time_samples = 0;
    unsigned int          spectrum_modes = 0; ///< measured: Study/Spectrum modes, or fewer on a coarse mesh
    std::optional<double> spectrum_error, receptance_error, energy_error_max, energy_error_median,
      force_error_max, contact_fraction_error_max, main_error_median, main_error_q90, time_defect_median,
      time_defect_max;
    unsigned int          energy_points = 0, main_points = 0;
    /// Study/Forced peaks: the curves traced (with a point), those traced
    /// whole (ForcedCurve::whole), those of these whose peak has main points
    /// on both sides, the largest |E_peak / E_main - 1| among these, and the
    /// peaks' phase lags' extremes.
    unsigned int          forced_curves = 0, forced_curves_whole = 0, forced_peaks_compared = 0;
    /// Of the whole curves' peaks not compared: at the range's end, and
    /// never touching the wall (forced_peak's reasons; the rest have no main
    /// point on both sides).
    unsigned int forced_peaks_at_range_end = 0, forced_peaks_linear = 0;
    std::optional<double> forced_peak_distance_max, forced_peak_phase_min, forced_peak_phase_max;
    std::vector<std::optional<MainBranchPoint>> points; ///< at each Backbone omega on the main branch
    std::vector<BackbonePoint>                  solved; ///< those found, for the verification in time
    unsigned long         newton_iterations = 0, failed_solves = 0;
    std::string           backbone_end; ///< backbone_end_name; empty without harmonic balance
    std::optional<double> omega_reached;
    /// The continuation stopped short strictly inside the span of the
    /// Backbone omegas: the backbone errors cover part of them only, so they
    /// are not comparable with other rows' (left off the energy error's
    /// Pareto front). Empty without harmonic balance.
    std::optional<bool> energy_error_partial;
  };

  /// The timed stages, in the order of their study.csv columns.
  const std::vector<std::string> &study_stages();

  /// Nothing to compare with: a run measured for its own values.
  RowReference no_reference(const StudyScene &row);

  /// The bar's exact references where it has them, else the fine
  /// backbone reference's points (if `fine` is given).
  RowReference reference_of(const StudyScene &row, const FineReference *fine);

  /// One run of the stages the study's measures need, each timed on
  /// `stages` under its study_stages() name, with its errors against
  /// `reference`. Throws NumericalError.
  RowMeasures measure_run(const StudyScene &row, const RowReference &reference, StageRunner &stages);
} // namespace nsm
