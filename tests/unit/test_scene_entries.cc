// Every entry the scene declares reaches its own member of the Scene struct,
// and no other: each entry is set alone to a value other than its default,
// and the parsed scene is compared member by member with the scene parsed
// without it. The rows below name each entry's member; an entry declared
// without a row fails the test, so a new parameter cannot go unchecked.
#include <nsm/scene/scene.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "scene_helpers.h"

namespace
{
  using nsm::Scene;

  std::string as_text(const double v) { return nsm::scene_entries::format_value(v); }
  std::string as_text(const unsigned int v) { return std::to_string(v); }
  std::string as_text(const bool v) { return v ? "true" : "false"; }
  std::string as_text(const std::string &v) { return v; }
  template <typename Enum, typename = std::enable_if_t<std::is_enum_v<Enum>>>
  std::string as_text(const Enum v)
  {
    return "enum " + std::to_string(static_cast<int>(v));
  }
  std::string as_text(const std::vector<double> &v)
  {
    std::string s;
    for (const double x : v)
      s += as_text(x) + ";";
    return s;
  }

  /// One declared entry: its path, a value other than its default, other
  /// entries the value needs ("Path=value", set in the scene it is compared
  /// with too), and the member it sets, as text.
  struct Entry
  {
    std::string                              path;
    std::string                              value;
    std::vector<std::string>                  needs; ///< "Path=value"
    std::function<std::string(const Scene &)> member;
  };

#define NSM_MEMBER(m) [](const Scene &s) { return as_text(s.m); }

