#include <nsm/scene.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>

namespace nsm
{
  namespace
  {
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

    void require(const bool         ok,
                 const std::string &parameter,
                 const std::string &allowed,
                 const std::string &value)
    {
      if (!ok)
        throw InputError("parameter '" + parameter + "' = " + value +
                         " is out of range: allowed " + allowed);
    }

    void require_positive(const double value, const std::string &parameter)
    {
      require(std::isfinite(value) && value > 0,
              parameter,
              "a finite number > 0",
              format_value(value));
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
      require(w >= 0, parameter, "frequencies >= 0", format_value(w));
    return values;
  }

  void Scene::declare(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    const Scene d;

    prm.enter_subsection("Bar");
    prm.declare_entry("Length", "1", Double(), "Bar length L > 0.");
    prm.declare_entry("Young modulus", "1", Double(), "Young modulus E > 0.");
    prm.declare_entry("Density", "1", Double(), "Mass density rho > 0.");
    prm.declare_entry("Cross section",
                      d.bar.cross_section,
                      Anything(),
                      "Cross-section area A(x), a muparser expression in x "
                      "(constants pi and L available); must be > 0 on [0, L].");
    prm.leave_subsection();

    prm.enter_subsection("Contact");
    prm.declare_entry("Enabled", "true", Bool(), "Rigid wall at x = L + gap; a backbone needs it.");
    prm.declare_entry("Gap", "1e-3", Double(), "Initial gap g0 > 0.");
    prm.declare_entry("Alpha",
                      "1",
                      Double(),
                      "alpha > 0 of the contact law "
                      "-lambda + max(lambda - alpha g, 0) = 0.");
    prm.declare_entry("Force sign",
                      "physical",
                      Selection("physical|seed-eq5"),
                      "physical: the wall pushes the bar back, u_N = -gamma "
                      "lambda; seed-eq5: the paper's eq. (5) literally, u_N = "
                      "+gamma lambda.");
    prm.leave_subsection();

    prm.enter_subsection("Discretisation");
    prm.declare_entry("Degree", "1", Integer(), "FE_Q degree p, 1 to 20.");
    prm.declare_entry("Cells", "4000", Integer(), "Initial cells, 1 to 1e6.");
    prm.declare_entry("Quadrature points",
                      "0",
                      Integer(),
                      "Gauss points per cell; 0 = degree + 2 (exact for a "
                      "cross-section polynomial of degree <= 3).");
    prm.declare_entry("Refinement",
                      "none",
                      Selection("none|graded|adaptive"),
                      "Mesh refinement towards the contact end x = L.");
    prm.declare_entry("Round-off limit",
                      "1e-7",
                      Double(),
                      "Largest accepted round-off floor eps p^2 L / h_min of the stiffness matrix: "
                      "the relative error that rounding alone puts on gamma and the "
                      "spectrum when the smallest cell is h_min. Graded meshes with smaller "
                      "cells are rejected; adaptive refinement stops before it makes them. "
                      "1e-12 to 1e-6: beyond, the LU of K - w^2 M itself breaks down.");
    prm.enter_subsection("Graded");
    prm.declare_entry("Ratio",
                      "0.8",
                      Double(),
                      "Size ratio of neighbouring cells in the graded layer, "
                      "0 < ratio <= 1.");
    prm.declare_entry("Layers",
                      "0",
                      Integer(),
                      "Cells at the contact end that shrink geometrically, "
                      "0 to Cells.");
    prm.leave_subsection();
    prm.enter_subsection("Adaptive");
    prm.declare_entry("Steps", "10", Integer(), "Refinement steps, 0 to 50.");
    prm.declare_entry("Tolerance",
                      "1e-8",
                      Double(),
                      "Target relative error of gamma over the band, > 0.");
    prm.declare_entry("Refine fraction",
                      "0.3",
                      Double(),
                      "Fraction of cells refined per step, 0 < f <= 1.");
    prm.declare_entry("Band max omega",
                      "0",
                      Double(),
                      "Upper end of the frequency band of the estimator; 0 = "
                      "the largest frequency the scene needs.");
    prm.leave_subsection();
    prm.leave_subsection();

    prm.enter_subsection("Receptance");
    prm.declare_entry("Method",
                      "direct",
                      Selection("direct|modal"),
                      "direct: one sparse LU (UMFPACK) per frequency; modal: "
                      "eigen-decomposition once, then the modal sum.");
    prm.declare_entry("Modes",
                      "0",
                      Integer(),
                      "Modal basis size, 0 = all; a truncated basis gets a "
                      "static correction.");
    prm.leave_subsection();

    prm.enter_subsection("Harmonic balance");
    prm.declare_entry("Harmonics", "40", Integer(), "M, 1 to 1000.");
    prm.declare_entry("Time samples",
                      "0",
                      Integer(),
                      "Samples per period; 0 = smallest power of two >= 16 M; "
                      "otherwise >= 2 M + 1.");
    prm.declare_entry("Basis",
                      "cosine",
                      Selection("cosine|full"),
                      "cosine: motions even in time; full: sine and cosine "
                      "with a phase condition.");
    prm.declare_entry("Integration",
                      "exact",
                      Selection("sampled|exact"),
                      "sampled: discrete Fourier transform of max(lambda - "
                      "alpha g, 0) at the samples; exact: integrals between "
                      "the roots of lambda - alpha g.");
    prm.declare_entry("Tolerance",
                      "1e-10",
                      Double(),
                      "Newton tolerance on the scaled residual norm, > 0.");
    prm.declare_entry("Max iterations", "12", Integer(), "Newton iterations per solve, 1 to 1000.");
    prm.declare_entry("Line search",
                      "Full Step",
                      Selection("Full Step|Backtrack|Polynomial"),
                      "NOX line search method.");
    prm.leave_subsection();

    prm.enter_subsection("Continuation");
    prm.declare_entry("Method",
                      "sequential",
                      Selection("sequential|arclength"),
                      "sequential: steps in Omega (the paper); arclength: "
                      "LOCA pseudo-arclength.");
    prm.declare_entry("Mode",
                      "1",
                      Integer(),
                      "Clamped-free mode j whose grazing starts the branch, "
                      ">= 1.");
    prm.declare_entry("Omega min", "0", Double(), "Lower end of the Omega range, >= 0.");
    prm.declare_entry("Omega max", "2.2", Double(), "Upper end of the Omega range, > Omega min; harmonics up to Harmonics x Omega max are resolved.");
    prm.declare_entry("Energy max", "1", Double(), "Points above it are not kept: the branch is climbing a resonance tongue, and the run leaps past it to a new segment; > 0, and above the energy at grazing.");
    prm.declare_entry("Initial step", "1e-3", Double(), "First step in Omega (arclength: in arclength, unscaled) and first leap distance; > 0.");
    prm.declare_entry("Min step", "1e-6", Double(), "Smallest step before a fold is declared, > 0, <= Initial step.");
    prm.declare_entry("Max step", "1e-2", Double(), "Largest step in Omega (arclength: in arclength, unscaled, so also in Omega), >= Initial step; never more than a tenth of the range covered.");
    prm.declare_entry("Max steps", "2000", Integer(), "Most backbone points, 1 to 1e6.");
    prm.declare_entry("Grazing offset", "1e-5", Double(), "Relative distance of the first try from grazing, W = w_j (1 +- offset), doubled until Newton converges; 1e-12 to 1e-2.");
    prm.declare_entry("Tongue share", "0.02", Double(), "A point is labelled a tongue point if the energy of one harmonic k >= 3 stands above the geometric mean of harmonics k - 2 and k + 2 by more than this share of the total energy; otherwise it is on the main branch. 1e-4 to 1.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Directory", "output", Anything(), "Output directory.");
    prm.declare_entry("Spectrum modes",
                      "0",
                      Integer(),
                      "Eigenfrequencies written to spectrum.csv; 0 = none.");
    prm.declare_entry("Receptance frequencies",
                      "",
                      Anything(),
                      "Frequencies of receptance.csv: numbers and ranges "
                      "a:b:n separated by commas; empty = none.");
    prm.declare_entry("Backbone",
                      "false",
                      Bool(),
                      "Write backbone.csv and resonances.csv.");
    prm.declare_entry("Fields at",
                      "",
                      Anything(),
                      "Omega of the mode fields, solved exactly there on the "
                      "branch: numbers and ranges a:b:n; empty = none.");
    prm.declare_entry("Fields every",
                      "0",
                      Integer(),
                      "Also a field at every n-th backbone point; 0 = none.");
    prm.declare_entry("Field time samples",
                      "0",
                      Integer(),
                      "Samples per period of the fields (CSV rows, snapshots, "
                      "plots, and the space-time mesh); 0 = 2 (2 M + 1); else "
                      "4 to 100000.");
    prm.declare_entry("VTK",
                      "false",
                      Bool(),
                      "ParaView files of the fields: space-time .vtu, .pvd of "
                      "1D snapshots, fields.pvd.");
    prm.declare_entry("Plots",
                      "false",
                      Bool(),
                      "PNG plots: backbone.png, and per field a space-time "
                      "colour map and the contact end over one period.");
    prm.leave_subsection();
  }

