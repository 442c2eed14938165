#include <nsm/continuation/continuation.h>
#include <nsm/base/csv.h>
#include <nsm/model/memory_estimate.h>
#include <nsm/output/output_directory.h>
#include <nsm/output/plots.h>
#include <nsm/base/interruption.h>
#include <nsm/base/progress.h>
#include <nsm/base/text.h>
#include <nsm/study/study.h>
#include <nsm/study/study_measures.h>
#include <nsm/study/study_shared_errors.h>
#include <nsm/study/study_combinations.h>
#include <nsm/study/study_reference.h>
#include <nsm/study/study_row.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <vector>
#include <set>
#include <sstream>
#include <thread>

namespace nsm
{
  namespace
  {
    /// Throws InputError if the run of `scene` needs more memory than is available.
    void check_scene_memory(const Scene &scene)
    {
      check_memory(estimated_memory(scene), scene.resources);
    }

    namespace fs = std::filesystem;

    std::string file_text(const std::string &path)
    {
      std::ifstream      in(path);
      std::ostringstream text;
      text << in.rdbuf();
      return text.str();
    }

    /// Removes those of `folders` that are empty, deepest first.
    void remove_empty(const std::vector<std::string> &folders)
    {
      std::error_code error;
      for (const std::string &folder : folders)
        fs::remove(folder, error); // a folder that is not empty stays
    }

    /// What a study writes into its directory, in place; NAME.partial is a
    /// write it did not finish.
    const std::set<std::string> study_files = {"study.csv",        "study.scene", "reference.csv", "study.png",
                                               "study_forced.png", "plots.log",   "summary.txt"};

    /// Output/Directory of a study, before anything reads or writes it:
    /// missing, or a directory (not a link) that holds only regular files
    /// of the kinds a study writes, so that no file is read from a special
    /// file or written through a link, and no scene's output is mixed in.
    void check_study_directory(const std::string &directory)
    {
      const auto refuse = [&](const std::string &why) {
        std::string files;
        for (const std::string &f : study_files)
          files += (files.empty() ? "" : ", ") + f;
        throw InputError("parameter 'Output/Directory' = '" + printable(directory) + "' is not allowed: " + why +
                         "; allowed: a new or empty directory, or this study's (" + files + ")");
      };
      std::error_code       error;
      const fs::file_status status = fs::symlink_status(directory, error);
      if (fs::is_symlink(status))
        refuse("it is a symbolic link");
      if (!fs::exists(status))
        return;
      if (!fs::is_directory(status))
        refuse("it is not a directory");
      const std::string partial = ".partial";
      for (const auto &entry : fs::directory_iterator(directory, error))
        {
          const std::string name = entry.path().filename().string();
          const bool        half = name.size() > partial.size() &&
                            name.compare(name.size() - partial.size(), partial.size(), partial) == 0;
          if (!study_files.count(half ? name.substr(0, name.size() - partial.size()) : name))
            refuse("it holds '" + printable(name) + "', which no study writes");
          if (entry.is_symlink() || !entry.is_regular_file())
            refuse("its '" + printable(name) + "' is not a regular file");
        }
    }

    /// Checks that Output/Directory is new, empty, or holds this base
    /// scene's study; returns the rows it already holds, by key, and their
    /// keys in the file's order.
    struct EarlierRows
    {
      std::map<std::vector<std::string>, std::vector<CsvCell>> by_key;
      std::vector<std::vector<std::string>>                    order;
    };

