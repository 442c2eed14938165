#include <nsm/scene/scene_entries.h>
#include <nsm/scene/scene_file.h>
#include <nsm/study/study_combinations.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <set>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// Calls `action` with `prm` inside subsection "A/B".
    template <typename Action>
    auto in_subsection(dealii::ParameterHandler &prm, const std::string &subsection, const Action &action)
    {
      std::stringstream parts(subsection);
      unsigned int      depth = 0;
      for (std::string part; std::getline(parts, part, '/'); ++depth)
        prm.enter_subsection(part);
      const auto result = action();
      for (; depth > 0; --depth)
        prm.leave_subsection();
      return result;
    }

    void set_entry(dealii::ParameterHandler &prm, const std::string &subsection, const std::string &name,
                   const std::string &value)
    {
      in_subsection(prm, subsection, [&] {
        prm.set(name, value);
        return 0;
      });
    }

    /// A row's outputs are the study's measures: the receptance band and
    /// the backbone follow from them, and no file output is asked for.
    void set_row_outputs(dealii::ParameterHandler &prm, const StudyParameters &study)
    {
      set_entry(prm, "Output", "Receptance frequencies", study.receptance_frequencies);
      set_entry(prm, "Output", "Backbone", study.backbone_omega_values.empty() ? "false" : "true");
      set_entry(prm, "Output", "Spectrum modes", "0");
      set_entry(prm, "Output", "Fields at", "");
      set_entry(prm, "Output", "Fields every", "0");
      set_entry(prm, "Output", "VTK", "false");
      set_entry(prm, "Output", "Plots", "false");
      set_entry(prm, "Output", "Verify in time", "false");
    }

    /// With Study/Forcing scaled with damping: the scene's amplitudes times
    /// the row's modal ratio (as `prm` holds it) over the scene's.
    void scale_forcing(dealii::ParameterHandler &prm, const StudyScene &base)
    {
      if (!base.study.forcing_scaled)
        return;
      const double ratio = in_subsection(prm, "Damping", [&] { return prm.get_double("Modal ratio"); }) /
                           base.scene.damping.modal_ratio;
      std::string amplitudes;
      for (const double f : base.scene.forcing.amplitudes)
        amplitudes += (amplitudes.empty() ? "" : ", ") + scene_entries::format_value(f * ratio);
      set_entry(prm, "Forcing", "Amplitudes", amplitudes);
    }

    dealii::ParameterHandler &read(dealii::ParameterHandler &prm, const std::string &path)
    {
      StudyScene::declare(prm);
      read_scene_file(path, prm);
      return prm;
    }

    /// The combination's values, those its run does not use as unused_value
    /// (Sweep::used_if_column: Time samples under exact integration, the
    /// graded and adaptive parameters under another refinement).
    std::vector<std::string> used_values(const std::vector<StudyParameters::Sweep> &sweeps,
                                         std::vector<std::string>                    key)
    {
      const std::vector<std::string> as_set = key;
      for (std::size_t i = 0; i < sweeps.size(); ++i)
        if (!sweeps[i].used_if_column.empty())
          {
            const auto condition = std::find_if(sweeps.begin(), sweeps.end(), [&](const auto &w) {
              return w.column == sweeps[i].used_if_column;
            });
            if (as_set[condition - sweeps.begin()] != sweeps[i].used_if_value)
              key[i] = unused_value;
          }
      return key;
    }

    /// Study/Spectrum modes within what the rows' meshes have: a row with
    /// fewer measures them all and says how many (spectrum_modes_measured);
    /// a request no row can meet is refused. Adaptive meshes are known once
    /// made.
    void check_spectrum_modes(const std::vector<StudyCombination> &combinations, const unsigned int requested)
    {
      unsigned int most = 0;
      for (const StudyCombination &c : combinations)
        {
          const DiscretisationParameters &d = c.scene.scene.discretisation;
          if (d.refinement == Refinement::adaptive)
            return;
          most = std::max(most, d.cells * d.degree);
        }
      if (requested > most)
        throw InputError("parameter 'Study/Spectrum modes' = " + std::to_string(requested) +
                         " is out of range: allowed an integer in [0, " + std::to_string(most) +
                         "], the most clamped-free modes (Cells x Degree) of a row's mesh");
    }
  } // namespace

  std::string study_fingerprint(const std::string &path, const StudyScene &base)
  {
    dealii::ParameterHandler prm;
    read(prm, path);
    for (const StudyParameters::Sweep &s : base.study.sweeps)
      set_entry(prm, "Study", s.study_entry, "");
    set_entry(prm, "Study", "Repeats", "1");
    set_entry(prm, "Output", "Directory", "-");
    set_entry(prm, "Output", "Progress every", "0");
    set_entry(prm, "Output", "Plots", "false");
    std::ostringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    return text.str();
  }

  std::vector<StudyCombination> study_combinations(const std::string &path, const StudyScene &base)
  {
    dealii::ParameterHandler prm;
    read(prm, path);
    set_row_outputs(prm, base.study);
    std::vector<std::vector<std::string>> values;
    for (const StudyParameters::Sweep &s : base.study.sweeps)
      values.push_back(s.values.empty() ?
                         std::vector<std::string>{in_subsection(prm, s.subsection, [&] { return prm.get(s.name); })} :
                         s.values);
    std::vector<StudyCombination>      combinations;
    std::set<std::vector<std::string>> used;
    std::vector<std::size_t>           digit(values.size(), 0);
    for (bool more = true; more;)
      {
        StudyCombination c;
        for (std::size_t i = 0; i < values.size(); ++i)
          {
            set_entry(prm, base.study.sweeps[i].subsection, base.study.sweeps[i].name, values[i][digit[i]]);
            c.key.push_back(values[i][digit[i]]);
          }
        // A combination that differs from an earlier one only in values its
        // run does not use would repeat that run: it is left out.
        c.key = used_values(base.study.sweeps, std::move(c.key));
        if (used.insert(c.key).second)
          {
            scale_forcing(prm, base);
            c.scene = StudyScene::from_parameters(prm, path + ", study row " + std::to_string(combinations.size() + 1));
            combinations.push_back(std::move(c));
          }
        // The last sweep varies fastest.
        more = false;
        for (std::size_t i = values.size(); i-- > 0 && !more;)
          if (++digit[i] < values[i].size())
            more = true;
          else
            digit[i] = 0;
      }
    check_spectrum_modes(combinations, base.study.spectrum_modes);
    return combinations;
  }

  std::vector<StudyScene> reference_levels(const std::string &path, const StudyScene &base)
  {
    dealii::ParameterHandler prm;
    read(prm, path);
    set_row_outputs(prm, base.study);
    if (!base.study.reference_degree.empty())
      set_entry(prm, "Discretisation", "Degree", base.study.reference_degree);
    set_entry(prm, "Discretisation", "Refinement", "none");
    std::vector<StudyScene> levels;
    for (const std::string &cells : base.study.reference_cells)
      {
        set_entry(prm, "Discretisation", "Cells", cells);
        levels.push_back(StudyScene::from_parameters(prm, path + ", reference with " + cells + " cells"));
      }
    return levels;
  }
} // namespace nsm
