#include <nsm/scene/scene.h>
#include <nsm/scene/scene_entries.h>
#include <nsm/scene/scene_file.h>
#include <nsm/base/errors.h>
#include <nsm/base/text.h>
#include <nsm/study/study_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <utility>

namespace nsm
{
  namespace
  {
    /// The parameters a study can sweep: scene subsection, scene name,
    /// the Study entry that lists its values, its study.csv column, and the
    /// column and value under which a run uses it (none: always).
    struct Sweepable
    {
      const char *subsection, *name, *study_entry, *column;
      const char *used_if_column = "", *used_if_value = "";
    };

    const Sweepable sweepable[] = {
      {"Discretisation", "Degree", "Degrees", "degree"},
      {"Discretisation", "Cells", "Cells", "cells"},
      {"Discretisation", "Refinement", "Refinements", "refinement"},
      {"Discretisation/Graded", "Layers", "Graded layers", "graded_layers", "refinement", "graded"},
      {"Discretisation/Graded", "Ratio", "Graded ratios", "graded_ratio", "refinement", "graded"},
      {"Discretisation/Adaptive", "Tolerance", "Adaptive tolerances", "adaptive_tolerance", "refinement",
       "adaptive"},
      {"Receptance", "Method", "Receptance methods", "receptance_method"},
      {"Harmonic balance", "Harmonics", "Harmonics", "harmonics"},
      {"Harmonic balance", "Integration", "Integrations", "integration"},
      {"Harmonic balance", "Time samples", "Time samples", "time_samples", "integration", "sampled"},
      {"Damping", "Modal ratio", "Damping ratios", "modal_ratio"}};


    /// The comma-separated values of Study/`entry`, trimmed. An empty value
    /// (a stray comma) or one listed twice is most likely a typo, and would
    /// only repeat a row: an input error.
    std::vector<std::string> split_list(const std::string &text, const std::string &entry)
    {
      std::vector<std::string> items;
      if (text.find_first_not_of(" \t") == std::string::npos)
        return items;
      const auto refuse = [&](const std::string &why) {
        throw InputError("parameter 'Study/" + entry + "' = '" + text + "' is not allowed: " + why +
                         "; allowed: distinct comma-separated values");
      };
      std::stringstream in(text + ",");
      for (std::string item; std::getline(in, item, ',');)
        {
          const auto first = item.find_first_not_of(" \t");
          if (first == std::string::npos)
            refuse("an empty value");
          item = item.substr(first, item.find_last_not_of(" \t") - first + 1);
          for (const std::string &earlier : items)
            if (same_study_value(earlier, item))
              refuse("'" + item + "' is listed twice" + (earlier == item ? "" : " (as '" + earlier + "')"));
          items.push_back(item);
        }
      return items;
    }
  } // namespace

  bool StudyParameters::enabled() const
  {
    return spectrum_modes > 0 || !receptance_frequency_values.empty() || !backbone_omega_values.empty();
  }

  void StudyParameters::check_reference_cells() const
  {
    const std::string allowed = "two or more cell counts, increasing, with Study/Backbone omegas set";
    if (reference_cells.empty())
      return;
    bool increasing = reference_cells.size() >= 2 && !backbone_omega_values.empty();
    for (std::size_t i = 1; i < reference_cells.size(); ++i)
      increasing &= std::stoul(reference_cells[i - 1]) < std::stoul(reference_cells[i]);
    if (!increasing)
      {
        std::string value;
        for (const std::string &c : reference_cells)
          value += (value.empty() ? "" : ", ") + c;
        throw InputError("parameter 'Study/Reference cells' = " + value + " is not allowed; allowed: " + allowed);
      }
  }

