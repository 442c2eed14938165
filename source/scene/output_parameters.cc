#include <nsm/base/errors.h>
#include <nsm/base/text.h>
#include <nsm/scene/output_parameters.h>
#include <nsm/scene/parameter_limits.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;
  } // namespace

  std::vector<double> parse_frequency_list(const std::string &text,
                                           const std::string &parameter)
  {
    std::vector<double> values;
    for (const std::string &item : list_items(text, parameter))
      {
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
      if (!(w >= 0 && w <= frequency_limit)) // the value formatted only when refused: a list holds up to 1e6
        require(false,
              parameter,
              "frequencies in [0, " + format_value(frequency_limit) + "]",
              format_value(w));
    return values;
  }

  void OutputParameters::declare(ParameterHandler &prm)
  {
    const OutputParameters d;
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      d.directory,
                      Patterns::Anything(),
                      "Output directory: a new one, or one that an earlier run wrote. A run "
                      "writes into a hidden sibling and swaps it in at the end, so the "
                      "directory holds the previous complete output or the new one. Empty: "
                      "output/NAME, NAME the scene file's name without its extension.");
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
    prm.declare_entry("Harmonics table",
                      text(d.harmonics_table),
                      Patterns::Bool(),
                      "Write harmonics.csv: every backbone point's harmonic coefficients of the "
                      "contact force and the contact-end displacement; needs Backbone = true.");
    prm.declare_entry("Error estimate",
                      text(d.error_estimate),
                      Patterns::Bool(),
                      "Add backbone.csv's energy_error_estimate: each point's |E(M / 2) / E(M) - 1|, "
                      "E(M / 2) solved with half the harmonics at its Omega; the summary gives its median "
                      "over the main points and the band check (the mesh against its cells halved). "
                      "Both cost about half the harmonic balance's time on the seed scene. On a branch that "
                      "crosses the accumulation point, the estimates also label the climb's truncated top a "
                      "tongue of it.");
    prm.declare_entry("Bar amplitude",
                      text(d.bar_amplitude),
                      Patterns::Bool(),
                      "Add backbone.csv's max_displacement: the largest |u(x, t)| over the bar's "
                      "DoFs at Field time samples per period, from each point's field (costs a "
                      "field per point); needs Backbone = true.");
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
    prm.declare_entry("VTK time",
                      d.vtk_time_over_period ? "t/T" : "t",
                      Patterns::Selection("t|t/T"),
                      "The VTK files' time axis: t (the space-time mesh spans one period T, the "
                      "snapshots' TIME is t), or t/T (it spans 1, as the plots' axis).");
    prm.declare_entry("Plots",
                      text(d.plots),
                      Patterns::Bool(),
                      "PNG plots: backbone.png, and per field a space-time colour map and the "
                      "contact end over one period.");
    prm.declare_entry("Progress every",
                      text(d.progress_every),
                      Patterns::Double(0, 1e6),
                      "Seconds between progress lines on stderr during long stages "
                      "(continuation, adaptive refinement, fields, verification, forced curves); 0 = never.");
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
                      "flagged verified = false, drawn as an open circle in backbone.png and counted in the "
                      "summary.");
    prm.declare_entry("Refine in time",
                      text(d.refine_in_time),
                      Patterns::Bool(),
                      "Find the periodic orbit of the FE model in time (exact flow, shooting) "
                      "from every Refine every-th main backbone point and the Fields at points; "
                      "write its energy, HB's energy error against it, its Floquet multipliers "
                      "and how isolated it is (backbone.csv); needs Backbone = true.");
    prm.declare_entry("Refine every",
                      text(d.refine_every),
                      Patterns::Integer(1, 1000000),
                      "Refine every n-th main point of the backbone.");
    prm.declare_entry("Stability margin",
                      text(d.stability_margin),
                      Patterns::Double(0, 1),
                      "A refined orbit is stable when every |Floquet multiplier| <= 1 + this.");
    prm.leave_subsection();
  }

  void OutputParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Directory");
    require(!has_control_character(directory), "Output/Directory", "a path without control characters",
            "'" + printable(directory) + "'");
    spectrum_modes = get_unsigned(prm, "Spectrum modes");
    receptance_frequencies =
      parse_frequency_list(prm.get("Receptance frequencies"), "Output/Receptance frequencies");
    backbone     = prm.get_bool("Backbone");
    harmonics_table = prm.get_bool("Harmonics table");
    bar_amplitude   = prm.get_bool("Bar amplitude");
    error_estimate  = prm.get_bool("Error estimate");
    fields_at    = parse_frequency_list(prm.get("Fields at"), "Output/Fields at");
    fields_every = get_unsigned(prm, "Fields every");
    field_time_samples = get_unsigned(prm, "Field time samples");
    require(field_time_samples == 0 || field_time_samples >= 4,
            "Output/Field time samples",
            "0 or an integer in [4, 100000]",
            std::to_string(field_time_samples));
    vtk            = prm.get_bool("VTK");
    vtk_time_over_period = prm.get("VTK time") == "t/T";
    plots          = prm.get_bool("Plots");
    progress_every = prm.get_double("Progress every");
    verify_in_time   = prm.get_bool("Verify in time");
    verify_every     = get_unsigned(prm, "Verify every");
    verify_periods   = get_unsigned(prm, "Verify periods");
    verify_steps     = get_unsigned(prm, "Verify steps");
    verify_tolerance = prm.get_double("Verify tolerance");
    refine_in_time   = prm.get_bool("Refine in time");
    refine_every     = get_unsigned(prm, "Refine every");
    stability_margin = prm.get_double("Stability margin");
    prm.leave_subsection();
  }
} // namespace nsm
