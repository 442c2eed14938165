#include <nsm/study/study_measures.h>
#include <nsm/study/study_row.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

namespace nsm
{
  namespace
  {
    std::string column_name(std::string stage)
    {
      std::replace(stage.begin(), stage.end(), ' ', '_');
      std::replace(stage.begin(), stage.end(), '-', '_');
      return "wall_" + stage;
    }

    std::string text(const double value)
    {
      std::ostringstream s;
      s.precision(std::numeric_limits<double>::max_digits10);
      s << value;
      return s.str();
    }

    std::string text(const std::optional<double> &value) { return value ? text(*value) : ""; }

    /// A line "Name:   value kB" of /proc/self/status, in MiB.
    double status_mib(const std::string &name)
    {
      std::ifstream status("/proc/self/status");
      for (std::string line; std::getline(status, line);)
        if (line.rfind(name + ":", 0) == 0)
          return std::stod(line.substr(name.size() + 1)) / 1024;
      return 0;
    }

    /// Resets the peak resident set size to the current one (Linux: "5" to
    /// clear_refs), so that VmHWM after the row is the row's peak. (The
    /// difference from the resident size at the start is no measure: the
    /// allocator reuses the memory earlier rows freed, and it was 0 in most
    /// rows.)
    void reset_peak_memory()
    {
      std::ofstream("/proc/self/clear_refs") << "5";
    }

    double median(std::vector<double> v)
    {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    }

    /// The costs of a row's repeated runs, and how the last one ended.
    struct RepeatedRuns
    {
      RowMeasures                      measures;
      std::string                      status = "ok";
      std::vector<double>              totals, cpu;
      std::vector<std::vector<double>> stage_walls = std::vector<std::vector<double>>(study_stages().size());
    };

    /// Runs `scene` Study/Repeats times, or until a run fails: a failure's
    /// status is kept as one CSV cell, and its measures left empty.
    RepeatedRuns repeat_runs(const StudyScene &row, const RowReference &reference)
    {
      RepeatedRuns runs;
      for (unsigned int r = 0; r < row.study.repeats && runs.status == "ok"; ++r)
        {
          StageRunner stages;
          try
            {
              runs.measures = measure_run(row, reference, stages);
            }
          catch (const NumericalError &e)
            {
              runs.status = std::string("failed: ") + e.what();
            }
          catch (const char *message) // NOX throws these
            {
              runs.status = std::string("failed: ") + message;
            }
          const std::vector<StageTiming> timings = stages.timings();
          double                         total = 0, total_cpu = 0;
          for (std::size_t s = 0; s < study_stages().size(); ++s)
            {
              const auto it = std::find_if(timings.begin(), timings.end(),
                                           [&](const StageTiming &t) { return t.name == study_stages()[s]; });
              runs.stage_walls[s].push_back(it == timings.end() ? 0.0 : it->wall_seconds);
              total += runs.stage_walls[s].back();
            }
          for (const StageTiming &t : timings)
            total_cpu += t.cpu_seconds;
          runs.totals.push_back(total);
          runs.cpu.push_back(total_cpu);
        }
      if (runs.status != "ok")
        runs.measures = RowMeasures();
      std::replace(runs.status.begin(), runs.status.end(), ',', ';');
      std::replace(runs.status.begin(), runs.status.end(), '\n', ' ');
      return runs;
    }
  } // namespace