  void StudyParameters::declare(dealii::ParameterHandler &prm)
  {
    namespace Patterns = dealii::Patterns;
    prm.enter_subsection("Study");
    for (const Sweepable &s : sweepable)
      prm.declare_entry(s.study_entry,
                        "",
                        Patterns::Anything(),
                        std::string("Values of ") + s.subsection + "/" + s.name +
                          " to sweep, comma-separated (each within that parameter's range); "
                          "empty: the scene's own value. A study runs every combination.");
    prm.declare_entry("Spectrum modes",
                      "0",
                      Patterns::Integer(0, 10000),
                      "Measure the error of the first n clamped-free eigenfrequencies; 0 = not "
                      "measured. A scene that measures anything is a study: it writes study.csv.");
    prm.declare_entry("Receptance frequencies",
                      "",
                      Patterns::Anything(),
                      "Measure the error of gamma at these frequencies (list or a:b:n ranges).");
    prm.declare_entry("Backbone omegas",
                      "",
                      Patterns::Anything(),
                      "Measure the main-branch energy at these Omega (numbers and ranges a:b:n within [Omega min, Omega max]): "
                      "Newton at exactly Omega from two main points of one segment that bracket it; its error "
                      "where the exact mode is known (uniform bar, mode 1, physical sign), else against the "
                      "fine reference (Reference cells).");
    prm.declare_entry("Reference degree",
                      "",
                      Patterns::Anything(),
                      "Degree of the fine backbone reference (empty: the scene's Discretisation/Degree).");
    prm.declare_entry("Reference cells",
                      "",
                      Patterns::Anything(),
                      "Cells of the fine backbone reference's uniform meshes, two or more, coarse to "
                      "fine: the finest is the reference that rows without an exact one are compared "
                      "with, the others show its convergence (reference.csv, computed once and kept "
                      "in the output directory). Empty: no fine reference. Needs Backbone omegas.");
    prm.declare_entry("Verify in time",
                      "false",
                      Patterns::Bool(),
                      "Integrate each main-branch point found at the Backbone omegas in time on the "
                      "row's FE model with the physical wall (Output/Verify steps and Verify periods): "
                      "study.csv gives the median and largest one-period defect max |u(T) - u(0)| / g0, "
                      "a measure against a true periodic motion for bars whose mode is not known. "
                      "Needs Backbone omegas.");
    prm.declare_entry("Forced peaks",
                      "false",
                      Patterns::Bool(),
                      "Trace each row's forced-response curves (Forcing/Amplitudes; timed as the forced "
                      "response stage) and write the peaks' largest distance from the row's main branch and "
                      "their phase lags to study.csv: with Damping ratios, the backbone check at decreasing "
                      "damping. Needs Backbone omegas and Forcing/Amplitudes.");
    prm.declare_entry("Forcing scaled with damping",
                      "false",
                      Patterns::Bool(),
                      "Scale each row's Forcing/Amplitudes by its Damping/Modal ratio over the scene's, so "
                      "that every row's peaks reach about the same energies. Needs Forced peaks and a "
                      "scene's Modal ratio > 0.");
    prm.declare_entry("Repeats",
                      "1",
                      Patterns::Integer(1, 100),
                      "Runs of each combination; study.csv gives min, median and max of the total time.");
    prm.leave_subsection();
  }