  const std::vector<Entry> &entries()
  {
    static const std::vector<Entry> rows = {
      {"Bar/Length", "2", {}, NSM_MEMBER(bar.length)},
      {"Bar/Young modulus", "3", {}, NSM_MEMBER(bar.young_modulus)},
      {"Bar/Density", "5", {}, NSM_MEMBER(bar.density)},
      {"Bar/Cross section", "1 + x", {}, NSM_MEMBER(bar.cross_section)},
      {"Contact/Enabled", "false", {}, NSM_MEMBER(contact.enabled)},
      {"Contact/Gap", "0.002", {}, NSM_MEMBER(contact.gap)},
      {"Contact/Alpha", "7", {}, NSM_MEMBER(contact.alpha)},
      {"Contact/Force sign", "seed-eq5", {}, NSM_MEMBER(contact.sign)},
      {"Contact/Wall", "compliant", {}, NSM_MEMBER(contact.wall)},
      {"Contact/Wall stiffness", "11", {}, NSM_MEMBER(contact.stiffness)},
      {"Discretisation/Degree", "2", {}, NSM_MEMBER(discretisation.degree)},
      {"Discretisation/Cells", "300", {}, NSM_MEMBER(discretisation.cells)},
      {"Discretisation/Quadrature points", "5", {}, NSM_MEMBER(discretisation.quadrature_points)},
      {"Discretisation/Round-off limit", "1e-8", {}, NSM_MEMBER(discretisation.roundoff_limit)},
      {"Discretisation/Refinement", "graded", {"Discretisation/Graded/Layers=4"},
       NSM_MEMBER(discretisation.refinement)},
      {"Discretisation/Contact mass", "redistributed", {}, NSM_MEMBER(discretisation.contact_mass)},
      {"Discretisation/Graded/Ratio", "0.5", {"Discretisation/Refinement=graded", "Discretisation/Graded/Layers=4"},
       NSM_MEMBER(discretisation.graded_ratio)},
      {"Discretisation/Graded/Layers", "6", {"Discretisation/Refinement=graded", "Discretisation/Graded/Layers=4"},
       NSM_MEMBER(discretisation.graded_layers)},
      {"Discretisation/Adaptive/Steps", "3", {}, NSM_MEMBER(discretisation.adaptive_steps)},
      {"Discretisation/Adaptive/Tolerance", "1e-6", {}, NSM_MEMBER(discretisation.adaptive_tolerance)},
      {"Discretisation/Adaptive/Refine fraction", "0.5", {}, NSM_MEMBER(discretisation.adaptive_fraction)},
      {"Discretisation/Adaptive/Band max omega", "9", {}, NSM_MEMBER(discretisation.adaptive_band_max)},
      {"Receptance/Method", "direct", {}, NSM_MEMBER(receptance.method)},
      {"Receptance/Modes", "50", {}, NSM_MEMBER(receptance.modes)},
      {"Harmonic balance/Harmonics", "12", {}, NSM_MEMBER(harmonic_balance.harmonics)},
      {"Harmonic balance/Time samples", "1024", {}, NSM_MEMBER(harmonic_balance.time_samples)},
      {"Harmonic balance/Basis", "full", {}, NSM_MEMBER(harmonic_balance.basis)},
      {"Harmonic balance/Integration", "sampled", {}, NSM_MEMBER(harmonic_balance.integration)},
      {"Harmonic balance/Tolerance", "1e-9", {}, NSM_MEMBER(harmonic_balance.tolerance)},
      {"Harmonic balance/Max iterations", "30", {}, NSM_MEMBER(harmonic_balance.max_iterations)},
      {"Harmonic balance/Line search", "Backtrack", {}, NSM_MEMBER(harmonic_balance.line_search)},
      {"Continuation/Method", "arclength", {}, NSM_MEMBER(continuation.method)},
      {"Continuation/Mode", "2", {}, NSM_MEMBER(continuation.mode)},
      {"Continuation/Omega min", "1.5", {"Continuation/Omega max=2.5"}, NSM_MEMBER(continuation.omega_min)},
      {"Continuation/Omega max", "2.5", {}, NSM_MEMBER(continuation.omega_max)},
      {"Continuation/Energy max", "0.5", {}, NSM_MEMBER(continuation.energy_max)},
      {"Continuation/Energy max over grazing", "20", {}, NSM_MEMBER(continuation.energy_max_over_grazing)},
      {"Continuation/Initial step", "0.002", {}, NSM_MEMBER(continuation.initial_step)},
      {"Continuation/Min step", "1e-5", {}, NSM_MEMBER(continuation.min_step)},
      {"Continuation/Max step", "0.03", {}, NSM_MEMBER(continuation.max_step)},
      {"Continuation/Max steps", "99", {}, NSM_MEMBER(continuation.max_steps)},
      {"Continuation/Grazing offset", "1e-4", {}, NSM_MEMBER(continuation.grazing_offset)},
      {"Continuation/Tongue share", "0.05", {}, NSM_MEMBER(continuation.tongue_share)},
      {"Continuation/Main contact drop", "0.2", {}, NSM_MEMBER(continuation.main_contact_drop)},
      {"Continuation/Tongue energy ratio", "3", {}, NSM_MEMBER(continuation.tongue_energy_ratio)},
      {"Continuation/Max contact change", "0.02", {}, NSM_MEMBER(continuation.max_contact_change)},
      {"Continuation/Max solution change", "0.3", {}, NSM_MEMBER(continuation.max_solution_change)},
      {"Continuation/Leap energy ratio", "6", {}, NSM_MEMBER(continuation.leap_energy_ratio)},
      {"Continuation/Search reach", "0.1", {}, NSM_MEMBER(continuation.search_reach)},
      {"Continuation/Leap from fewer harmonics", "false", {}, NSM_MEMBER(continuation.leap_from_fewer_harmonics)},
      {"Continuation/Fill gaps wider than", "0.05", {}, NSM_MEMBER(continuation.fill_gaps_wider_than)},
      {"Resources/Memory limit", "4000", {}, NSM_MEMBER(resources.memory_limit)},
      {"Damping/Modal ratio", "0.01", {}, NSM_MEMBER(damping.modal_ratio)},
      {"Damping/Rayleigh alpha", "0.1", {}, NSM_MEMBER(damping.rayleigh_alpha)},
      {"Damping/Rayleigh beta", "0.001", {}, NSM_MEMBER(damping.rayleigh_beta)},
      {"Forcing/Amplitudes", "1e-5, 2e-5", {"Damping/Modal ratio=0.01"}, NSM_MEMBER(forcing.amplitudes)},
      {"Forcing/Verify every", "5", {}, NSM_MEMBER(forcing.verify_every)},
      {"Forcing/Verify periods", "7", {}, NSM_MEMBER(forcing.verify_periods)},
      {"Forcing/Omegas", "1.9, 2", {"Damping/Modal ratio=0.01", "Forcing/Amplitude max=1e-5"}, NSM_MEMBER(forcing.omegas)},
      {"Forcing/Amplitude max", "3e-5", {}, NSM_MEMBER(forcing.amplitude_max)},
      {"Forcing/Shape", "uniform", {}, NSM_MEMBER(forcing.shape)},
      {"Forcing/Floquet", "true", {"Contact/Wall=compliant", "Forcing/Verify every=5", "Damping/Modal ratio=0.01", "Forcing/Amplitudes=1e-5"}, NSM_MEMBER(forcing.floquet)},
      {"Output/Directory", "elsewhere", {}, NSM_MEMBER(output.directory)},
      {"Output/Spectrum modes", "4", {}, NSM_MEMBER(output.spectrum_modes)},
      {"Output/Receptance frequencies", "0.5, 1", {}, NSM_MEMBER(output.receptance_frequencies)},
      {"Output/Backbone", "true", {}, NSM_MEMBER(output.backbone)},
      {"Output/Harmonics table", "true", {"Output/Backbone=true"}, NSM_MEMBER(output.harmonics_table)},
      {"Output/Bar amplitude", "true", {"Output/Backbone=true"}, NSM_MEMBER(output.bar_amplitude)},
      {"Output/Error estimate", "false", {"Output/Backbone=true"}, NSM_MEMBER(output.error_estimate)},
      {"Output/Fields at", "2", {"Continuation/Omega max=2.5"}, NSM_MEMBER(output.fields_at)},
      {"Output/Fields every", "3", {}, NSM_MEMBER(output.fields_every)},
      {"Output/Field time samples", "64", {"Output/Fields every=3"}, NSM_MEMBER(output.field_time_samples)},
      {"Output/VTK", "true", {"Output/Fields every=3"}, NSM_MEMBER(output.vtk)},
      {"Output/VTK time", "t/T", {"Output/Fields every=3", "Output/VTK=true"},
       NSM_MEMBER(output.vtk_time_over_period)},
      {"Output/Plots", "true", {"Output/Backbone=true"}, NSM_MEMBER(output.plots)},
      {"Output/Progress every", "2", {}, NSM_MEMBER(output.progress_every)},
      {"Output/Verify in time", "true", {"Output/Backbone=true"}, NSM_MEMBER(output.verify_in_time)},
      {"Output/Verify every", "4", {"Output/Backbone=true", "Output/Verify in time=true"},
       NSM_MEMBER(output.verify_every)},
      {"Output/Verify periods", "2", {"Output/Backbone=true", "Output/Verify in time=true"},
       NSM_MEMBER(output.verify_periods)},
      {"Output/Verify steps", "800", {"Output/Backbone=true", "Output/Verify in time=true"},
       NSM_MEMBER(output.verify_steps)},
      {"Output/Verify tolerance", "0.05", {"Output/Backbone=true", "Output/Verify in time=true"},
       NSM_MEMBER(output.verify_tolerance)},
      {"Output/Refine in time", "true", {"Output/Backbone=true"}, NSM_MEMBER(output.refine_in_time)},
      {"Output/Refine every", "5", {"Output/Backbone=true", "Output/Refine in time=true"},
       NSM_MEMBER(output.refine_every)},
      {"Output/Stability margin", "0.001", {"Output/Backbone=true", "Output/Refine in time=true"},
       NSM_MEMBER(output.stability_margin)},
    };
    return rows;
  }
#undef NSM_MEMBER

