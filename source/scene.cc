#include <nsm/scene.h>
#include <nsm/scene_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace nsm
{
  namespace
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;

    constexpr double big  = Scene::magnitude_limit;
    constexpr double tiny = 1.0 / Scene::magnitude_limit;

    /// The shortest text that reads back as the same double.
    std::string format_value(const double value)
    {
      for (int digits = 6;; ++digits)
        {
          std::ostringstream out;
          out.precision(digits);
          out << value;
          if (digits >= 17 || std::stod(out.str()) == value)
            return out.str();
        }
    }

    std::string text(const double value) { return format_value(value); }
    std::string text(const unsigned int value) { return std::to_string(value); }
    std::string text(const bool value) { return value ? "true" : "false"; }

    void require(const bool         ok,
                 const std::string &parameter,
                 const std::string &allowed,
                 const std::string &value)
    {
      if (!ok)
        throw InputError("parameter '" + parameter + "' = " + value +
                         " is out of range: allowed " + allowed);
    }

    std::string trim(const std::string &s)
    {
      const auto first = s.find_first_not_of(" \t");
      if (first == std::string::npos)
        return "";
      const auto last = s.find_last_not_of(" \t");
      return s.substr(first, last - first + 1);
    }

    double parse_double(const std::string &text, const std::string &parameter)
    {
      std::size_t used = 0;
      double      value;
      try
        {
          value = std::stod(text, &used);
        }
      catch (const std::exception &)
        {
          used = 0;
        }
      if (used == 0 || trim(text.substr(used)) != "" || !std::isfinite(value))
        throw InputError("parameter '" + parameter + "': '" + text +
                         "' is not a finite number");
      return value;
    }

    /// The names of an enumeration's values in a Selection pattern.
    template <typename Enum>
    using Options = std::vector<std::pair<std::string, Enum>>;

    template <typename Enum>
    Patterns::Selection selection(const Options<Enum> &options)
    {
      std::string names;
      for (const auto &[name, value] : options)
        names += (names.empty() ? "" : "|") + name;
      return Patterns::Selection(names);
    }

    template <typename Enum>
    std::string name_of(const Enum value, const Options<Enum> &options)
    {
      for (const auto &[name, v] : options)
        if (v == value)
          return name;
      return options.front().first;
    }

    /// A Selection value (already checked against its pattern).
    template <typename Enum>
    Enum selected(const std::string &name, const Options<Enum> &options)
    {
      for (const auto &[n, value] : options)
        if (n == name)
          return value;
      return options.front().second;
    }

    const Options<ForceSign> force_signs = {{"physical", ForceSign::physical},
                                            {"seed-eq5", ForceSign::seed_eq5}};
    const Options<Refinement> refinements = {{"none", Refinement::none},
                                             {"graded", Refinement::graded},
                                             {"adaptive", Refinement::adaptive}};
    const Options<ReceptanceMethod> receptance_methods = {{"direct", ReceptanceMethod::direct},
                                                          {"modal", ReceptanceMethod::modal}};
    const Options<HarmonicBasis> bases = {{"cosine", HarmonicBasis::cosine},
                                          {"full", HarmonicBasis::full}};
    const Options<Integration> integrations = {{"sampled", Integration::sampled},
                                               {"exact", Integration::exact}};
    const Options<ContinuationMethod> continuation_methods = {
      {"sequential", ContinuationMethod::sequential},
      {"arclength", ContinuationMethod::arclength}};

    unsigned int get_unsigned(ParameterHandler &prm, const std::string &name)
    {
      return static_cast<unsigned int>(prm.get_integer(name));
    }

    /// Smallest cell of a graded mesh relative to L (make_mesh's sizes).
    double graded_smallest_cell(const Scene::Discretisation &d, const unsigned int layers)
    {
      double total = d.cells - layers;
      for (unsigned int i = 1; i <= layers; ++i)
        total += std::pow(d.graded_ratio, i);
      return std::pow(d.graded_ratio, layers) / total;
    }

    void require_graded_cells_above_roundoff(const Scene::Discretisation &d)
    {
      if (graded_smallest_cell(d, d.graded_layers) >= d.smallest_cell())
        return;
      unsigned int allowed = d.graded_layers;
      while (allowed > 0 && graded_smallest_cell(d, allowed) < d.smallest_cell())
        --allowed;
      require(false,
              "Discretisation/Graded/Layers",
              "at most " + std::to_string(allowed) + " with Ratio = " +
                format_value(d.graded_ratio) + " and Cells = " + std::to_string(d.cells) +
                " (more make cells smaller than " + format_value(d.smallest_cell()) +
                " L, where the round-off floor eps p^2 L / h_min exceeds "
                "Discretisation/Round-off limit = " + format_value(d.roundoff_limit) + ")",
              std::to_string(d.graded_layers));
    }
  } // namespace

  std::string one_line_message(const dealii::ExceptionBase &e)
  {
    std::ostringstream info;
    e.print_info(info);
    std::istringstream words(info.str());
    std::string        message, word;
    while (words >> word)
      message += (message.empty() ? "" : " ") + word;
    return message;
  }

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
    prm.declare_entry("Enabled", text(d.enabled), Patterns::Bool(), "Rigid wall at x = L + gap; a backbone needs it.");
    prm.declare_entry("Gap", text(d.gap), Patterns::Double(tiny, big), "Initial gap g0.");
    prm.declare_entry("Alpha",
                      text(d.alpha),
                      Patterns::Double(tiny, big),
                      "alpha of the contact law -lambda + max(lambda - alpha g, 0) = 0.");
    prm.declare_entry("Force sign",
                      name_of(d.sign, force_signs),
                      selection(force_signs),
                      "physical: the wall pushes the bar back, u_N = -gamma lambda; seed-eq5: the "
                      "paper's eq. (5) literally, u_N = +gamma lambda.");
    prm.leave_subsection();
  }

  void Scene::Contact::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    enabled = prm.get_bool("Enabled");
    gap     = prm.get_double("Gap");
    alpha   = prm.get_double("Alpha");
    sign    = selected(prm.get("Force sign"), force_signs);
    prm.leave_subsection();
  }

  void Scene::Discretisation::declare(ParameterHandler &prm)
  {
    const Discretisation d;
    prm.enter_subsection("Discretisation");
    prm.declare_entry("Degree", text(d.degree), Patterns::Integer(1, 20), "FE_Q degree p.");
    prm.declare_entry("Cells", text(d.cells), Patterns::Integer(1, 1000000), "Initial cells.");
    prm.declare_entry("Quadrature points",
                      text(d.quadrature_points),
                      Patterns::Integer(0, 64),
                      "Gauss points per cell; 0 = degree + 2 (exact for a cross-section "
                      "polynomial of degree <= 3); otherwise at least degree + 1, which "
                      "integrates the mass matrix of a constant section exactly.");
    prm.declare_entry("Round-off limit",
                      text(d.roundoff_limit),
                      Patterns::Double(1e-12, 1e-6),
                      "Largest accepted round-off floor eps p^2 L / h_min of the stiffness "
                      "matrix: the relative error that rounding alone puts on gamma and the "
                      "spectrum when the smallest cell is h_min. Graded meshes with smaller "
                      "cells are rejected; adaptive refinement stops before it makes them. "
                      "Above 1e-6 the LU of K - w^2 M itself breaks down.");
    prm.declare_entry("Refinement",
                      name_of(d.refinement, refinements),
                      selection(refinements),
                      "Mesh refinement towards the contact end x = L.");
    prm.enter_subsection("Graded");
    prm.declare_entry("Ratio",
                      text(d.graded_ratio),
                      Patterns::Double(1e-6, 1),
                      "Size ratio of neighbouring cells in the graded layer.");
    prm.declare_entry("Layers",
                      text(d.graded_layers),
                      Patterns::Integer(0, 1000000),
                      "Cells at the contact end that shrink geometrically; at most Cells, and "
                      "the smallest within the Round-off limit.");
    prm.leave_subsection();
    prm.enter_subsection("Adaptive");
    prm.declare_entry("Steps", text(d.adaptive_steps), Patterns::Integer(0, 50), "Refinement steps at most.");
    prm.declare_entry("Tolerance",
                      text(d.adaptive_tolerance),
                      Patterns::Double(1e-15, 0.1),
                      "Target relative error of gamma over the band.");
    prm.declare_entry("Refine fraction",
                      text(d.adaptive_fraction),
                      Patterns::Double(1e-6, 1),
                      "Fraction of cells refined per step (at least one cell).");
    prm.declare_entry("Band max omega",
                      text(d.adaptive_band_max),
                      Patterns::Double(0, frequency_limit),
                      "Upper end of the frequency band of the estimator; 0 = the largest "
                      "frequency the scene needs.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  void Scene::Discretisation::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretisation");
    degree            = get_unsigned(prm, "Degree");
    cells             = get_unsigned(prm, "Cells");
    quadrature_points = get_unsigned(prm, "Quadrature points");
    require(quadrature_points == 0 || quadrature_points >= degree + 1,
            "Discretisation/Quadrature points",
            "0 (= Degree + 2) or an integer in [Degree + 1, 64] = [" + std::to_string(degree + 1) +
              ", 64]: fewer make the mass matrix singular",
            std::to_string(quadrature_points));
    roundoff_limit = prm.get_double("Round-off limit");
    refinement     = selected(prm.get("Refinement"), refinements);
    prm.enter_subsection("Graded");
    graded_ratio  = prm.get_double("Ratio");
    graded_layers = get_unsigned(prm, "Layers");
    require(graded_layers <= cells,
            "Discretisation/Graded/Layers",
            "an integer in [0, Cells] = [0, " + std::to_string(cells) + "]",
            std::to_string(graded_layers));
    require_graded_cells_above_roundoff(*this);
    prm.leave_subsection();
    prm.enter_subsection("Adaptive");
    adaptive_steps     = get_unsigned(prm, "Steps");
    adaptive_tolerance = prm.get_double("Tolerance");
    adaptive_fraction  = prm.get_double("Refine fraction");
    adaptive_band_max  = prm.get_double("Band max omega");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  double Scene::Discretisation::smallest_cell() const
  {
    return std::numeric_limits<double>::epsilon() * degree * degree / roundoff_limit;
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
    prm.declare_entry("Max iterations", text(d.max_iterations), Patterns::Integer(1, 1000), "Newton iterations per solve.");
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

  void Scene::Continuation::declare(ParameterHandler &prm)
  {
    const Continuation d;
    prm.enter_subsection("Continuation");
    prm.declare_entry("Method",
                      name_of(d.method, continuation_methods),
                      selection(continuation_methods),
                      "sequential: steps in Omega (the paper); arclength: LOCA pseudo-arclength.");
    prm.declare_entry("Mode",
                      text(d.mode),
                      Patterns::Integer(1, 1000000),
                      "Clamped-free mode j whose grazing starts the branch; at most the number "
                      "of modes of the mesh.");
    prm.declare_entry("Omega min", text(d.omega_min), Patterns::Double(0, frequency_limit), "Lower end of the Omega range.");
    prm.declare_entry("Omega max",
                      text(d.omega_max),
                      Patterns::Double(0, frequency_limit),
                      "Upper end of the Omega range, > Omega min; harmonics up to Harmonics x "
                      "Omega max are resolved.");
    prm.declare_entry("Energy max",
                      text(d.energy_max),
                      Patterns::Double(1e-300, 1e300),
                      "Points above it are not kept: the branch is climbing a resonance tongue, "
                      "and the run leaps past it to a new segment; above the energy at grazing.");
    prm.declare_entry("Initial step",
                      text(d.initial_step),
                      Patterns::Double(1e-15, frequency_limit),
                      "First step in Omega (arclength: in arclength, unscaled) and first leap "
                      "distance.");
    prm.declare_entry("Min step",
                      text(d.min_step),
                      Patterns::Double(1e-15, frequency_limit),
                      "Smallest step before a fold is declared; <= Initial step.");
    prm.declare_entry("Max step",
                      text(d.max_step),
                      Patterns::Double(1e-15, frequency_limit),
                      "Largest step in Omega (arclength: in arclength, unscaled, so also in "
                      "Omega), >= Initial step; never more than a tenth of the range covered.");
    prm.declare_entry("Max steps", text(d.max_steps), Patterns::Integer(1, 1000000), "Most backbone points.");
    prm.declare_entry("Grazing offset",
                      text(d.grazing_offset),
                      Patterns::Double(1e-12, 1e-2),
                      "Relative distance of the first try from grazing, W = w_j (1 +- offset), "
                      "doubled until Newton converges.");
    prm.declare_entry("Tongue share",
                      text(d.tongue_share),
                      Patterns::Double(1e-4, 1),
                      "A point is labelled a tongue point if its energy exceeds the least energy "
                      "written at or beyond its Omega (in the direction of continuation) by more "
                      "than this share; otherwise it is on the main branch.");
    prm.declare_entry("Tongue energy ratio",
                      text(d.tongue_energy_ratio),
                      Patterns::Double(1, 1e6),
                      "Arclength follows a resonance tongue until its energy reaches this many "
                      "times the energy where the segment first turned back (a fold), then "
                      "leaps to the main branch beyond the tongue.");
    prm.declare_entry("Max contact change",
                      text(d.max_contact_change),
                      Patterns::Double(1e-6, 1),
                      "Largest change of the contact fraction from one point of a segment to "
                      "the next; a larger one is a jump to another branch, and the step is "
                      "shortened.");
    prm.declare_entry("Max solution change",
                      text(d.max_solution_change),
                      Patterns::Double(1e-3, 10),
                      "Largest change of the HB unknowns from one point of a segment to the "
                      "next, relative to their norm; a larger one is a jump to another branch, "
                      "and the step is shortened.");
    prm.declare_entry("Leap energy ratio",
                      text(d.leap_energy_ratio),
                      Patterns::Double(1.001, 1e6),
                      "A leap lands only below this many times the energy before the fold (above "
                      "it, on a tongue's flank) and above the least energy written within reach "
                      "behind the front divided by it.");
    prm.declare_entry("Search reach",
                      text(d.search_reach),
                      Patterns::Double(1e-4, 0.5),
                      "How far, relative to Omega, the start searches from grazing and a leap "
                      "searches beyond the front for a converged point.");
    prm.leave_subsection();
  }

  void Scene::Continuation::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Continuation");
    method    = selected(prm.get("Method"), continuation_methods);
    mode      = get_unsigned(prm, "Mode");
    omega_min = prm.get_double("Omega min");
    omega_max = prm.get_double("Omega max");
    require(omega_max > omega_min,
            "Continuation/Omega max",
            "> Omega min = " + format_value(omega_min),
            format_value(omega_max));
    energy_max   = prm.get_double("Energy max");
    initial_step = prm.get_double("Initial step");
    min_step     = prm.get_double("Min step");
    require(min_step <= initial_step,
            "Continuation/Min step",
            "<= Initial step = " + format_value(initial_step),
            format_value(min_step));
    max_step = prm.get_double("Max step");
    require(max_step >= initial_step,
            "Continuation/Max step",
            ">= Initial step = " + format_value(initial_step),
            format_value(max_step));
    max_steps      = get_unsigned(prm, "Max steps");
    grazing_offset = prm.get_double("Grazing offset");
    tongue_share   = prm.get_double("Tongue share");
    tongue_energy_ratio = prm.get_double("Tongue energy ratio");
    max_contact_change  = prm.get_double("Max contact change");
    max_solution_change = prm.get_double("Max solution change");
    leap_energy_ratio   = prm.get_double("Leap energy ratio");
    search_reach        = prm.get_double("Search reach");
    require(grazing_offset < search_reach,
            "Continuation/Grazing offset",
            "< Search reach = " + format_value(search_reach),
            format_value(grazing_offset));
    prm.leave_subsection();
  }

  void Scene::Output::declare(ParameterHandler &prm)
  {
    const Output d;
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      d.directory,
                      Patterns::Anything(),
                      "Output directory: a new one, or one that an earlier run wrote. A run "
                      "writes into a hidden sibling and swaps it in at the end, so the "
                      "directory holds the previous complete output or the new one.");
    prm.declare_entry("Spectrum modes",
                      text(d.spectrum_modes),
                      Patterns::Integer(0, 100000),
                      "Eigenfrequencies written to spectrum.csv; 0 = none.");
    prm.declare_entry("Receptance frequencies",
                      "",
                      Patterns::Anything(),
                      "Frequencies of receptance.csv: numbers and ranges a:b:n separated by "
                      "commas, in [0, 1e100]; empty = none.");
    prm.declare_entry("Backbone", text(d.backbone), Patterns::Bool(), "Write backbone.csv and resonances.csv.");
    prm.declare_entry("Fields at",
                      "",
                      Patterns::Anything(),
                      "Omega of the mode fields, solved exactly there on the branch: numbers "
                      "and ranges a:b:n in [Omega min, Omega max]; empty = none.");
    prm.declare_entry("Fields every",
                      text(d.fields_every),
                      Patterns::Integer(0, 1000000),
                      "Also a field at every n-th backbone point; 0 = none.");
    prm.declare_entry("Field time samples",
                      text(d.field_time_samples),
                      Patterns::Integer(0, 100000),
                      "Samples per period of the fields (CSV rows, snapshots, plots, and the "
                      "space-time mesh); 0 = 2 (2 M + 1); else at least 4.");
    prm.declare_entry("VTK",
                      text(d.vtk),
                      Patterns::Bool(),
                      "ParaView files of the fields: space-time .vtu, .pvd of 1D snapshots, "
                      "fields.pvd.");
    prm.declare_entry("Plots",
                      text(d.plots),
                      Patterns::Bool(),
                      "PNG plots: backbone.png, and per field a space-time colour map and the "
                      "contact end over one period.");
    prm.declare_entry("Progress every",
                      text(d.progress_every),
                      Patterns::Double(0, 1e6),
                      "Seconds between progress lines on stderr during long stages "
                      "(continuation, adaptive refinement, fields, verification); 0 = never.");
    prm.declare_entry("Verify in time",
                      text(d.verify_in_time),
                      Patterns::Bool(),
                      "Integrate backbone points in time on the same FE model with the physical "
                      "wall and write how far they are from periodic (backbone.csv); needs "
                      "Backbone = true.");
    prm.declare_entry("Verify every",
                      text(d.verify_every),
                      Patterns::Integer(1, 1000000),
                      "Verify every n-th backbone point (the fields' points always).");
    prm.declare_entry("Verify periods", text(d.verify_periods), Patterns::Integer(1, 1000), "Periods integrated.");
    prm.declare_entry("Verify steps",
                      text(d.verify_steps),
                      Patterns::Integer(16, 10000000),
                      "Time steps per period of the verification (Newmark, average acceleration).");
    prm.declare_entry("Verify tolerance",
                      text(d.verify_tolerance),
                      Patterns::Double(1e-12, 1e3),
                      "A point whose one-period defect max |u(T) - u(0)| / g0 exceeds this is "
                      "flagged verified = false.");
    prm.leave_subsection();
  }

  void Scene::Output::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Directory");
    require(!directory.empty(), "Output/Directory", "a non-empty path", "''");
    spectrum_modes = get_unsigned(prm, "Spectrum modes");
    receptance_frequencies =
      parse_frequency_list(prm.get("Receptance frequencies"), "Output/Receptance frequencies");
    backbone     = prm.get_bool("Backbone");
    fields_at    = parse_frequency_list(prm.get("Fields at"), "Output/Fields at");
    fields_every = get_unsigned(prm, "Fields every");
    field_time_samples = get_unsigned(prm, "Field time samples");
    require(field_time_samples == 0 || field_time_samples >= 4,
            "Output/Field time samples",
            "0 or an integer in [4, 100000]",
            std::to_string(field_time_samples));
    vtk            = prm.get_bool("VTK");
    plots          = prm.get_bool("Plots");
    progress_every = prm.get_double("Progress every");
    verify_in_time   = prm.get_bool("Verify in time");
    verify_every     = get_unsigned(prm, "Verify every");
    verify_periods   = get_unsigned(prm, "Verify periods");
    verify_steps     = get_unsigned(prm, "Verify steps");
    verify_tolerance = prm.get_double("Verify tolerance");
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
    StudyParameters::declare(prm);
  }

  void Scene::check_consistency() const
  {
    require(!output.vtk || output.fields(),
            "Output/VTK",
            "false unless fields are requested (Output/Fields at or Output/Fields every)",
            "true");
    require(!output.plots || output.fields() || output.backbone || study.enabled(),
            "Output/Plots",
            "false unless Output/Backbone = true, fields are requested or the scene is a study",
            "true");
    require(!output.fields() || contact.enabled,
            "Output/Fields at",
            "empty (and Fields every = 0) when Contact/Enabled = false",
            "a list");
    require(!output.verify_in_time || output.backbone,
            "Output/Verify in time",
            "false unless Output/Backbone = true (the results are columns of backbone.csv)",
            "true");
    require(!output.backbone || contact.enabled,
            "Output/Backbone",
            "false when Contact/Enabled = false (no contact, no nonsmooth mode)",
            "true");
    for (const double w : study.backbone_omega_values)
      require(contact.enabled && w >= continuation.omega_min && w <= continuation.omega_max,
              "Study/Backbone omegas",
              "frequencies in [Omega min, Omega max] = [" + format_value(continuation.omega_min) +
                ", " + format_value(continuation.omega_max) + "], with Contact/Enabled = true",
              format_value(w));
    for (const double w : output.fields_at)
      require(w >= continuation.omega_min && w <= continuation.omega_max,
              "Output/Fields at",
              "frequencies in [Omega min, Omega max] = [" + format_value(continuation.omega_min) +
                ", " + format_value(continuation.omega_max) + "]",
              format_value(w));
    // The clamped-free problem has one mode per DoF but the clamped one; an
    // adaptive mesh adds DoFs, so its modes are checked once it is made.
    const unsigned int modes = discretisation.cells * discretisation.degree;
    require((!output.backbone && !output.fields()) ||
              discretisation.refinement == Refinement::adaptive || continuation.mode <= modes,
            "Continuation/Mode",
            "an integer in [1, Cells x Degree] = [1, " + std::to_string(modes) +
              "] (the modes of the mesh)",
            std::to_string(continuation.mode));
  }

  Scene Scene::from_file(const std::string &path)
  {
    ParameterHandler prm;
    declare(prm);
    read_scene_file(path, prm);
    return from_parameters(prm, path);
  }

  Scene Scene::from_parameters(ParameterHandler &prm, const std::string &origin)
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
        scene.study.parse(prm);
        scene.check_consistency();
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
    if (output.backbone)
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

  unsigned int Scene::time_samples() const
  {
    if (harmonic_balance.time_samples != 0)
      return harmonic_balance.time_samples;
    unsigned int n = 1;
    while (n < 16 * harmonic_balance.harmonics)
      n *= 2;
    return n;
  }
} // namespace nsm