  void StudyParameters::parse(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Study");
    sweeps.clear();
    std::vector<AllowedCheck> checks;
    for (const Sweepable &s : sweepable)
      {
        Sweep sweep{s.subsection,
                    s.name,
                    s.study_entry,
                    s.column,
                    split_list(prm.get(s.study_entry), s.study_entry),
                    s.used_if_column,
                    s.used_if_value};
        for (const std::string &value : sweep.values)
          checks.push_back({sweep.subsection + "/" + sweep.name, value, std::string("Study/") + s.study_entry});
        sweeps.push_back(std::move(sweep));
      }
    spectrum_modes         = static_cast<unsigned int>(prm.get_integer("Spectrum modes"));
    receptance_frequencies = prm.get("Receptance frequencies");
    receptance_frequency_values =
      parse_frequency_list(receptance_frequencies, "Study/Receptance frequencies");
    backbone_omegas       = prm.get("Backbone omegas");
    backbone_omega_values = parse_frequency_list(backbone_omegas, "Study/Backbone omegas");
    // Two values are one column (energy_at_W, 12 digits) if they print alike.
    const auto column = [](const double w) {
      std::ostringstream s;
      s.precision(12);
      s << w;
      return s.str();
    };
    for (std::size_t i = 0; i < backbone_omega_values.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (column(backbone_omega_values[i]) == column(backbone_omega_values[j]))
          throw InputError("parameter 'Study/Backbone omegas' = '" + backbone_omegas + "' is not allowed: " +
                           scene_entries::format_value(backbone_omega_values[i]) +
                           " is listed twice; allowed: distinct frequencies");
    repeats               = static_cast<unsigned int>(prm.get_integer("Repeats"));
    verify_in_time        = prm.get_bool("Verify in time");
    forced_peaks          = prm.get_bool("Forced peaks");
    forcing_scaled        = prm.get_bool("Forcing scaled with damping");
    reference_degree      = prm.get("Reference degree");
    reference_cells       = split_list(prm.get("Reference cells"), "Reference cells");
    if (!reference_degree.empty())
      checks.push_back({"Discretisation/Degree", reference_degree, "Study/Reference degree"});
    for (const std::string &cells : reference_cells)
      checks.push_back({"Discretisation/Cells", cells, "Study/Reference cells"});
    require_allowed(prm, checks);
    prm.leave_subsection();
    check_reference_cells();
    if (verify_in_time && backbone_omega_values.empty())
      throw InputError("parameter 'Study/Verify in time' = true is not allowed; allowed: false "
                       "unless Study/Backbone omegas is set");
    if (forced_peaks && backbone_omega_values.empty())
      throw InputError("parameter 'Study/Forced peaks' = true is not allowed; allowed: false "
                       "unless Study/Backbone omegas is set (the peaks are compared with the row's backbone)");
    if (forcing_scaled && !forced_peaks)
      throw InputError("parameter 'Study/Forcing scaled with damping' = true is not allowed; allowed: false "
                       "unless Study/Forced peaks = true");

    bool sweeps_something = false;
    for (const Sweep &s : sweeps)
      sweeps_something |= !s.values.empty();
    if (sweeps_something && !enabled())
      throw InputError("parameter 'Study/Spectrum modes' = 0 is out of range: a study that sweeps "
                       "parameters measures something (Spectrum modes > 0, Receptance frequencies "
                       "or Backbone omegas)");
  }

  void StudyScene::declare(dealii::ParameterHandler &prm)
  {
    Scene::declare(prm);
    StudyParameters::declare(prm);
  }

  StudyScene StudyScene::from_file(const std::string &path)
  {
    dealii::ParameterHandler prm;
    declare(prm);
    read_scene_file(path, prm);
    StudyScene scene = from_parameters(prm, path);
    prm.enter_subsection("Output");
    prm.set("Directory", scene.scene.output.directory);
    prm.leave_subsection();
    std::ostringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    scene.scene.parameter_file = text.str();
    try
      {
        check_record_reads_back(prm, scene.scene.parameter_file);
      }
    catch (const InputError &e)
      {
        throw InputError("scene '" + printable(path) + "': " + e.what());
      }
    return scene;
  }

  StudyScene StudyScene::from_parameters(dealii::ParameterHandler &prm, const std::string &origin)
  {
    StudyScene result;
    try
      {
        result.study.parse(prm);
      }
    catch (const InputError &e)
      {
        throw InputError("scene '" + origin + "': " + e.what());
      }
    result.scene = Scene::from_parameters(prm, origin, result.study.enabled());
    try
      {
        result.check_consistency();
      }
    catch (const InputError &e)
      {
        throw InputError("scene '" + origin + "': " + e.what());
      }
    return result;
  }

  void StudyScene::check_consistency() const
  {
    using scene_entries::format_value;
    const auto &c = scene.continuation;
    // Rows differ in their meshes, and so in an automatic range: a study's
    // rows share the range the scene states.
    // Every missing entry named at once, not one per run.
    std::string missing;
    if (!study.backbone_omega_values.empty())
      for (const auto &[value, entry] : {std::pair(c.omega_max, "Omega max"), std::pair(c.energy_max, "Energy max")})
        if (!(value > 0))
          missing += std::string(missing.empty() ? "" : " and ") + "'Continuation/" + entry + "' = 0";
    if (!missing.empty())
      throw InputError("parameter " + missing + (missing.find(" and ") != std::string::npos ? " are" : " is") +
                       " out of range: allowed > 0 in a study with Backbone omegas (its rows share one range and one "
                       "energy ceiling; 0, automatic, is for a single run)");
    if (study.forced_peaks)
      scene_entries::require(scene.forcing.enabled(), "Forcing/Amplitudes",
                             "one or more force levels with Study/Forced peaks = true", "''");
    if (study.forcing_scaled)
      scene_entries::require(scene.damping.modal_ratio > 0, "Damping/Modal ratio",
                             "> 0 with Study/Forcing scaled with damping = true (the rows' amplitudes are scaled "
                             "by their ratio over it)",
                             format_value(scene.damping.modal_ratio));
    // An undamped row of a driven scene would be refused by its run, naming
    // the entry the sweep sets (or the amplitude scaled to 0): named here.
    if (scene.forcing.enabled())
      for (const StudyParameters::Sweep &sweep : study.sweeps)
        if (sweep.column == "modal_ratio")
          for (const std::string &value : sweep.values)
            scene_entries::require(scene_entries::parse_double(value, "Study/Damping ratios") > 0,
                                   "Study/Damping ratios",
                                   "numbers > 0 when Forcing/Amplitudes or Omegas is set (an undamped drive has no "
                                   "bounded linear response at resonance)",
                                   value);
    for (const double w : study.backbone_omega_values)
      scene_entries::require(scene.contact.enabled && w >= c.omega_min && w <= c.omega_max,
                             "Study/Backbone omegas",
                             "frequencies in [Omega min, Omega max] = [" + format_value(c.omega_min) + ", " +
                               format_value(c.omega_max) + "], with Contact/Enabled = true",
                             format_value(w));
  }

  bool same_study_value(const std::string &a, const std::string &b)
  {
    const auto number = [](const std::string &text, double &value) {
      char *end = nullptr;
      value     = std::strtod(text.c_str(), &end);
      return !text.empty() && end == text.c_str() + text.size();
    };
    double x, y;
    return a == b || (number(a, x) && number(b, y) && x == y);
  }
} // namespace nsm
