// A scene: every parameter of one run, read once from a ParameterHandler file
// and validated before any work is done.
#pragma once

#include <nsm/base/errors.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  enum class ForceSign
  {
    physical, ///< the wall pushes the bar in -x: u_N = -gamma lambda
    seed_eq5  ///< the paper's eq. (5) literally: u_N = +gamma lambda
  };

  /// What the bar's end meets beyond the gap (doc/method.md, "The wall").
  enum class Wall
  {
    rigid,    ///< Signorini: g >= 0, lambda >= 0, lambda g = 0
    compliant ///< a unilateral spring of stiffness k: lambda = k max(-g, 0)
  };

  enum class Refinement
  {
    none,
    graded,
    adaptive
  };

  /// Where the mass of the contact DoF goes.
  enum class ContactMass
  {
    consistent,   ///< the consistent mass matrix as assembled
    redistributed ///< moved to the DoFs it couples: no inertia at the contact DoF
  };

  enum class ReceptanceMethod
  {
    direct,
    modal
  };

  enum class HarmonicBasis
  {
    cosine,
    full
  };

  enum class Integration
  {
    sampled,
    exact
  };

  enum class ContinuationMethod
  {
    sequential,
    arclength
  };

  /// Every parameter of one run. Each part declares its own subsection, with
  /// the bounds in the Patterns and the default stated once (the member
  /// initialisers below), and parses it back with the checks that involve
  /// more than one parameter.
  struct Scene
  {
    /// Dimensional inputs (L, E, rho, A(x), g0, alpha, k) lie in
    /// [1 / magnitude_limit, magnitude_limit]: the products and quotients the
    /// run forms of them (frequencies, energies, contact forces) then stay
    /// finite and above the underflow threshold.
    static constexpr double magnitude_limit = 1e20;
    /// Frequencies (Omega, receptance and field frequencies, bands) lie in
    /// [0, frequency_limit]: w^2 times the mass matrix stays finite.
    static constexpr double frequency_limit = 1e100;

    struct Bar
    {
      double      length        = 1.0;
      double      young_modulus = 1.0;
      double      density       = 1.0;
      std::string cross_section = "1.5 - x";

      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    } bar;

    struct Contact
    {
      bool      enabled = true;
      double    gap     = 1e-3;
      double    alpha   = 1.0;
      ForceSign sign    = ForceSign::physical;
      Wall      wall    = Wall::rigid;
      double    stiffness = 100.0; ///< k of a compliant wall

      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    } contact;

    struct Discretisation
    {
      unsigned int degree             = 1;
      unsigned int cells              = 4000; ///< 0: chosen for the band (model/band_cells.h)
      unsigned int quadrature_points  = 0; ///< 0: degree + 2
      double       roundoff_limit     = 1e-7;
      Refinement   refinement         = Refinement::none;
      ContactMass  contact_mass       = ContactMass::consistent;
      double       graded_ratio       = 0.8;
      unsigned int graded_layers      = 0;
      unsigned int adaptive_steps     = 10;
      double       adaptive_tolerance = 1e-8;
      double       adaptive_fraction  = 0.3;
      double       adaptive_band_max  = 0.0; ///< 0: derived from the scene

      /// Smallest cell size, relative to L, that keeps the round-off floor
      /// eps p^2 L / h_min of the stiffness matrix within `roundoff_limit`.
      double smallest_cell() const;

      /// The checks that need Cells (Graded/Layers within it, the round-off
      /// floor of the graded layer): at parsing, or once Cells = 0 is chosen
      /// (model/band_cells.h).
      void check_cells() const;

      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    } discretisation;

    struct Receptance
    {
      ReceptanceMethod method = ReceptanceMethod::modal;
      unsigned int     modes  = 0; ///< modal basis size, 0 = all

      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    } receptance;

    struct HarmonicBalance
    {
      unsigned int  harmonics      = 40;
      unsigned int  time_samples   = 0; ///< 0: chosen from the harmonics
      HarmonicBasis basis          = HarmonicBasis::cosine;
      Integration   integration    = Integration::exact;
      double        tolerance      = 1e-10;
      unsigned int  max_iterations = 0; ///< 0: chosen from the harmonics (iterations())
      std::string   line_search    = "Full Step";

      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
      /// Newton iterations per solve: Max iterations, or where it is 0,
      /// max(12, M / 16).
      unsigned int iterations() const;
      /// Time samples of the sampled rule: Time samples, or where it is 0,
      /// the smallest power of 2 not below 16 M.
      unsigned int samples() const;
    } harmonic_balance;

    struct Continuation
    {
      ContinuationMethod method         = ContinuationMethod::sequential;
      unsigned int       mode           = 1;
      double             omega_min      = 0.0;
      double             omega_max      = 0.0; ///< 0: from the spectrum (automatic_range.h)
      double             energy_max     = 0.0; ///< 0: energy_max_over_grazing x E_g
      double             energy_max_over_grazing = 1000.0;
      double             initial_step   = 1e-3;
      double             min_step       = 1e-6;
      double             max_step       = 1e-2;
      unsigned int       max_steps      = 2000;
      double             grazing_offset = 1e-5;
      double             tongue_share   = 0.02;
      double             main_contact_drop = 0.1; ///< main_branch.h
      double             tongue_energy_ratio = 2.0;
      double             max_contact_change  = 0.01;
      double             max_solution_change = 0.2;
      double             leap_energy_ratio   = 4.0;
      double             search_reach        = 0.05;
      bool               leap_from_fewer_harmonics = true;
      double             fill_gaps_wider_than      = 0.02; ///< 0: no filling (gap_filling.h)

      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    } continuation;

    struct Resources
    {
      double memory_limit = 0; ///< MiB; 0: the memory the machine has available

      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    } resources;

    struct Output
    {
      /// Empty: output/NAME, NAME the scene file's name without its
      /// extension (Scene::from_parameters), so that scenes without a
      /// Directory never write into one folder.
      std::string         directory;
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
    } output;

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
  };

  /// Parses "0, 0.5, 2:3:11" (a:b:n = n values from a to b) into a list.
  std::vector<double> parse_frequency_list(const std::string &text,
                                           const std::string &parameter);
} // namespace nsm
