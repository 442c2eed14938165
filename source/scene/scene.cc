#include <nsm/base/text.h>
#include <nsm/scene/scene.h>
#include <nsm/scene/scene_entries.h>
#include <nsm/scene/scene_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <tuple>
#include <utility>

namespace nsm
{
  namespace
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;
    using namespace scene_entries;

    constexpr double big  = Scene::magnitude_limit;
    constexpr double tiny = 1.0 / Scene::magnitude_limit;

    const Options<ForceSign> force_signs = {{"physical", ForceSign::physical},
                                            {"seed-eq5", ForceSign::seed_eq5}};
    const Options<Wall> walls = {{"rigid", Wall::rigid}, {"compliant", Wall::compliant}};
    const Options<ReceptanceMethod> receptance_methods = {{"direct", ReceptanceMethod::direct},
                                                          {"modal", ReceptanceMethod::modal}};
    const Options<HarmonicBasis> bases = {{"cosine", HarmonicBasis::cosine},
                                          {"full", HarmonicBasis::full}};
    const Options<Integration> integrations = {{"sampled", Integration::sampled},
                                               {"exact", Integration::exact}};
  } // namespace

  std::vector<double> parse_frequency_list(const std::string &text,
                                           const std::string &parameter)
  {
    std::vector<double> values;
    std::stringstream   items(text);
    std::string         item;
    while (std::getline(items, item, ','))
      {
        item = trim(item);
        if (item.empty())
          continue;
        std::vector<std::string> parts;
        std::stringstream        fields(item);
        std::string              field;
        while (std::getline(fields, field, ':'))
          parts.push_back(trim(field));
        if (parts.size() == 1)
          values.push_back(parse_double(parts[0], parameter));
        else if (parts.size() == 3)
          {
            const double a = parse_double(parts[0], parameter);
            const double b = parse_double(parts[1], parameter);
            const double n = parse_double(parts[2], parameter);
            require(n >= 2 && n <= 1e6 && n == std::floor(n) && b > a,
                    parameter,
                    "ranges a:b:n with a < b and an integer n in [2, 1e6]",
                    "'" + item + "'");
            for (unsigned int i = 0; i < n; ++i)
              values.push_back(a + (b - a) * i / (n - 1));
          }
        else
          throw InputError("parameter '" + parameter + "': '" + item +
                           "' is neither a number nor a range a:b:n");
      }
    for (const double w : values)
      require(w >= 0 && w <= Scene::frequency_limit,
              parameter,
              "frequencies in [0, " + format_value(Scene::frequency_limit) + "]",
              format_value(w));
    return values;
  }

  void Scene::Bar::declare(ParameterHandler &prm)
  {
    const Bar d;
    prm.enter_subsection("Bar");
    prm.declare_entry("Length", text(d.length), Patterns::Double(tiny, big), "Bar length L.");
    prm.declare_entry("Young modulus", text(d.young_modulus), Patterns::Double(tiny, big), "Young modulus E.");
    prm.declare_entry("Density", text(d.density), Patterns::Double(tiny, big), "Mass density rho.");
    prm.declare_entry("Cross section",
                      d.cross_section,
                      Patterns::Anything(),
                      "Cross-section area A(x), a muparser expression in x (constants pi and L "
                      "available); 1e-20 <= A(x) <= 1e20 on [0, L].");
    prm.leave_subsection();
  }

  void Scene::Bar::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Bar");
    length        = prm.get_double("Length");
    young_modulus = prm.get_double("Young modulus");
    density       = prm.get_double("Density");
    cross_section = prm.get("Cross section");
    prm.leave_subsection();
  }

  void Scene::Contact::declare(ParameterHandler &prm)
  {
    const Contact d;
    prm.enter_subsection("Contact");
    prm.declare_entry("Enabled", text(d.enabled), Patterns::Bool(), "A wall at x = L + gap; a backbone needs it.");
    prm.declare_entry("Gap", text(d.gap), Patterns::Double(tiny, big), "Initial gap g0.");
    prm.declare_entry("Alpha",
                      text(d.alpha),
                      Patterns::Double(tiny, big),
                      "alpha of the rigid wall's law -lambda + max(lambda - alpha g, 0) = 0 (a stiffness: it "
                      "scales the gap against the force in the switch).");
    prm.declare_entry("Force sign",
                      name_of(d.sign, force_signs),
                      selection(force_signs),
                      "physical: the wall pushes the bar back, u_N = -gamma lambda; seed-eq5: the "
                      "paper's eq. (5) literally, u_N = +gamma lambda.");
    prm.declare_entry("Wall",
                      name_of(d.wall, walls),
                      selection(walls),
                      "rigid: Signorini's law, lambda >= 0, g >= 0, lambda g = 0; compliant: a unilateral spring, "
                      "lambda = k max(-g, 0), solved as -lambda + max(-k g, 0) = 0 (doc/method.md, The wall).");
    prm.declare_entry("Wall stiffness",
                      text(d.stiffness),
                      Patterns::Double(tiny, big),
                      "k of a compliant wall, force per length; the rigid wall is its limit k -> infinity. The "
                      "bar's own static end stiffness is 1 / gamma(0) (E A / L for a uniform bar).");
    prm.leave_subsection();
  }

  void Scene::Contact::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    enabled = prm.get_bool("Enabled");
    gap     = prm.get_double("Gap");
    alpha   = prm.get_double("Alpha");
    sign    = selected(prm.get("Force sign"), force_signs);
    wall      = selected(prm.get("Wall"), walls);
    stiffness = prm.get_double("Wall stiffness");
    prm.leave_subsection();
  }

  void Scene::Receptance::declare(ParameterHandler &prm)
  {
    const Receptance d;
    prm.enter_subsection("Receptance");
    prm.declare_entry("Method",
                      name_of(d.method, receptance_methods),
                      selection(receptance_methods),
                      "direct: one band LU of K - w^2 M per frequency; modal: the modes below the band "
                      "once, then the modal sum.");
    prm.declare_entry("Modes",
                      text(d.modes),
                      Patterns::Integer(0, 10000000),
                      "Modal basis size, 0 = all; a truncated basis gets a static correction.");
    prm.leave_subsection();
  }

  void Scene::Receptance::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Receptance");
    method = selected(prm.get("Method"), receptance_methods);
    modes  = get_unsigned(prm, "Modes");
    prm.leave_subsection();
  }

  void Scene::HarmonicBalance::declare(ParameterHandler &prm)
  {
    const HarmonicBalance d;
    prm.enter_subsection("Harmonic balance");
    prm.declare_entry("Harmonics", text(d.harmonics), Patterns::Integer(1, 1000), "M.");
    prm.declare_entry("Time samples",
                      text(d.time_samples),
                      Patterns::Integer(0, 1 << 20),
                      "Samples per period; 0 = smallest power of two >= 16 M; otherwise >= 2 M + 1.");
    prm.declare_entry("Basis",
                      name_of(d.basis, bases),
                      selection(bases),
                      "cosine: motions even in time; full: sine and cosine with a phase condition.");
    prm.declare_entry("Integration",
                      name_of(d.integration, integrations),
                      selection(integrations),
                      "sampled: discrete Fourier transform of max(lambda - alpha g, 0) at the "
                      "samples; exact: integrals between the roots of lambda - alpha g.");
    prm.declare_entry("Tolerance",
                      text(d.tolerance),
                      Patterns::Double(1e-15, 1e-6),
                      "Newton tolerance on the scaled residual norm; a looser one would write "
                      "points that solve nothing.");
    prm.declare_entry("Max iterations",
                      text(d.max_iterations),
                      Patterns::Integer(0, 1000),
                      "Newton iterations per solve; 0 = max(12, M / 16): converging solves take more "
                      "iterations as M grows.");
    prm.declare_entry("Line search",
                      d.line_search,
                      Patterns::Selection("Full Step|Backtrack|Polynomial"),
                      "NOX line search method.");
    prm.leave_subsection();
  }

  void Scene::HarmonicBalance::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Harmonic balance");
    harmonics    = get_unsigned(prm, "Harmonics");
    time_samples = get_unsigned(prm, "Time samples");
    require(time_samples == 0 || time_samples >= 2 * harmonics + 1,
            "Harmonic balance/Time samples",
            "0 or an integer in [2 M + 1, 2^20] = [" + std::to_string(2 * harmonics + 1) +
              ", 1048576]",
            std::to_string(time_samples));
    basis          = selected(prm.get("Basis"), bases);
    integration    = selected(prm.get("Integration"), integrations);
    tolerance      = prm.get_double("Tolerance");
    max_iterations = get_unsigned(prm, "Max iterations");
    line_search    = prm.get("Line search");
    prm.leave_subsection();
  }

  unsigned int Scene::HarmonicBalance::iterations() const
  {
    // The iterations the converged solves of the seed bar take (FE_Q(10),
    // sequential, to 2.2): at most 12 at M = 80 and 160 (a few at the limit), up
    // to 20 at M = 320, where 12 lose the branch at 2.1530 and 20 carry it to
    // 2.2 (doc/accuracy-and-cost.md, "M = 320"). So 12 up to M = 207, then M / 16.
    constexpr unsigned int least = 12, harmonics_per_iteration = 16;
    return max_iterations != 0 ? max_iterations : std::max(least, harmonics / harmonics_per_iteration);
  }

  void Scene::Resources::declare(ParameterHandler &prm)
  {
    const Resources d;
    prm.enter_subsection("Resources");
    prm.declare_entry("Memory limit",
                      text(d.memory_limit),
                      Patterns::Double(0, 1e9),
                      "MiB a run may use; 0 = the memory the machine has available (and the process's "
                      "address-space limit). A scene whose estimated need exceeds it is refused before "
                      "any work, naming the entries that drive the estimate.");
    prm.leave_subsection();
  }

  void Scene::Resources::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Resources");
    memory_limit = prm.get_double("Memory limit");
    prm.leave_subsection();
  }

  void Scene::declare(ParameterHandler &prm)
  {
    Bar::declare(prm);
    Contact::declare(prm);
    Discretisation::declare(prm);
    Receptance::declare(prm);
    HarmonicBalance::declare(prm);
    Continuation::declare(prm);
    Output::declare(prm);
    Resources::declare(prm);
  }

  void Scene::check_consistency(const bool is_study) const
  {
    require(!output.vtk || output.fields(),
            "Output/VTK",
            "false unless fields are requested (Output/Fields at or Output/Fields every)",
            "true");
    require(!output.plots || output.fields() || output.backbone || is_study,
            "Output/Plots",
            "false unless Output/Backbone = true, fields are requested or the scene is a study",
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
    require(!redistributed || modes >= 2, "Discretisation/Contact mass",
            "consistent when Cells x Degree = 1 (redistributed moves the contact DoF's mass to the DoFs beside it, "
            "and there are none)",
            "redistributed");
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
        scene.output.parse(prm);
        if (scene.output.directory.empty())
          scene.output.directory = default_directory(origin);
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
    if (output.backbone || output.fields())
      w = std::max(w, harmonic_balance.harmonics * continuation.omega_max);
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

  unsigned int Scene::HarmonicBalance::samples() const
  {
    if (time_samples != 0)
      return time_samples;
    unsigned int n = 1;
    while (n < 16 * harmonics)
      n *= 2;
    return n;
  }
} // namespace nsm
