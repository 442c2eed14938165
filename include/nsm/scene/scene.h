// A scene: every parameter of one run, read once from a ParameterHandler file
// and validated before any work is done.
#pragma once

#include <nsm/base/errors.h>
#include <nsm/scene/bar_parameters.h>
#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/continuation_parameters.h>
#include <nsm/scene/damping_parameters.h>
#include <nsm/scene/discretisation_parameters.h>
#include <nsm/scene/forcing_parameters.h>
#include <nsm/scene/harmonic_balance_parameters.h>
#include <nsm/scene/output_parameters.h>
#include <nsm/scene/parameter_limits.h>
#include <nsm/scene/receptance_parameters.h>
#include <nsm/scene/resources_parameters.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  /// Every parameter of one run: the composition of the subsections, each of
  /// which declares its own entries, with the bounds in the Patterns and the
  /// default stated once (its member initialisers), and parses them back.
  /// Scene adds the checks that involve more than one subsection.
  struct Scene
  {
    BarParameters             bar;
    ContactParameters         contact;
    DiscretisationParameters  discretisation;
    ReceptanceParameters      receptance;
    HarmonicBalanceParameters harmonic_balance;
    ContinuationParameters    continuation;
    DampingParameters         damping;
    ForcingParameters         forcing;
    ResourcesParameters       resources;
    OutputParameters          output;

    /// Every entry outside Output and Resources, as "Section/Entry = value":
    /// what decides the continuation's points. A run resumed with --resume
    /// must share them with the run it continues (continuation/checkpoint.h).
    std::vector<std::string> computation_entries;

    /// The scene as read, every entry (the --set values applied, the output
    /// directory resolved), as a parameter file that runs it again: the run
    /// record's parameters.prm. Empty for a scene not read from a file.
    std::string parameter_file;

    /// Where the scene was read from (the scene file; a study's row says so).
    std::string origin;

    /// Reads and validates a scene file; throws InputError.
    static Scene from_file(const std::string &path);

    /// Parses and validates a scene from `prm`, which holds a scene file read
    /// by read_scene_file (perhaps with values changed since); `origin` names
    /// it in messages. A study (`is_study`) may ask for plots without a
    /// backbone or fields: it plots its own table. Throws InputError.
    static Scene from_parameters(dealii::ParameterHandler &prm, const std::string &origin,
                                 bool is_study = false);

    /// Declares every parameter with its default, bounds and documentation.
    static void declare(dealii::ParameterHandler &prm);

    /// Time samples per period of the fields (CSV, snapshots, plots).
    unsigned int field_time_samples() const;

    /// Largest frequency at which the run evaluates the receptance: the
    /// poles below it are counted, and give the internal resonances.
    double receptance_band() const;

    /// The band over which adaptive refinement resolves the receptance.
    double refinement_band() const;

    /// Checks between subsections: when the scene is read, and again once
    /// Discretisation/Cells = 0 is chosen (model/band_cells.h).
    void check_consistency(bool is_study) const;

    /// Entries set away from their defaults that this scene never uses
    /// (damping without a drive, the forced verification without a curve
    /// to verify), one line each for the run summary: the run simulates only
    /// what the scene calls for, and says what it left unused.
    std::vector<std::string> unused_entries() const;

  private:
    /// The checks of a scene with Forcing/Amplitudes.
    void check_forcing() const;
  };
} // namespace nsm
