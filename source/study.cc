#include <nsm/output.h>
#include <nsm/progress.h>
#include <nsm/scene_file.h>
#include <nsm/study.h>
#include <nsm/study_reference.h>
#include <nsm/study_row.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace nsm
{
  namespace
  {
    namespace fs = std::filesystem;

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

    dealii::ParameterHandler &read(dealii::ParameterHandler &prm, const std::string &path)
    {
      Scene::declare(prm);
      read_scene_file(path, prm);
      return prm;
    }

    /// The base scene as text, without what a rerun may change: the swept
    /// lists, the repeats, where the output goes and how it is shown.
    std::string fingerprint(const std::string &path, const Scene &base)
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

    std::string file_text(const std::string &path)
    {
      std::ifstream      in(path);
      std::ostringstream text;
      text << in.rdbuf();
      return text.str();
    }

    /// Checks that Output/Directory is new, empty, or holds this base
    /// scene's study; returns the rows it already holds, by key.
    std::map<std::vector<std::string>, std::vector<CsvCell>>
    earlier_rows(const std::string &directory, const std::string &scene_text,
                 const std::vector<std::string> &columns, const std::size_t key_size)
    {
      std::map<std::vector<std::string>, std::vector<CsvCell>> rows;
      const std::string recorded = directory + "/study.scene";
      std::error_code   error;
      if (!fs::exists(directory, error) || fs::is_empty(directory, error))
        return rows;
      if (!fs::is_regular_file(recorded) || file_text(recorded) != scene_text)
        throw InputError("parameter 'Output/Directory' = " + directory +
                         " is not allowed: it holds files but not a study of this scene "
                         "(study.scene differs); allowed: a new or empty directory, or this study's");
      const CsvTable table = read_csv(directory + "/study.csv");
      if (!table.columns.empty() && table.columns != columns)
        throw InputError("parameter 'Output/Directory' = " + directory +
                         ": its study.csv has other columns; allowed: a new or empty directory");
      for (const auto &row : table.rows)
        {
          std::vector<std::string> key;
          for (std::size_t c = 0; c < key_size; ++c)
            key.push_back(std::get<std::string>(row[c]));
          rows[key] = row;
        }
      return rows;
    }

    /// One round's rows travel to rank 0 as text: index, then the cells,
    /// split again by split_fields.
    std::string pack_row(const std::size_t index, const std::vector<std::string> &cells)
    {
      std::string packed = std::to_string(index);
      for (const std::string &c : cells)
        packed += '\x1f' + c;
      return packed;
    }

    /// The run summary's answer to "what does accuracy cost": per measured
    /// error, the rows that no other row beats in both error and median
    /// time (the Pareto front), fastest first.
    std::vector<std::string> pareto_notes(const CsvTable &table, const std::size_t key_size)
    {
      const auto column = [&](const std::string &name) {
        return std::find(table.columns.begin(), table.columns.end(), name) - table.columns.begin();
      };
      const auto cell = [](const std::vector<CsvCell> &row, const std::size_t c) {
        return std::get<std::string>(row[c]);
      };
      // A row is named by the swept parameters whose values differ between rows.
      std::vector<std::size_t> varying;
      for (std::size_t c = 0; c < key_size; ++c)
        for (const auto &row : table.rows)
          if (cell(row, c) != cell(table.rows.front(), c))
            {
              varying.push_back(c);
              break;
            }
      const std::size_t        time = column("wall_total_median");
      std::vector<std::string> notes;
      for (const char *error : {"spectrum_error", "receptance_error", "energy_error_max"})
        {
          std::vector<std::pair<double, const std::vector<CsvCell> *>> rows;
          for (const auto &row : table.rows)
            if (!cell(row, column(error)).empty())
              rows.emplace_back(std::stod(cell(row, time)), &row);
          std::sort(rows.begin(), rows.end(),
                    [](const auto &a, const auto &b) { return a.first < b.first; });
          double best = std::numeric_limits<double>::infinity();
          for (const auto &[seconds_taken, row] : rows)
            if (const double e = std::stod(cell(*row, column(error))); e < best)
              {
                best = e;
                std::ostringstream note;
                note.precision(3);
                note << "  " << error << " " << e << " in " << seconds_taken << " s:";
                for (const std::size_t c : varying)
                  note << " " << table.columns[c] << " " << cell(*row, c);
                notes.push_back(note.str());
              }
        }
      if (!notes.empty())
        notes.insert(notes.begin(), "the fastest row to each error (median time):");
      return notes;
    }

    std::string seconds(const double s)
    {
      std::ostringstream out;
      out.precision(3);
      out << s << " s";
      return out.str();
    }
  } // namespace

  namespace
  {
    /// The combination's values with those its run does not use written "-"
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
              key[i] = "-";
          }
      return key;
    }
  } // namespace

  std::vector<StudyCombination> study_combinations(const std::string &path, const Scene &base)
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
            c.scene = Scene::from_parameters(prm, path + ", study row " + std::to_string(combinations.size() + 1));
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
    return combinations;
  }

  std::vector<Scene> reference_levels(const std::string &path, const Scene &base)
  {
    dealii::ParameterHandler prm;
    read(prm, path);
    set_row_outputs(prm, base.study);
    if (!base.study.reference_degree.empty())
      set_entry(prm, "Discretisation", "Degree", base.study.reference_degree);
    set_entry(prm, "Discretisation", "Refinement", "none");
    std::vector<Scene> levels;
    for (const std::string &cells : base.study.reference_cells)
      {
        set_entry(prm, "Discretisation", "Cells", cells);
        levels.push_back(Scene::from_parameters(prm, path + ", reference with " + cells + " cells"));
      }
    return levels;
  }

  namespace
  {
    /// "; n combinations left out: ..." if study_combinations left any out.
    std::string left_out_note(const StudyParameters &study, const std::size_t rows)
    {
      std::size_t swept = 1;
      for (const StudyParameters::Sweep &s : study.sweeps)
        swept *= std::max<std::size_t>(1, s.values.size());
      if (swept == rows)
        return "";
      return "; " + std::to_string(swept - rows) +
             " combinations left out: each repeats an earlier row's run (Time samples under exact "
             "integration, graded or adaptive parameters of another refinement)";
    }

    /// The study's fine backbone reference, if it asks for one: rank 0
    /// computes it (or finds it kept); every rank then reads it once, and
    /// rank 0 adds the summary's lines to `notes`. A failure on rank 0 stops
    /// all.
    std::optional<FineReference> shared_fine_reference(const std::string &path, const Scene &base,
                                                       const MPI_Comm comm, std::vector<std::string> &notes)
    {
      if (base.study.reference_cells.empty())
        return std::nullopt;
      const std::vector<Scene> levels = reference_levels(path, base);
      const bool               root   = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      std::string              origin, failure;
      if (root)
        try
          {
            origin = keep_fine_reference(levels, base.output.directory);
          }
        catch (const std::exception &e)
          {
            failure = e.what();
          }
      failure = dealii::Utilities::MPI::broadcast(comm, failure, 0);
      if (!failure.empty())
        throw NumericalError("the fine reference (Study/Reference cells) failed: " + failure);
      const CsvTable table = read_csv(base.output.directory + "/reference.csv");
      if (root)
        notes = fine_reference_notes(table, levels, origin);
      return read_fine_reference(table, levels);
    }
  } // namespace

  RunReport run_study(const std::string &path, const Scene &base)
  {
    const MPI_Comm     comm  = MPI_COMM_WORLD;
    const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const bool         root  = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    const auto         start = std::chrono::steady_clock::now();
    const clock_t      cpu_start = std::clock();

    const std::vector<StudyCombination> combinations = study_combinations(path, base);
    CsvTable                            table{"study.csv", {}, {}};
    for (const StudyParameters::Sweep &s : base.study.sweeps)
      table.columns.push_back(s.column);
    const std::size_t key_size = table.columns.size();
    for (const std::string &c : study_row_columns(base.study))
      table.columns.push_back(c);

    const std::string directory  = base.output.directory;
    const std::string scene_text = fingerprint(path, base);
    auto              rows       = earlier_rows(directory, scene_text, table.columns, key_size);
    std::vector<std::size_t> missing;
    for (std::size_t i = 0; i < combinations.size(); ++i)
      if (rows.count(combinations[i].key) == 0)
        missing.push_back(i);
    const std::size_t resumed = combinations.size() - missing.size();
    // study.csv holds the rows computed so far, in combination order.
    const auto in_combination_order = [&] {
      table.rows.clear();
      for (const StudyCombination &c : combinations)
        if (const auto row = rows.find(c.key); row != rows.end())
          table.rows.push_back(row->second);
    };

    // Every rank has checked the same input; only rank 0 writes.
    if (root)
      {
        std::error_code error;
        fs::create_directories(directory, error);
        if (error)
          throw InputError("parameter 'Output/Directory' = " + directory + " cannot be created: " +
                           error.message() + "; allowed: a new or empty directory, or this study's");
        write_atomically(directory + "/study.scene", [&](std::ostream &out) { out << scene_text; });
      }
    std::vector<std::string>           reference_notes;
    const std::optional<FineReference> fine = shared_fine_reference(path, base, comm, reference_notes);
    unsigned int failed = 0;
    Progress     progress("study", base.output.progress_every);
    for (std::size_t round = 0; round < missing.size(); round += ranks)
      {
        const std::size_t mine = round + dealii::Utilities::MPI::this_mpi_process(comm);
        std::string       packed;
        if (mine < missing.size())
          {
            const StudyCombination  &c     = combinations[missing[mine]];
            std::vector<std::string> cells = c.key;
            for (std::string &cell : measure_study_row(c.scene, fine ? &*fine : nullptr))
              cells.push_back(std::move(cell));
            packed = pack_row(missing[mine], cells);
          }
        const std::vector<std::string> gathered = dealii::Utilities::MPI::gather(comm, packed, 0);
        if (!root)
          continue;
        for (const std::string &p : gathered)
          if (!p.empty())
            {
              std::vector<std::string> cells = split_fields(p, '\x1f');
              cells.erase(cells.begin());
              failed += cells[key_size] != "ok";
              std::vector<std::string> key(cells.begin(), cells.begin() + key_size);
              rows[key] = std::vector<CsvCell>(cells.begin(), cells.end());
            }
        in_combination_order();
        write_csv(directory, table);
        const std::size_t done    = std::min(missing.size(), round + ranks);
        const double      elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        progress.update([&] {
          return std::to_string(resumed + done) + " of " + std::to_string(combinations.size()) + " rows (" +
                 std::to_string(resumed) + " from an earlier run), " + seconds(elapsed) + " elapsed, about " +
                 seconds(elapsed / done * (missing.size() - done)) + " left";
        });
      }

    RunReport report;
    report.stages.push_back({"study",
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                             double(std::clock() - cpu_start) / CLOCKS_PER_SEC});
    if (!root)
      return report;
    std::ostringstream note;
    note << "study: " << combinations.size() << " rows, " << missing.size() << " run now on " << ranks
         << (ranks == 1 ? " rank, " : " ranks, ") << resumed << " from an earlier run, " << failed
         << " failed" << left_out_note(base.study, combinations.size());
    report.notes.push_back(note.str());
    for (std::string &line : reference_notes)
      report.notes.push_back(std::move(line));
    in_combination_order();
    for (std::string &line : pareto_notes(table, key_size))
      report.notes.push_back(std::move(line));
    report.files = {directory + "/study.csv", directory + "/study.scene"};
    if (fine)
      report.files.push_back(directory + "/reference.csv");
    if (base.output.plots)
      for (std::string &f : make_plots(base, directory))
        report.files.push_back(std::move(f));
    return report;
  }
} // namespace nsm
