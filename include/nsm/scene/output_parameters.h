// The Output subsection: what a run writes and how it checks its points
// (output/, verification/ and app/ read it). It declares and parses its own
// entries; Scene (scene.h) composes the subsections.
#pragma once

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  struct OutputParameters
  {
    /// Empty: output/NAME, NAME the scene file's name without its
    /// extension (Scene::from_parameters), so that scenes without a
    /// Directory never write into one folder.
    std::string         directory;
    /// The directory is the default output/NAME: it belongs to the scene
    /// file that made it (output/output_directory.h), and another scene file
    /// with the same NAME is refused it.
    bool                directory_is_default = false;
    unsigned int        spectrum_modes = 0;
    std::vector<double> receptance_frequencies;
    bool                backbone       = false;
    bool                harmonics_table = false; ///< harmonics.csv: every point's coefficients
    bool                bar_amplitude   = false; ///< backbone.csv's max_displacement column
    bool                error_estimate  = true;  ///< backbone.csv's energy_error_estimate column
    std::vector<double> fields_at;              ///< Omega of each field
    unsigned int        fields_every       = 0; ///< every n-th backbone point; 0 = none
    unsigned int        field_time_samples = 0; ///< 0: 2 (2 M + 1)
    bool                vtk                = false;
    /// The VTK files' time axis: t / T (the plots' axis) instead of t.
    bool vtk_time_over_period = false;
    bool                plots              = false;
    double              progress_every     = 5.0; ///< seconds; 0 = never
    bool                verify_in_time     = false;
    unsigned int        verify_every       = 1;
    unsigned int        verify_periods     = 5;
    unsigned int        verify_steps       = 4000; ///< time steps per period
    double              verify_tolerance   = 0.01; ///< largest periodicity defect of a verified point
    bool                refine_in_time     = false;
    unsigned int        refine_every       = 10;   ///< every n-th main point
    double              stability_margin   = 1e-4; ///< stable: every |Floquet multiplier| <= 1 + margin

    bool fields() const { return !fields_at.empty() || fields_every > 0; }

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };

  /// Parses "0, 0.5, 2:3:11" (a:b:n = n values from a to b) into a list:
  /// Output/Receptance frequencies and Fields at, and the Study's lists.
  std::vector<double> parse_frequency_list(const std::string &text,
                                           const std::string &parameter);
} // namespace nsm