    EarlierRows earlier_rows(const std::string &directory, const std::string &scene_text,
                             const std::vector<std::string> &columns, const std::size_t key_size)
    {
      EarlierRows rows;
      const std::string recorded = directory + "/study.scene";
      std::error_code   error;
      check_study_directory(directory);
      if (!fs::exists(directory, error) || fs::is_empty(directory, error))
        return rows;
      if (!fs::is_regular_file(recorded) || file_text(recorded) != scene_text)
        throw InputError("parameter 'Output/Directory' = " + directory +
                         " is not allowed: it holds files but not a study of this scene "
                         "(study.scene differs); allowed: a new or empty directory, or this study's");
      const CsvTable table = read_csv(directory + "/study.csv");
      if (!table.columns.empty() && table.columns != columns)
        {
          // Name one column that differs: a study.csv of another sweep, or of
          // another version of nsm-bar.
          std::string differs;
          for (const std::string &c : columns)
            if (differs.empty() && std::find(table.columns.begin(), table.columns.end(), c) == table.columns.end())
              differs = "it lacks '" + c + "'";
          for (const std::string &c : table.columns)
            if (differs.empty() && std::find(columns.begin(), columns.end(), c) == columns.end())
              differs = "it has '" + printable(c) + "', which this study does not write";
          if (differs.empty())
            differs = "its columns come in another order";
          throw InputError("parameter 'Output/Directory' = " + directory + ": its study.csv has other columns (" +
                           differs + ": another sweep, or another version of nsm-bar); allowed: a new or empty "
                           "directory");
        }
      // The shared errors (the last columns) are computed anew from all rows.
      const std::size_t own = columns.size() - shared_error_columns().size();
      for (const auto &row : table.rows)
        {
          std::vector<std::string> key;
          for (std::size_t c = 0; c < key_size; ++c)
            key.push_back(text_cell(row, c));
          if (rows.by_key.count(key) == 0)
            rows.order.push_back(key);
          rows.by_key[key] = std::vector<CsvCell>(row.begin(), row.begin() + own);
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

    /// A row's backbone_end says its continuation stopped before the range's
    /// end (empty: the row ran no harmonic balance).
    bool stopped_short(const std::string &end)
    {
      return !end.empty() && end != backbone_end_name(BackboneEnd::range);
    }

    /// The swept columns (the first key_size) that take more than one value:
    /// they name a row. unused_value, for a value a row's run does not use,
    /// names nothing.
    std::vector<std::size_t> varying_columns(const CsvTable &table, const std::size_t key_size)
    {
      std::vector<std::size_t> varying;
      for (std::size_t c = 0; c < key_size; ++c)
        {
          std::set<std::string> values;
          for (const auto &row : table.rows)
            if (text_cell(row, c) != unused_value)
              values.insert(text_cell(row, c));
          if (values.size() > 1)
            varying.push_back(c);
        }
      return varying;
    }

    std::string row_name(const CsvTable                 &table,
                         const std::vector<CsvCell>     &row,
                         const std::vector<std::size_t> &varying)
    {
      std::string name;
      for (const std::size_t c : varying)
        if (text_cell(row, c) != unused_value)
          name += " " + table.columns[c] + " " + text_cell(row, c);
      return varying.empty() ? " the scene's own values (one row)" : name;
    }

    /// The forced peaks against the backbone, a line per row that traced
    /// forced curves with the backbone (Study/Forced peaks): how many peaks
    /// were compared, the largest distance in energy, and the fundamental's
    /// phase lag at the peaks (pi / 2 at phase resonance).
    std::vector<std::string> forced_peak_notes(const CsvTable &table, const std::size_t key_size)
    {
      const std::size_t distance = column_of(table, "forced_peak_distance_max");
      if (distance == table.columns.size())
        return {};
      const auto               varying = varying_columns(table, key_size);
      std::vector<std::string> notes;
      for (const auto &row : table.rows)
        {
          std::ostringstream note;
          note.precision(2);
          if (text_cell(row, column_of(table, "status")) != "ok")
            {
              notes.push_back(" " + row_name(table, row, varying) + ": the row failed, no peak compared (its status "
                              "in study.csv says why)");
              continue;
            }
          if (text_cell(row, column_of(table, "forced_curves")).empty())
            continue;
          const std::string curves = text_cell(row, column_of(table, "forced_curves")),
                            whole  = text_cell(row, column_of(table, "forced_curves_whole"));
          const std::string compared = text_cell(row, column_of(table, "forced_peaks_compared"));
          const int         open     = std::stoi(curves) - std::stoi(whole);
          const int at_end = std::stoi(text_cell(row, column_of(table, "forced_peaks_at_range_end")));
          const int linear = std::stoi(text_cell(row, column_of(table, "forced_peaks_linear")));
          const int unbracketed = std::stoi(whole) - std::stoi(compared) - at_end - linear;
          std::vector<std::string> why;
          if (open > 0)
            why.push_back(std::to_string(open) + " not traced whole: a stretch neither trace reached may hold the peak");
          if (at_end > 0)
            why.push_back(std::to_string(at_end) + " with the most energy at the range's end (still climbing there)");
          if (linear > 0)
            why.push_back(std::to_string(linear) + " never touching the wall (the linear response)");
          if (unbracketed > 0)
            why.push_back(std::to_string(unbracketed) + " with no main point on both sides");
          note << " " << row_name(table, row, varying) << ": " << compared << " of " << curves << " peaks compared";
          for (std::size_t w = 0; w < why.size(); ++w)
            note << (w == 0 ? " (" : "; ") << why[w] << (w + 1 == why.size() ? ")" : "");
          if (text_cell(row, distance).empty())
            note << ": no peak to compare";
          else
            note << ", the largest " << 100 * std::stod(text_cell(row, distance))
                 << " % from the main branch in energy; phase lag "
                 << significant(std::stod(text_cell(row, column_of(table, "forced_peak_phase_min"))), 3) << " to "
                 << significant(std::stod(text_cell(row, column_of(table, "forced_peak_phase_max"))), 3);
          notes.push_back(note.str());
        }
      if (!notes.empty())
        notes.insert(notes.begin(), "the forced curves' peaks against the backbone's main branch (phase lag pi / 2 "
                                    "= 1.57 at phase resonance):");
      return notes;
    }

    /// The run summary's answer to "what does accuracy cost": per measured
    /// error, the rows that no other row beats in both error and median
    /// time (the Pareto front), fastest first. The backbone's energy errors
    /// are those over the Backbone omegas every row shares with the
    /// reference (study_shared_errors.h), so that rows which found the main
    /// branch at different Omegas compare on equal terms; rows whose
    /// continuation ended inside the Backbone omegas (energy_error_partial)
    /// are left out of them, as study.png marks them.
    std::vector<std::string> pareto_notes(const CsvTable &table, const std::size_t key_size)
    {
      const auto column  = [&](const std::string &name) { return column_of(table, name); };
      const auto varying = varying_columns(table, key_size);
      const std::size_t        time = column("wall_total_median");
      std::vector<std::string> notes;
      for (const std::string error : {"spectrum_error", "receptance_error", "energy_error_max", "energy_error_median",
                                      "main_time_defect_median"})
        {
          const bool        backbone_error = error.rfind("energy_error", 0) == 0;
          const std::string measured       = backbone_error ? error + "_shared" : error;
          std::vector<std::pair<double, const std::vector<CsvCell> *>> rows;
          unsigned int                                                 partial = 0;
          std::string                                                  shared;
          for (const auto &row : table.rows)
            {
              if (text_cell(row, column(error)).empty())
                continue;
              if (backbone_error && text_cell(row, column(measured)).empty())
                ++partial;
              else
                rows.emplace_back(std::stod(text_cell(row, time)), &row);
              if (backbone_error && shared.empty())
                shared = text_cell(row, column("shared_omegas"));
            }
          std::sort(rows.begin(), rows.end(),
                    [](const auto &a, const auto &b) { return a.first < b.first; });
          double best = std::numeric_limits<double>::infinity();
          for (const auto &[seconds_taken, row] : rows)
            if (const double e = std::stod(text_cell(*row, column(measured))); e < best)
              {
                best = e;
                std::ostringstream note;
                note.precision(3);
                note << "  " << measured << " " << e << " in " << seconds_taken << " s:"
                     << row_name(table, *row, varying);
                notes.push_back(note.str());
              }
          if (backbone_error && !rows.empty())
            notes.push_back("  (" + measured + ": " + error + " over the " + shared +
                            " Backbone omegas every row shares with the reference)");
          if (partial > 0)
            notes.push_back("  (" + measured + ": " + std::to_string(partial) +
                            (partial == 1 ? " row left out: its continuation ended" :
                                            " rows left out: their continuations ended") +
                            " inside the Backbone omegas (energy_error_partial), or no Omega is shared)");
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

    /// The ranks and this one's: a serial study (no mpirun) runs without
    /// MPI, and deal.II's MPI functions need it initialised.
    unsigned int ranks(const MPI_Comm comm)
    {
      return dealii::Utilities::MPI::job_supports_mpi() ? dealii::Utilities::MPI::n_mpi_processes(comm) : 1;
    }
    unsigned int rank(const MPI_Comm comm)
    {
      return dealii::Utilities::MPI::job_supports_mpi() ? dealii::Utilities::MPI::this_mpi_process(comm) : 0;
    }
    bool parallel(const MPI_Comm comm) { return ranks(comm) > 1; }

    /// The study's fine backbone reference, if it asks for one: rank 0
    /// computes it (or finds it kept); every rank then reads it once, and
    /// rank 0 adds the summary's lines to `notes`. A failure on rank 0 stops
    /// all.
    std::optional<FineReference> shared_fine_reference(const std::string &path, const StudyScene &base,
                                                       const MPI_Comm comm, std::vector<std::string> &notes)
    {
      if (base.study.reference_cells.empty())
        return std::nullopt;
      const std::vector<StudyScene> levels = reference_levels(path, base);
      const bool               root   = rank(comm) == 0;
      std::string              origin, failure;
      if (!parallel(comm)) // a failure keeps its kind (input, output, numerical)
        origin = keep_fine_reference(levels, base.scene.output.directory);
      else if (root)
        try
          {
            origin = keep_fine_reference(levels, base.scene.output.directory);
          }
        catch (const std::exception &e)
          {
            failure = e.what();
          }
      if (parallel(comm))
        failure = dealii::Utilities::MPI::broadcast(comm, failure, 0);
      if (!failure.empty())
        throw NumericalError("the fine reference (Study/Reference cells) failed: " + failure);
      const CsvTable table = read_csv(base.scene.output.directory + "/reference.csv");
      if (root)
        notes = fine_reference_notes(table, levels, origin);
      return read_fine_reference(table, levels);
    }
    /// A study's rows on this rank: those study.csv already holds, those
    /// missing, and the rounds over the ranks that compute them.
    class StudyRun
    {
    public:
      StudyRun(const std::string &path, const StudyScene &base)
        : base_(base)
        , combinations_(study_combinations(path, base))
        , scene_text_(study_fingerprint(path, base))
      {
        for (const StudyParameters::Sweep &s : base.study.sweeps)
          table_.columns.push_back(s.column);
        key_size_ = table_.columns.size();
        for (const std::string &c : study_row_columns(base.study))
          table_.columns.push_back(c);
        own_columns_ = table_.columns;
        std::vector<std::string> written = own_columns_;
        written.insert(written.end(), shared_error_columns().begin(), shared_error_columns().end());
        EarlierRows earlier = earlier_rows(directory(), scene_text_, written, key_size_);
        // An earlier row is a combination's where every value is the same,
        // however spelt (0.002 and 2e-3): it takes the combination's key.
        // The rows of an earlier sweep that this one's lists leave out stay.
        for (std::vector<std::string> &key : earlier.order)
          {
            std::vector<CsvCell> &row = earlier.by_key.at(key);
            const auto same = std::find_if(combinations_.begin(), combinations_.end(), [&](const StudyCombination &c) {
              return std::equal(c.key.begin(), c.key.end(), key.begin(), key.end(), same_study_value);
            });
            if (same == combinations_.end())
              {
                rows_[key] = std::move(row);
                kept_.push_back(std::move(key));
                continue;
              }
            std::copy(same->key.begin(), same->key.end(), row.begin());
            rows_[same->key] = std::move(row);
          }
        for (std::size_t i = 0; i < combinations_.size(); ++i)
          if (rows_.count(combinations_[i].key) == 0)
            missing_.push_back(i);
        in_combination_order();
      }

      bool root() const { return rank_ == 0; }

      /// Every row fits in memory.
      void check_memory() const
      {
        for (const StudyCombination &c : combinations_)
          check_scene_memory(c.scene.scene);
      }

      const std::string &directory() const { return base_.scene.output.directory; }

      /// The wall and CPU time since the study began (deal.II's Timer).
      StageTiming timing() const { return {"study", timer_.wall_time(), timer_.cpu_time()}; }

      /// Rank 0 creates the directory and records the base scene: every
      /// rank has checked the same input, and only rank 0 writes.
      void prepare_directory() const
      {
        if (!root())
          return;
        // A failure leaves none of the directories it created behind.
        const std::vector<std::string> created = missing_folders(directory());
        std::error_code                error;
        fs::create_directories(directory(), error);
        if (error)
          {
            remove_empty(created);
            throw InputError("parameter 'Output/Directory' = " + directory() + " cannot be created: " +
                             error.message() + "; allowed: a new or empty directory, or this study's");
          }
        try
          {
            write_atomically(directory() + "/study.scene", [&](std::ostream &out) { out << scene_text_; });
          }
        catch (const OutputError &)
          {
            remove_empty(created); // nothing of the study is in them
            throw;
          }
      }

      /// Deals the missing rows out over the ranks in rounds; after each,
      /// rank 0 rewrites study.csv and prints the progress.
      void run_missing_rows(const FineReference *fine)
      {
        Progress progress("study", base_.scene.output.progress_every);
        rows_start_ = timer_.wall_time();
        for (std::size_t round = 0; round < missing_.size(); round += ranks_)
          {
            const std::size_t mine = round + rank_;
            std::string       packed;
            if (mine < missing_.size())
              {
                const StudyCombination  &c     = combinations_[missing_[mine]];
                std::vector<std::string> cells = c.key;
                for (std::string &cell : measure_study_row(c.scene, fine))
                  cells.push_back(std::move(cell));
                packed = pack_row(missing_[mine], cells);
              }
            // A second stop signal stopped this row at a point (serially):
            // the row is left out, the rows done are kept.
            if (!parallel(comm_) && point_stop_signal() != 0)
              {
                stopped_by_ = stop_signal();
                return;
              }
            const std::vector<std::string> gathered =
              parallel(comm_) ? dealii::Utilities::MPI::gather(comm_, packed, 0) : std::vector<std::string>{packed};
            if (root())
              {
                keep_rows(gathered);
                write_csv(directory(), table_);
                ran_ = std::min(missing_.size(), round + ranks_);
                progress.update([&] { return progress_line(ran_); });
              }
            // A stop asked of any rank stops every rank after the same round
            // (none after the last: every row is done).
            if (round + ranks_ < missing_.size() && (stopped_by_ = parallel(comm_) ? dealii::Utilities::MPI::max(stop_signal(), comm_) : stop_signal()) != 0)
              return;
          }
      }

      /// The signal that stopped the study after a round; 0 if none did.
      int stopped_by() const { return stopped_by_; }

      /// The summary's lines (rank 0): rows, the fine reference's lines,
      /// then the Pareto front.
      std::vector<std::string> notes(const std::vector<std::string> &reference_notes) const
      {
        std::ostringstream note;
        note << "study: " << counted(combinations_.size(), "row") << ", " << ran_ << " run now on "
             << counted(ranks_, "rank") << ", " << resumed() << " from an earlier run, " << failed_ << " failed; "
             << counted(ended_early(), "row") << " ended before the Omega range's end (backbone_end)"
             << left_out_note(base_.study, combinations_.size());
        std::vector<std::string> lines{note.str()};
        if (!kept_.empty())
          lines.push_back("study.csv keeps " + counted(kept_.size(), "row") +
                          " of an earlier run that this sweep's lists leave out, after its own (delete study.csv "
                          "to drop them)");
        if (const std::size_t fewer = fewer_spectrum_modes(); fewer > 0)
          lines.push_back(counted(fewer, "row") + " measured fewer than Study/Spectrum modes = " +
                          std::to_string(base_.study.spectrum_modes) +
                          ": their meshes have fewer modes (spectrum_modes_measured)");
        for (std::string &line : off_branch_notes())
          lines.push_back(std::move(line));
        if (ranks_ > 1 && ran_ > 0)
          lines.push_back("timings: the rows ran on " + counted(ranks_, "rank") + " sharing " +
                          counted(std::thread::hardware_concurrency(), "core") +
                          ": they compete for the cores and the memory bandwidth, so their wall_ and cpu_ "
                          "columns (and the fastest rows below) are not comparable with a serial study's");
        if (stopped_by_)
          lines.push_back(std::string("stopped by ") + stop_signal_name(stopped_by_) + " after " +
                          std::to_string(resumed() + ran_) + " of " + counted(combinations_.size(), "row") +
                          ": a rerun of the same scene computes the others");
        lines.insert(lines.end(), reference_notes.begin(), reference_notes.end());
        for (std::string &line : pareto_notes(table_, key_size_))
          lines.push_back(std::move(line));
        for (std::string &line : forced_peak_notes(table_, key_size_))
          lines.push_back(std::move(line));
        return lines;
      }

    private:
      std::size_t resumed() const { return combinations_.size() - missing_.size(); }

      /// The rows of study.csv whose spectrum error covers fewer modes than
      /// asked for.
      std::size_t fewer_spectrum_modes() const
      {
        const std::size_t c = column_of(table_, "spectrum_modes_measured");
        return std::count_if(table_.rows.begin(), table_.rows.end(), [&](const std::vector<CsvCell> &row) {
          const std::string &cell = text_cell(row, c);
          return !cell.empty() && std::stoul(cell) < base_.study.spectrum_modes;
        });
      }

      /// Per Backbone omega that lies on no main-branch segment in some
      /// finished rows (a tongue or a gap of the branch there), a line saying
      /// why its energy_at_ column is empty in those rows.
      std::vector<std::string> off_branch_notes() const
      {
        std::vector<std::string> lines;
        const std::size_t        status = column_of(table_, "status");
        for (std::size_t c = 0; c < table_.columns.size(); ++c)
          if (table_.columns[c].rfind("energy_at_", 0) == 0)
            {
              std::size_t ok = 0, empty = 0;
              for (const std::vector<CsvCell> &row : table_.rows)
                if (text_cell(row, status) == "ok")
                  {
                    ++ok;
                    empty += text_cell(row, c).empty();
                  }
              if (empty > 0)
                lines.push_back("Study/Backbone omegas: W = " + table_.columns[c].substr(10) +
                                " lies on no main-branch segment (outside the branch's extent, on a tongue or in a gap) in " +
                                std::to_string(empty) + " of " + counted(ok, "finished row") + ": its " +
                                table_.columns[c] + " column is empty there; an Omega inside a main segment of "
                                "backbone.csv gives a value");
            }
        return lines;
      }

      /// The rows of study.csv, earlier runs' too, whose continuation ended
      /// before the range's end.
      std::size_t ended_early() const
      {
        const std::size_t c = column_of(table_, "backbone_end");
        return std::count_if(table_.rows.begin(), table_.rows.end(), [&](const std::vector<CsvCell> &row) {
          return stopped_short(text_cell(row, c));
        });
      }

      /// Rank 0 keeps the gathered rows of one round.
      void keep_rows(const std::vector<std::string> &gathered)
      {
        for (const std::string &p : gathered)
          if (!p.empty())
            {
              std::vector<std::string> cells = split_fields(p, '\x1f');
              cells.erase(cells.begin());
              failed_ += cells[key_size_] != "ok";
              std::vector<std::string> key(cells.begin(), cells.begin() + key_size_);
              rows_[key] = std::vector<CsvCell>(cells.begin(), cells.end());
            }
        in_combination_order();
      }

      /// study.csv holds the rows computed so far (earlier runs' too), in
      /// combination order, then the rows of an earlier sweep outside this
      /// one, in their earlier order.
      void in_combination_order()
      {
        table_.rows.clear();
        table_.columns = own_columns_;
        for (const StudyCombination &c : combinations_)
          if (const auto row = rows_.find(c.key); row != rows_.end())
            table_.rows.push_back(row->second);
        for (const std::vector<std::string> &key : kept_)
          table_.rows.push_back(rows_.at(key));
        add_shared_errors(table_, base_.study.backbone_omega_values, reference_energies_);
      }

    public:
      /// The backbone reference's energies at the Backbone omegas (the
      /// exact mode's or the fine reference's), for the shared errors.
      void compare_with(const std::vector<std::optional<double>> &energies)
      {
        reference_energies_ = energies;
        in_combination_order();
      }

    private:

      /// A row's predicted share of the study's time: with backbones,
      /// (M + 1)^2.6, as whole rows of prm/study-seed-harmonics.prm grow
      /// from M = 40 to 160 (0.34, 2.07, 12.3 s); otherwise 1 (rows of a
      /// spectrum study take milliseconds, their fixed costs dominate).
      double predicted_work(const std::size_t missing_index) const
      {
        constexpr double harmonics_exponent = 2.6;
        const Scene     &scene              = combinations_[missing_[missing_index]].scene.scene;
        return base_.study.backbone_omega_values.empty() ?
                 1.0 :
                 std::pow(scene.harmonic_balance.harmonics + 1.0, harmonics_exponent);
      }

      /// The time left: the rows' time so far (the set-up and the fine
      /// reference left out) per unit of predicted work of the rows done,
      /// times the work of the rows left (rows of different M differ in cost
      /// by orders of magnitude).
      std::string progress_line(const std::size_t done) const
      {
        const double t = timer_.wall_time(), rows = t - rows_start_;
        double       past = 0, ahead = 0;
        for (std::size_t i = 0; i < missing_.size(); ++i)
          (i < done ? past : ahead) += predicted_work(i);
        return std::to_string(resumed() + done) + " of " + std::to_string(combinations_.size()) + " rows (" +
               std::to_string(resumed()) + " from an earlier run), " + seconds(t) + " elapsed, about " +
               seconds(past > 0 ? rows / past * ahead : 0) + " left";
      }

      const MPI_Comm                      comm_  = MPI_COMM_WORLD;
      const unsigned int                  ranks_ = ranks(comm_);
      const unsigned int                  rank_  = rank(comm_);
      const dealii::Timer                 timer_; ///< started first, so it counts the set-up too
      double                              rows_start_ = 0; ///< timer_'s time when the rows began
      const StudyScene &base_;
      const std::vector<StudyCombination> combinations_;
      const std::string                   scene_text_;
      CsvTable                            table_{"study.csv", {}, {}};
      std::size_t                         key_size_ = 0;
      std::vector<std::string>            own_columns_; ///< study.csv's columns but the shared errors
      std::vector<std::optional<double>>  reference_energies_; ///< at the Backbone omegas
      std::map<std::vector<std::string>, std::vector<CsvCell>> rows_;
      std::vector<std::vector<std::string>> kept_; ///< keys of earlier rows outside this sweep, in file order
      std::vector<std::size_t>            missing_;
      unsigned int                        failed_ = 0;
      int                                 stopped_by_ = 0;
      std::size_t                         ran_        = 0; ///< rows computed in this run
    };
  } // namespace

  RunReport run_study(const std::string &path, const StudyScene &base)
  {
    StudyRun study(path, base);
    // Rank 0 checks the memory and prepares the directory; a refusal there
    // stops every rank alike (the others would wait for it in a collective).
    std::string refused;
    try
      {
        study.check_memory();
        for (const StudyScene &level : reference_levels(path, base))
          check_scene_memory(level.scene);
        study.prepare_directory();
      }
    catch (const InputError &e)
      {
        refused = e.what();
      }
    if (parallel(MPI_COMM_WORLD))
      refused = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, refused, 0);
    if (!refused.empty())
      throw InputError(refused);
    std::vector<std::string>           reference_notes;
    const std::optional<FineReference> fine = shared_fine_reference(path, base, MPI_COMM_WORLD, reference_notes);
    study.compare_with(reference_of(base, fine ? &*fine : nullptr).energies);
    study.run_missing_rows(fine ? &*fine : nullptr);

    RunReport report;
    report.stages.push_back(study.timing());
    report.stopped_by = study.stopped_by();
    if (!study.root())
      return report;
    report.notes = study.notes(reference_notes);
    report.files = {study.directory() + "/study.csv", study.directory() + "/study.scene"};
    if (fine)
      report.files.push_back(study.directory() + "/reference.csv");
    if (base.scene.output.plots)
      {
        // A plot is an output like study.csv: a stop or a failure while it is
        // drawn keeps the rows (written in place before), and is said.
        PlotResult plots = make_plots(base.scene.contact, study.directory(), "study " + path);
        for (std::string &f : plots.files)
          report.files.push_back(std::move(f));
        if (!plots.failure.empty())
          {
            report.notes.insert(report.notes.begin(), "plots not drawn: " + plots.failure);
            if (plots.stopped_by == 0)
              report.plot_failure = plots.failure;
            else if (report.stopped_by == 0)
              report.stopped_by = plots.stopped_by;
          }
      }
    return report;
  }
} // namespace nsm