  namespace
  {
    /// A value of [min, max]: an integer (long) or a real number (double).
    template <typename Number>
    Number get_in(dealii::ParameterHandler &prm,
                  const std::string        &section,
                  const std::string        &name,
                  const Number              min,
                  const Number              max)
    {
      constexpr bool integer = std::is_integral_v<Number>;
      const Number value = integer ? Number(prm.get_integer(name)) : Number(prm.get_double(name));
      const auto   text  = [](const Number v) {
        if constexpr (std::is_integral_v<Number>)
          return std::to_string(v);
        else
          return format_value(v);
      };
      require(value >= min && value <= max,
              section + "/" + name,
              std::string(integer ? "an integer" : "a number") + " in [" + text(min) + ", " +
                text(max) + "]",
              text(value));
      return value;
    }

    long get_integer(dealii::ParameterHandler &prm,
                     const std::string        &section,
                     const std::string        &name,
                     const long                min,
                     const long                max)
    {
      return get_in<long>(prm, section, name, min, max);
    }

    double get_positive(dealii::ParameterHandler &prm,
                        const std::string        &section,
                        const std::string        &name)
    {
      const double value = prm.get_double(name);
      require_positive(value, section + "/" + name);
      return value;
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

    void read(dealii::ParameterHandler &prm, Scene &s)
    {
      prm.enter_subsection("Bar");
      s.bar.length        = get_positive(prm, "Bar", "Length");
      s.bar.young_modulus = get_positive(prm, "Bar", "Young modulus");
      s.bar.density       = get_positive(prm, "Bar", "Density");
      s.bar.cross_section = prm.get("Cross section");
      prm.leave_subsection();

      prm.enter_subsection("Contact");
      s.contact.enabled = prm.get_bool("Enabled");
      s.contact.gap     = get_positive(prm, "Contact", "Gap");
      s.contact.alpha   = get_positive(prm, "Contact", "Alpha");
      s.contact.sign    = prm.get("Force sign") == "physical" ?
                            ForceSign::physical :
                            ForceSign::seed_eq5;
      prm.leave_subsection();

      auto &d = s.discretisation;
      prm.enter_subsection("Discretisation");
      d.degree = get_integer(prm, "Discretisation", "Degree", 1, 20);
      d.cells  = get_integer(prm, "Discretisation", "Cells", 1, 1000000);
      d.quadrature_points =
        get_integer(prm, "Discretisation", "Quadrature points", 0, 64);
      d.roundoff_limit = get_in(prm, "Discretisation", "Round-off limit", 1e-12, 1e-6);
      const std::string refinement = prm.get("Refinement");
      d.refinement = refinement == "none"   ? Refinement::none :
                     refinement == "graded" ? Refinement::graded :
                                              Refinement::adaptive;
      prm.enter_subsection("Graded");
      d.graded_ratio = prm.get_double("Ratio");
      require(d.graded_ratio > 0 && d.graded_ratio <= 1,
              "Discretisation/Graded/Ratio",
              "0 < ratio <= 1",
              format_value(d.graded_ratio));
      d.graded_layers = get_integer(
        prm, "Discretisation/Graded", "Layers", 0, d.cells);
      require_graded_cells_above_roundoff(d);
      prm.leave_subsection();
      prm.enter_subsection("Adaptive");
      d.adaptive_steps =
        get_integer(prm, "Discretisation/Adaptive", "Steps", 0, 50);
      d.adaptive_tolerance =
        get_positive(prm, "Discretisation/Adaptive", "Tolerance");
      d.adaptive_fraction = prm.get_double("Refine fraction");
      require(d.adaptive_fraction > 0 && d.adaptive_fraction <= 1,
              "Discretisation/Adaptive/Refine fraction",
              "0 < fraction <= 1",
              format_value(d.adaptive_fraction));
      d.adaptive_band_max = prm.get_double("Band max omega");
      require(d.adaptive_band_max >= 0,
              "Discretisation/Adaptive/Band max omega",
              ">= 0",
              format_value(d.adaptive_band_max));
      prm.leave_subsection();
      prm.leave_subsection();

      prm.enter_subsection("Receptance");
      s.receptance.method = prm.get("Method") == "direct" ?
                              ReceptanceMethod::direct :
                              ReceptanceMethod::modal;
      s.receptance.modes =
        get_integer(prm, "Receptance", "Modes", 0, 10000000);
      prm.leave_subsection();

      auto &hb = s.harmonic_balance;
      prm.enter_subsection("Harmonic balance");
      hb.harmonics =
        get_integer(prm, "Harmonic balance", "Harmonics", 1, 1000);
      hb.time_samples = prm.get_integer("Time samples");
      require(hb.time_samples == 0 ||
                (hb.time_samples >= 2 * hb.harmonics + 1 &&
                 hb.time_samples <= 1u << 20),
              "Harmonic balance/Time samples",
              "0 or an integer in [2 M + 1, 2^20] = [" +
                std::to_string(2 * hb.harmonics + 1) + ", 1048576]",
              std::to_string(prm.get_integer("Time samples")));
      hb.basis = prm.get("Basis") == "cosine" ? HarmonicBasis::cosine :
                                                HarmonicBasis::full;
      hb.integration = prm.get("Integration") == "exact" ?
                         Integration::exact :
                         Integration::sampled;
      hb.tolerance = get_positive(prm, "Harmonic balance", "Tolerance");
      hb.max_iterations =
        get_integer(prm, "Harmonic balance", "Max iterations", 1, 1000);
      hb.line_search = prm.get("Line search");
      prm.leave_subsection();

      auto &c = s.continuation;
      prm.enter_subsection("Continuation");
      c.method = prm.get("Method") == "sequential" ?
                   ContinuationMethod::sequential :
                   ContinuationMethod::arclength;
      c.mode      = get_integer(prm, "Continuation", "Mode", 1, 100000);
      c.omega_min = prm.get_double("Omega min");
      require(c.omega_min >= 0,
              "Continuation/Omega min",
              ">= 0",
              format_value(c.omega_min));
      c.omega_max = prm.get_double("Omega max");
      require(c.omega_max > c.omega_min,
              "Continuation/Omega max",
              "> Omega min = " + format_value(c.omega_min),
              format_value(c.omega_max));
      c.energy_max   = get_positive(prm, "Continuation", "Energy max");
      c.initial_step = get_positive(prm, "Continuation", "Initial step");
      c.min_step     = get_positive(prm, "Continuation", "Min step");
      require(c.min_step <= c.initial_step,
              "Continuation/Min step",
              "<= Initial step = " + format_value(c.initial_step),
              format_value(c.min_step));
      c.max_step = get_positive(prm, "Continuation", "Max step");
      require(c.max_step >= c.initial_step,
              "Continuation/Max step",
              ">= Initial step = " + format_value(c.initial_step),
              format_value(c.max_step));
      c.max_steps = get_integer(prm, "Continuation", "Max steps", 1, 1000000);
      c.grazing_offset = get_in(prm, "Continuation", "Grazing offset", 1e-12, 1e-2);
      c.tongue_share   = get_in(prm, "Continuation", "Tongue share", 1e-4, 1.0);
      prm.leave_subsection();

      prm.enter_subsection("Output");
      s.output.directory = prm.get("Directory");
      require(!s.output.directory.empty(),
              "Output/Directory",
              "a non-empty path",
              "''");
      s.output.spectrum_modes =
        get_integer(prm, "Output", "Spectrum modes", 0, 100000);
      s.output.receptance_frequencies = parse_frequency_list(
        prm.get("Receptance frequencies"), "Output/Receptance frequencies");
      s.output.backbone = prm.get_bool("Backbone");
      s.output.fields_at =
        parse_frequency_list(prm.get("Fields at"), "Output/Fields at");
      s.output.fields_every =
        get_integer(prm, "Output", "Fields every", 0, 1000000);
      s.output.field_time_samples = prm.get_integer("Field time samples");
      require(s.output.field_time_samples == 0 ||
                (s.output.field_time_samples >= 4 &&
                 s.output.field_time_samples <= 100000),
              "Output/Field time samples",
              "0 or an integer in [4, 100000]",
              std::to_string(prm.get_integer("Field time samples")));
      s.output.vtk   = prm.get_bool("VTK");
      s.output.plots = prm.get_bool("Plots");
      prm.leave_subsection();

      require(!s.output.vtk || s.output.fields(),
              "Output/VTK",
              "false unless fields are requested (Output/Fields at or "
              "Output/Fields every)",
              "true");
      require(!s.output.plots || s.output.fields() || s.output.backbone,
              "Output/Plots",
              "false unless Output/Backbone = true or fields are requested",
              "true");

      require(!s.output.fields() || s.contact.enabled,
              "Output/Fields at",
              "empty (and Fields every = 0) when Contact/Enabled = false",
              "a list");
      require(!s.output.backbone || s.contact.enabled,
              "Output/Backbone",
              "false when Contact/Enabled = false (no contact, no "
              "nonsmooth mode)",
              "true");
    }
  } // namespace

  Scene Scene::from_file(const std::string &path)
  {
    dealii::ParameterHandler prm;
    declare(prm);
    try
      {
        prm.parse_input(path);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError("scene '" + path + "': " + one_line_message(e));
      }
    Scene scene;
    try
      {
        read(prm, scene);
      }
    catch (const InputError &e)
      {
        throw InputError("scene '" + path + "': " + e.what());
      }
    return scene;
  }

  double Scene::Discretisation::smallest_cell() const
  {
    return std::numeric_limits<double>::epsilon() * degree * degree / roundoff_limit;
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