  /// The entries Scene::declare declares, as paths "Subsection/.../Entry".
  std::set<std::string> declared_paths()
  {
    dealii::ParameterHandler prm;
    Scene::declare(prm);
    std::ostringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    std::set<std::string>    paths;
    std::vector<std::string> sections;
    std::istringstream       lines(text.str());
    for (std::string line; std::getline(lines, line);)
      {
        line = nsm::scene_entries::trim(line);
        if (line.rfind("subsection ", 0) == 0)
          sections.push_back(line.substr(11));
        else if (line == "end")
          sections.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            std::string path;
            for (const std::string &s : sections)
              path += s + "/";
            paths.insert(path + nsm::scene_entries::trim(line.substr(4, line.find('=') - 4)));
          }
      }
    return paths;
  }

  /// A scene file that sets the given entries ("Path=value"), each inside
  /// its subsections.
  std::string scene_setting(const std::vector<std::string> &settings)
  {
    std::string body;
    for (const std::string &setting : settings)
      {
        const std::size_t equals = setting.find('=');
        std::string       rest = setting.substr(0, equals), closing;
        for (std::size_t slash; (slash = rest.find('/')) != std::string::npos; rest = rest.substr(slash + 1))
          {
            body += "subsection " + rest.substr(0, slash) + "\n";
            closing += "end\n";
          }
        body += "set " + rest + " = " + setting.substr(equals + 1) + "\n" + closing;
      }
    return body;
  }

  /// The scene of the given settings, always from the same file name, so
  /// that the output directory derived from it is the same.
  Scene parsed(const std::vector<std::string> &settings)
  {
    return Scene::from_file(testing_helpers::write_scene("entries", scene_setting(settings)));
  }
} // namespace

TEST(SceneEntries, EveryDeclaredEntryHasARowAndEveryRowAnEntry)
{
  std::set<std::string> rows;
  for (const Entry &e : entries())
    EXPECT_TRUE(rows.insert(e.path).second) << e.path << " has two rows";
  const std::set<std::string> declared = declared_paths();
  for (const std::string &path : declared)
    EXPECT_EQ(rows.count(path), 1u) << path << " is declared, and this test has no row for it";
  for (const std::string &path : rows)
    EXPECT_EQ(declared.count(path), 1u) << path << " has a row, and is not declared";
}

// The struct's defaults and the declared ones are the same (the directory is
// derived from the scene's name when left empty).
TEST(SceneEntries, AnEmptyFileGivesTheStructsDefaults)
{
  const Scene from_file = parsed({}), defaults;
  for (const Entry &e : entries())
    {
      if (e.path != "Output/Directory")
        {
          EXPECT_EQ(e.member(from_file), e.member(defaults)) << e.path;
        }
    }
}

// Each entry changes its own member and no other: a parse that reads one
// entry into another's member, or ignores it, fails here.
TEST(SceneEntries, EachEntrySetsItsOwnMemberAndNoOther)
{
  for (const Entry &e : entries())
    {
      SCOPED_TRACE(e.path + " = " + e.value);
      const Scene without  = parsed(e.needs);
      auto        settings = e.needs;
      settings.push_back(e.path + "=" + e.value);
      const Scene with = parsed(settings);
      EXPECT_NE(e.member(with), e.member(without)) << "the entry did not reach its member";
      for (const Entry &other : entries())
        {
          if (&other != &e)
            {
              EXPECT_EQ(other.member(with), other.member(without)) << "it changed " << other.path << "'s member";
            }
        }
    }
}
