#include <nsm/base/text.h>
#include <nsm/scene/scene.h>
#include <nsm/scene/scene_entries.h>
#include <nsm/scene/scene_file.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <tuple>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;
  } // namespace

  void Scene::declare(ParameterHandler &prm)
  {
    BarParameters::declare(prm);
    ContactParameters::declare(prm);
    DiscretisationParameters::declare(prm);
    ReceptanceParameters::declare(prm);
    HarmonicBalanceParameters::declare(prm);
    ContinuationParameters::declare(prm);
    DampingParameters::declare(prm);
    ForcingParameters::declare(prm);
    OutputParameters::declare(prm);
    ResourcesParameters::declare(prm);
  }

  void Scene::check_consistency(const bool is_study) const
  {
    require(!output.vtk || output.fields(),
            "Output/VTK",
            "false unless fields are requested (Output/Fields at or Output/Fields every)",
            "true");
    require(!output.plots || output.fields() || output.backbone || forcing.enabled() || is_study,
            "Output/Plots",
            "false unless Output/Backbone = true, fields or a forced response (Forcing/Amplitudes) are requested or "
            "the scene is a study",
            "true");
    require(!output.fields() || contact.enabled,
            "Output/Fields at",
            "empty (and Fields every = 0) when Contact/Enabled = false",
            "a list");
    // Outputs that are columns or rows of the backbone's tables.
    for (const auto &[wanted, entry, what] :
         {std::tuple{output.verify_in_time, "Output/Verify in time", "the results are columns of backbone.csv"},
          std::tuple{output.refine_in_time, "Output/Refine in time", "the results are columns of backbone.csv"},
          std::tuple{output.harmonics_table, "Output/Harmonics table", "one row per backbone point and harmonic"},
          std::tuple{output.bar_amplitude, "Output/Bar amplitude", "a column of backbone.csv"}})
      require(!wanted || output.backbone, entry,
              std::string("false unless Output/Backbone = true (") + what + ")", "true");
    require(!output.refine_in_time || contact.wall == Wall::rigid,
            "Output/Refine in time",
            "false when Contact/Wall = compliant (its exact flow follows the rigid wall's impacts only)",
            "true");
    require(!output.backbone || contact.enabled,
            "Output/Backbone",
            "false when Contact/Enabled = false (no contact, no nonsmooth mode)",
            "true");
    // An automatic Omega max (0) is checked once the FE model sets it.
    for (const double w : output.fields_at)
      require(w >= continuation.omega_min && (continuation.omega_max == 0 || w <= continuation.omega_max),
              "Output/Fields at",
              "frequencies in [Omega min, Omega max] = [" + format_value(continuation.omega_min) +
                ", " + format_value(continuation.omega_max) + "]",
              format_value(w));
    // The clamped-free problem has one mode per DoF but the clamped one; an
    // adaptive mesh adds DoFs, so its modes are checked once it is made.
    require(discretisation.cells != 0 || (discretisation.refinement != Refinement::adaptive && !is_study),
            "Discretisation/Cells",
            std::string("an integer in [1, 1000000] ") +
              (is_study ? "in a study (0 chooses a run's cells for its band)" :
                          "with Refinement = adaptive (which refines for the band itself)"),
            "0");
    // Cells = 0: checked once chosen (model/band_cells.h).
    const bool         known = discretisation.refinement != Refinement::adaptive && discretisation.cells != 0;
    const unsigned int modes = discretisation.cells * discretisation.degree;
    require(!known || output.spectrum_modes < modes,
            "Output/Spectrum modes",
            "an integer in [0, Cells x Degree - 1] = [0, " + std::to_string(modes - 1) +
              "] (spectrum.csv pairs each clamped-free frequency with a clamped-clamped one, and the "
              "clamped-clamped mesh has Cells x Degree - 1 modes)",
            std::to_string(output.spectrum_modes));
    // Without inertia at the contact DoF the clamped-free problem loses a mode.
    const bool         redistributed = discretisation.contact_mass == ContactMass::redistributed;
    const unsigned int free_modes    = redistributed ? modes - 1 : modes;
    require((!output.backbone && !output.fields()) ||
              !known || continuation.mode <= free_modes,
            "Continuation/Mode",
            "an integer in [1, " + std::string(redistributed ? "Cells x Degree - 1" : "Cells x Degree") + "] = [1, " +
              std::to_string(free_modes) + "] (the modes of the mesh)",
            std::to_string(continuation.mode));
    require(!redistributed || receptance.method == ReceptanceMethod::direct || receptance.modes == 0,
            "Receptance/Modes",
            "0 (every mode) or Receptance/Method = direct when Discretisation/Contact mass = redistributed: a "
            "truncated basis needs a mass matrix with inertia at every DoF",
            std::to_string(receptance.modes));
    check_forcing();
    require(!redistributed || modes >= 2, "Discretisation/Contact mass",
            "consistent when Cells x Degree = 1 (redistributed moves the contact DoF's mass to the DoFs beside it, "
            "and there are none)",
            "redistributed");
  }

  void Scene::check_forcing() const
  {
    if (!forcing.enabled())
      return;
    require(damping.any(), "Damping/Modal ratio",
            "a number in (0, 1], or Rayleigh alpha or beta > 0, when Forcing/Amplitudes or Omegas is set (an undamped "
            "drive has no bounded linear response at resonance)",
            "0");
    require(contact.enabled, "Contact/Enabled", "true when Forcing/Amplitudes or Omegas is set (the gap scales the forced "
            "response's unknowns; a gap no motion reaches gives the linear response)", "false");
    require(receptance.method == ReceptanceMethod::modal, "Receptance/Method",
            "modal when Forcing/Amplitudes or Omegas is set (the damped receptance is a modal sum)", "direct");
    require(forcing.verify_every == 0 || contact.sign == ForceSign::physical, "Forcing/Verify every",
            "0 when Contact/Force sign = seed-eq5 (the time integration has the physical wall)",
            std::to_string(forcing.verify_every));
    require(!forcing.floquet || contact.wall == Wall::compliant, "Forcing/Floquet",
            "false unless Contact/Wall = compliant (the rigid wall's impacts are not continuous in the state, and "
            "the time steps' derivatives miss their saltation)",
            "true");
    require(!forcing.floquet || forcing.verify_every > 0, "Forcing/Floquet",
            "false when Forcing/Verify every = 0 (the multipliers are computed at the points verified)", "true");
  }

  Scene Scene::from_file(const std::string &path)
  {
    ParameterHandler prm;
    declare(prm);
    read_scene_file(path, prm);
    return from_parameters(prm, path);
  }

  namespace
  {
    /// output/NAME, NAME the scene file's name without its extension
    /// ("scene" for a name that has none left).
    std::string default_directory(const std::string &scene_file)
    {
      std::string name = std::filesystem::path(scene_file).stem().string();
      if (name.empty() || name == "." || name == "..")
        name = "scene";
      // The record holds the folder: a name it would not read back (not
      // UTF-8; a '#', a trailing backslash, white space at an end) has no
      // default.
      const bool recordable = is_valid_utf8(name) && name.find('#') == std::string::npos && name.back() != '\\' &&
                              !std::isspace(static_cast<unsigned char>(name.front())) &&
                              !std::isspace(static_cast<unsigned char>(name.back()));
      if (!recordable)
        throw InputError("parameter 'Output/Directory' is empty, and its default output/NAME would take NAME from "
                         "the scene file's name, '" + printable(name) +
                         "', which the run's record cannot hold (allowed: UTF-8 text without '#', without a "
                         "backslash at its end and without white space at either end): set Output/Directory (or "
                         "--output)");
      return "output/" + name;
    }
  } // namespace

  Scene Scene::from_parameters(ParameterHandler &prm, const std::string &origin, const bool is_study)
  {
    Scene scene;
    try
      {
        scene.bar.parse(prm);
        scene.contact.parse(prm);
        scene.discretisation.parse(prm);
        scene.receptance.parse(prm);
        scene.harmonic_balance.parse(prm);
        scene.continuation.parse(prm);
        scene.damping.parse(prm);
        scene.forcing.parse(prm);
        scene.output.parse(prm);
        if (scene.output.directory.empty())
          {
            scene.output.directory            = default_directory(origin);
            scene.output.directory_is_default = true;
          }
        scene.origin = origin;
        scene.resources.parse(prm);
        scene.check_consistency(is_study);
        for (const DeclaredEntry &entry : declared_entries(prm))
          if (entry.sections.empty() || (entry.sections.front() != "Output" &&
                                         entry.sections.front() != "Resources" && entry.sections.front() != "Study"))
            scene.computation_entries.push_back(entry.path() + " = " + entry.value);
        // Output entries that shape the model: the band the receptance and an
        // adaptive mesh resolve.
        scene.computation_entries.push_back(
          "receptance band (the largest of Output/Receptance frequencies and Harmonics x Omega max) = " +
          significant(scene.receptance_band(), 17));
        scene.computation_entries.push_back("adaptive refinement band = " + significant(scene.refinement_band(), 17));
      }
    catch (const InputError &e)
      {
        throw InputError("scene '" + origin + "': " + e.what());
      }
    return scene;
  }

  double Scene::receptance_band() const
  {
    double w = 0;
    for (const double f : output.receptance_frequencies)
      w = std::max(w, f);
    // A field is a point of the backbone: the run traces it for fields alone too.
    if (output.backbone || output.fields() || forcing.enabled())
      w = std::max(w, harmonic_balance.harmonics * continuation.omega_max);
    // A curve in F at a fixed W asks the receptance for its harmonics too.
    for (const double omega : forcing.omegas)
      w = std::max(w, harmonic_balance.harmonics * omega);
    return w;
  }

  double Scene::refinement_band() const
  {
    return discretisation.adaptive_band_max > 0 ? discretisation.adaptive_band_max : receptance_band();
  }

  unsigned int Scene::field_time_samples() const
  {
    return output.field_time_samples != 0 ? output.field_time_samples :
                                            2 * (2 * harmonic_balance.harmonics + 1);
  }

  std::vector<std::string> Scene::unused_entries() const
  {
    std::vector<std::string> unused;
    if (damping.any() && !forcing.enabled())
      unused.push_back("Damping (Modal ratio, Rayleigh alpha or beta) is set but unused: the scene drives nothing "
                       "(Forcing/Amplitudes and Omegas are empty), and the backbone is undamped");
    if (forcing.amplitudes.empty() && (forcing.verify_every > 0 || forcing.floquet))
      unused.push_back(std::string(forcing.verify_every > 0 && forcing.floquet ? "Forcing/Verify every and Floquet are" :
                                   forcing.floquet                             ? "Forcing/Floquet is" :
                                                                                 "Forcing/Verify every is") +
                       " set but unused: the forced verification checks the curves in W, and Forcing/Amplitudes is "
                       "empty");
    return unused;
  }
} // namespace nsm
