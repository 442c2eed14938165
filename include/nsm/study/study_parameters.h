// The Study subsection of a scene: which discretisation parameters a study
// sweeps, and what it measures in each run.
#pragma once

#include <nsm/scene/scene.h>

#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  struct StudyParameters
  {
    /// One swept parameter: where it lives in the scene, and its values as
    /// text (each already checked against that parameter's own pattern).
    struct Sweep
    {
      std::string              subsection; ///< "Discretisation", "Harmonic balance/..."
      std::string              name;       ///< the scene parameter it sets
      std::string              study_entry; ///< the Study entry that lists the values
      std::string              column;     ///< its column in study.csv
      std::vector<std::string> values;     ///< empty: the base scene's value only
      /// A run uses the value only where the column `used_if_column` holds
      /// `used_if_value` (empty: always).
      std::string used_if_column, used_if_value;
    };

    std::vector<Sweep>  sweeps;
    unsigned int        spectrum_modes = 0; ///< errors of the first n clamped-free frequencies
    std::string         receptance_frequencies; ///< as written, for the runs' scenes
    std::vector<double> receptance_frequency_values;
    std::string         backbone_omegas; ///< as written
    std::vector<double> backbone_omega_values;
    unsigned int        repeats = 1;
    /// Integrate the main-branch points found at the Backbone omegas in time
    /// (Output/Verify steps and periods): their periodicity defect measures
    /// the harmonic balance against a true periodic motion where no exact mode
    /// is known.
    bool verify_in_time = false;
    /// Trace the row's forced-response curves and compare their peaks with
    /// its main branch (needs Backbone omegas and Forcing/Amplitudes).
    bool forced_peaks = false;
    /// Each row's Forcing/Amplitudes times its Damping/Modal ratio over the
    /// scene's (study_combinations sets them).
    bool forcing_scaled = false;
    /// The fine backbone reference's degree ("" = the base scene's) and its
    /// cell counts, coarse to fine (empty: no fine reference). The finest
    /// level is the reference; the others show its convergence.
    std::string              reference_degree;
    std::vector<std::string> reference_cells;

    /// A scene is a study when it measures something.
    bool enabled() const;

    /// Throws InputError unless Reference cells is empty or two or more
    /// increasing counts with Backbone omegas set.
    void check_reference_cells() const;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  /// A scene file that may be a study: the scene, and its Study subsection.
  struct StudyScene
  {
    Scene           scene;
    StudyParameters study;

    /// Reads and validates a scene file with or without a Study
    /// subsection; throws InputError.
    static StudyScene from_file(const std::string &path);

    /// Parses and validates both parts from `prm` (declared by declare());
    /// `origin` names the file in messages. Throws InputError.
    static StudyScene from_parameters(dealii::ParameterHandler &prm, const std::string &origin);

    /// Declares the scene's parameters and the Study subsection.
    static void declare(dealii::ParameterHandler &prm);

  private:
    /// Checks between the Study subsection and the scene.
    void check_consistency() const;
  };

  /// Two spellings of one swept value: the same text, or the same number
  /// ("2" and "02", "0.002" and "2e-3").
  bool same_study_value(const std::string &a, const std::string &b);
} // namespace nsm