  std::vector<std::string> study_row_columns(const StudyParameters &study)
  {
    std::vector<std::string> columns = {"status", "reference", "dofs", "final_cells", "hb_unknowns",
                                        "time_samples_used", "spectrum_error", "spectrum_modes_measured", "receptance_error",
                                        "energy_error_max", "energy_error_median", "force_error_max",
                                        "contact_fraction_error_max", "main_energy_error_median",
                                        "main_energy_error_q90", "main_time_defect_median",
                                        "main_time_defect_max", "energy_points",
                                        "main_points", "newton_iterations", "failed_solves",
                                        "backbone_end", "omega_reached", "energy_error_partial",
                                        "forced_curves", "forced_curves_whole", "forced_peaks_compared",
                                        "forced_peaks_at_range_end", "forced_peaks_linear", "forced_peak_distance_max",
                                        "forced_peak_phase_min", "forced_peak_phase_max",
                                        "peak_memory_mib", "wall_total_min", "wall_total_median",
                                        "wall_total_max", "cpu_total_median"};
    for (const std::string &stage : study_stages())
      columns.push_back(column_name(stage));
    for (const double omega : study.backbone_omega_values)
      {
        std::ostringstream name;
        name.precision(12);
        name << "energy_at_" << omega;
        columns.push_back(name.str());
      }
    return columns;
  }

  std::vector<std::optional<MainBranchPoint>> main_branch_at(const StudyScene &row)
  {
    StageRunner stages;
    // Without a reference, measure_run skips the spectrum and receptance errors
    // the study's rows measure, and without verification the time
    // integration: a reference level needs only its backbone.
    StudyScene level           = row;
    level.study.verify_in_time = false;
    level.study.forced_peaks   = false;
    return measure_run(level, no_reference(level), stages).points;
  }

  std::vector<std::string> measure_study_row(const StudyScene &run, const FineReference *fine)
  {
    const RowReference reference = reference_of(run, fine);
    reset_peak_memory();
    RepeatedRuns       runs      = repeat_runs(run, reference);
    RowMeasures       &m         = runs.measures;
    const auto        &totals    = runs.totals;

    std::vector<std::string> row = {runs.status,
                                    reference.name,
                                    std::to_string(m.dofs),
                                    std::to_string(m.cells),
                                    std::to_string(m.hb_unknowns),
                                    m.time_samples ? std::to_string(m.time_samples) : std::string(),
                                    text(m.spectrum_error),
                                    m.spectrum_error ? std::to_string(m.spectrum_modes) : std::string(),
                                    text(m.receptance_error),
                                    text(m.energy_error_max),
                                    text(m.energy_error_median),
                                    text(m.force_error_max),
                                    text(m.contact_fraction_error_max),
                                    text(m.main_error_median),
                                    text(m.main_error_q90),
                                    text(m.time_defect_median),
                                    text(m.time_defect_max),
                                    std::to_string(m.energy_points),
                                    std::to_string(m.main_points),
                                    std::to_string(m.newton_iterations),
                                    std::to_string(m.failed_solves),
                                    m.backbone_end,
                                    text(m.omega_reached),
                                    m.energy_error_partial ? (*m.energy_error_partial ? "yes" : "no") : "",
                                    run.study.forced_peaks ? std::to_string(m.forced_curves) : "",
                                    run.study.forced_peaks ? std::to_string(m.forced_curves_whole) : "",
                                    run.study.forced_peaks ? std::to_string(m.forced_peaks_compared) : "",
                                    run.study.forced_peaks ? std::to_string(m.forced_peaks_at_range_end) : "",
                                    run.study.forced_peaks ? std::to_string(m.forced_peaks_linear) : "",
                                    text(m.forced_peak_distance_max),
                                    text(m.forced_peak_phase_min),
                                    text(m.forced_peak_phase_max),
                                    text(status_mib("VmHWM")),
                                    text(*std::min_element(totals.begin(), totals.end())),
                                    text(median(totals)),
                                    text(*std::max_element(totals.begin(), totals.end())),
                                    text(median(runs.cpu))};
    for (const std::vector<double> &walls : runs.stage_walls)
      row.push_back(text(median(walls)));
    m.points.resize(run.study.backbone_omega_values.size());
    for (const std::optional<MainBranchPoint> &p : m.points)
      row.push_back(p ? text(p->energy) : "");
    return row;
  }
} // namespace nsm
