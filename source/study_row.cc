#include <nsm/adaptive_refinement.h>
#include <nsm/bar_model.h>
#include <nsm/continuation.h>
#include <nsm/discretisation.h>
#include <nsm/exact_references.h>
#include <nsm/harmonic_balance.h>
#include <nsm/receptance.h>
#include <nsm/spectrum.h>
#include <nsm/study_row.h>
#include <nsm/time_verification.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// The timed stages, in the order of their study.csv columns.
    const std::vector<std::string> stages = {"mesh", "refinement", "spectrum", "receptance set-up",
                                             "receptance", "harmonic balance", "energy solves",
                                             "verification in time"};

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

    /// The values a row's measures compare with, computed once per row and
    /// outside the timed stages, so that the costs are the run's alone: the
    /// bar's exact spectrum, receptance and mode where known, else the fine
    /// backbone reference's points.
    struct Reference
    {
      std::string                        name = "none";
      bool                               exact_bar = false;
      std::vector<double>                frequencies; ///< the first Spectrum modes clamped-free ones
      std::vector<double>                gammas;      ///< at the Receptance frequencies
      std::vector<std::optional<double>> energies, forces, fractions; ///< at the Backbone omegas
      std::optional<ExactBar>            mode_bar; ///< knows the first mode's energy at any Omega
    };

    /// Nothing to compare with: a run measured for its own values.
    Reference no_reference(const Scene &scene)
    {
      Reference         r;
      const std::size_t n = scene.study.backbone_omega_values.size();
      r.energies.assign(n, std::nullopt);
      r.forces.assign(n, std::nullopt);
      r.fractions.assign(n, std::nullopt);
      return r;
    }

    Reference reference_of(const Scene &scene, const FineReference *fine)
    {
      Reference                     r     = no_reference(scene);
      const StudyParameters        &study = scene.study;
      const std::size_t             n     = study.backbone_omega_values.size();
      const std::optional<ExactBar> exact = ExactBar::of(BarModel(scene.bar));
      const bool mode = scene.contact.sign == ForceSign::physical && scene.continuation.mode == 1;
      bool       exact_mode = false;
      if (exact)
        {
          r.name        = exact->name();
          r.exact_bar   = true;
          r.frequencies = exact->clamped_free_frequencies(study.spectrum_modes);
          for (const double w : study.receptance_frequency_values)
            r.gammas.push_back(exact->receptance(w));
          if (mode)
            for (std::size_t i = 0; i < n; ++i)
              {
                r.energies[i] = exact->first_mode_energy(study.backbone_omega_values[i], scene.contact.gap);
                exact_mode |= r.energies[i].has_value();
              }
          if (mode)
            r.mode_bar = exact;
        }
      if (fine && !exact_mode && n > 0)
        {
          r.name = (exact ? r.name + "; backbone: " : std::string()) + fine->name;
          for (std::size_t i = 0; i < n; ++i)
            if (const auto &p = fine->points[i])
              {
                r.energies[i]  = p->energy;
                r.forces[i]    = p->max_contact_force;
                r.fractions[i] = p->contact_fraction;
              }
        }
      return r;
    }

    /// What one run measured; empty optionals were not measured.
    struct Measures
    {
      unsigned int          dofs = 0, cells = 0, hb_unknowns = 0, time_samples = 0;
      std::optional<double> spectrum_error, receptance_error, energy_error_max, energy_error_median,
        force_error_max, contact_fraction_error_max, main_error_median, main_error_q90, time_defect_median,
        time_defect_max;
      unsigned int          energy_points = 0, main_points = 0;
      std::vector<std::optional<MainBranchPoint>> points; ///< at each Backbone omega on the main branch
      std::vector<BackbonePoint>                  solved; ///< those found, for the verification in time
      unsigned long         newton_iterations = 0, failed_solves = 0;
    };

    /// max_j |w_h,j - w_j| / w_j over the exact frequencies w (fewer if the
    /// mesh has fewer modes).
    double spectrum_error(const Discretisation &d, const std::vector<double> &w)
    {
      const ModalData h     = compute_spectrum(d, EndCondition::clamped_free, w.size(), false);
      double          error = 0;
      for (std::size_t j = 0; j < h.eigenvalues.size(); ++j)
        error = std::max(error, std::abs(std::sqrt(h.eigenvalues[j]) - w[j]) / w[j]);
      return error;
    }

    /// max |gamma_h - gamma| / max |gamma| over the frequencies.
    double receptance_error(const Receptance &r, const std::vector<double> &omegas, const std::vector<double> &gammas)
    {
      double error = 0, scale = 0;
      for (std::size_t i = 0; i < omegas.size(); ++i)
        {
          error = std::max(error, std::abs(r(omegas[i]).gamma - gammas[i]));
          scale = std::max(scale, std::abs(gammas[i]));
        }
      return error / scale;
    }

    /// The largest of `errors` (empty: not measured).
    std::optional<double> largest(const std::vector<double> &errors)
    {
      if (errors.empty())
        return std::nullopt;
      return *std::max_element(errors.begin(), errors.end());
    }

    /// The main-branch points at the study's Omega values, and their errors
    /// where the reference knows them (energy and largest contact force
    /// relative, contact fraction absolute); the solves run either way, for
    /// their cost.
    void backbone_errors(HarmonicBalance &hb, const Scene &scene, const Backbone &backbone,
                         const Reference &reference, Measures &m)
    {
      std::vector<double> energy, force, fraction;
      m.points.assign(scene.study.backbone_omega_values.size(), std::nullopt);
      for (std::size_t i = 0; i < m.points.size(); ++i)
        try
          {
            const double        omega = scene.study.backbone_omega_values[i];
            const BackbonePoint p     = solve_on_branch(hb, scene, backbone, omega, true);
            ++m.energy_points;
            m.points[i] = MainBranchPoint{p.measures.energy, p.measures.max_contact_force,
                                          p.measures.contact_fraction};
            m.solved.push_back(p);
            if (const auto &e = reference.energies[i])
              energy.push_back(std::abs(p.measures.energy - *e) / *e);
            if (const auto &f = reference.forces[i])
              force.push_back(std::abs(p.measures.max_contact_force - *f) / *f);
            if (const auto &c = reference.fractions[i])
              fraction.push_back(std::abs(p.measures.contact_fraction - *c));
          }
        catch (const NumericalError &)
          {
            // Not on a main-branch segment: counted by energy_points.
          }
      m.force_error_max            = largest(force);
      m.contact_fraction_error_max = largest(fraction);
      if (energy.empty())
        return;
      std::sort(energy.begin(), energy.end());
      m.energy_error_max    = energy.back();
      m.energy_error_median = energy[energy.size() / 2];
    }

    /// The energy error of every written main-branch point against the exact
    /// mode, where it exists: needs no Omega bracketed by two main points, so
    /// it measures a run whose tongues leave only short main segments.
    void main_point_errors(const Backbone &backbone, const ExactBar &bar, double gap, Measures &m)
    {
      std::vector<double> errors;
      for (const BackbonePoint &p : backbone.points)
        if (p.branch == Branch::main)
          if (const std::optional<double> e = bar.first_mode_energy(p.omega, gap))
            errors.push_back(std::abs(p.measures.energy - *e) / *e);
      if (errors.empty())
        return;
      std::sort(errors.begin(), errors.end());
      m.main_error_median = errors[errors.size() / 2];
      m.main_error_q90    = errors[(errors.size() * 9) / 10];
    }

    /// The one-period defects of the main-branch points found at the
    /// Backbone omegas, integrated in time on the row's own FE model.
    void time_defects(HarmonicBalance &hb, const Discretisation &d, const Scene &scene, Measures &m)
    {
      std::vector<double> defects;
      for (const BackbonePoint &p : m.solved)
        {
          const PeriodicField field(hb, d, p, scene.contact.sign);
          defects.push_back(verify_in_time(field, d, scene).time.periodicity_defect);
        }
      if (defects.empty())
        return;
      std::sort(defects.begin(), defects.end());
      m.time_defect_median = defects[defects.size() / 2];
      m.time_defect_max    = defects.back();
    }

    Measures run_once(const Scene &scene, const Reference &reference, dealii::TimerOutput &timer)
    {
      using Scope = dealii::TimerOutput::Scope;
      Measures                        m;
      const BarModel                  bar(scene.bar);
      const bool                      exact = reference.exact_bar;
      std::unique_ptr<Discretisation> d;
      {
        Scope scope(timer, "mesh");
        d = std::make_unique<Discretisation>(bar, scene.discretisation);
      }
      if (scene.discretisation.refinement == Refinement::adaptive)
        {
          Scope scope(timer, "refinement");
          refine_adaptively(*d, scene.discretisation, scene.refinement_band());
        }
      m.dofs  = d->n_dofs();
      m.cells = d->n_cells();
      const StudyParameters &study = scene.study;
      if (study.spectrum_modes > 0 && exact)
        {
          Scope scope(timer, "spectrum");
          m.spectrum_error = spectrum_error(*d, reference.frequencies);
        }
      if (study.receptance_frequency_values.empty() && study.backbone_omega_values.empty())
        return m;
      std::unique_ptr<Receptance> receptance;
      {
        Scope scope(timer, "receptance set-up");
        receptance = std::make_unique<Receptance>(*d, scene.receptance, scene.receptance_band());
      }
      if (!study.receptance_frequency_values.empty() && exact)
        {
          Scope scope(timer, "receptance");
          m.receptance_error = receptance_error(*receptance, study.receptance_frequency_values, reference.gammas);
        }
      if (study.backbone_omega_values.empty())
        return m;
      HarmonicBalance hb(scene, *receptance);
      Backbone        backbone;
      {
        Scope scope(timer, "harmonic balance");
        backbone = compute_backbone(hb, scene, internal_resonances(*receptance, scene));
      }
      m.hb_unknowns       = hb.n_unknowns();
      m.time_samples      = hb.n_samples();
      m.main_points       = backbone.main_points();
      m.newton_iterations = backbone.newton_cost.converged_iterations + backbone.newton_cost.failed_iterations;
      m.failed_solves     = backbone.newton_cost.failed_solves;
      if (reference.mode_bar)
        main_point_errors(backbone, *reference.mode_bar, scene.contact.gap, m);
      {
        Scope scope(timer, "energy solves");
        backbone_errors(hb, scene, backbone, reference, m);
      }
      if (study.verify_in_time)
        {
          Scope scope(timer, "verification in time");
          time_defects(hb, *d, scene, m);
        }
      return m;
    }

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
    /// clear_refs) and returns it, so that the row's own peak is the
    /// difference.
    double reset_peak_memory()
    {
      std::ofstream("/proc/self/clear_refs") << "5";
      return status_mib("VmRSS");
    }

    double median(std::vector<double> v)
    {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    }
  } // namespace

  std::vector<std::string> study_row_columns(const StudyParameters &study)
  {
    std::vector<std::string> columns = {"status", "reference", "dofs", "final_cells", "hb_unknowns",
                                        "time_samples_used", "spectrum_error", "receptance_error",
                                        "energy_error_max", "energy_error_median", "force_error_max",
                                        "contact_fraction_error_max", "main_energy_error_median",
                                        "main_energy_error_q90", "main_time_defect_median",
                                        "main_time_defect_max", "energy_points",
                                        "main_points", "newton_iterations", "failed_solves",
                                        "peak_memory_mib", "wall_total_min", "wall_total_median",
                                        "wall_total_max", "cpu_total_median"};
    for (const std::string &stage : stages)
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

  std::vector<std::optional<MainBranchPoint>> main_branch_at(const Scene &scene)
  {
    std::ostringstream  quiet;
    dealii::TimerOutput timer(quiet, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    // Without a reference, run_once skips the spectrum and receptance errors
    // the study's rows measure, and without verification the time
    // integration: a reference level needs only its backbone.
    Scene level                = scene;
    level.study.verify_in_time = false;
    return run_once(level, no_reference(level), timer).points;
  }

  std::vector<std::string> measure_study_row(const Scene &scene, const FineReference *fine)
  {
    using Timer = dealii::TimerOutput;
    std::ostringstream                 quiet;
    Measures                           m;
    std::string                        status = "ok";
    std::vector<double>                totals, cpu;
    std::vector<std::vector<double>>   stage_walls(stages.size());
    const Reference reference = reference_of(scene, fine);
    const double    resident  = reset_peak_memory();
    for (unsigned int r = 0; r < scene.study.repeats && status == "ok"; ++r)
      {
        Timer timer(quiet, Timer::never, Timer::cpu_and_wall_times);
        try
          {
            m = run_once(scene, reference, timer);
          }
        catch (const NumericalError &e)
          {
            status = std::string("failed: ") + e.what();
          }
        catch (const char *message) // NOX throws these
          {
            status = std::string("failed: ") + message;
          }
        const auto walls = timer.get_summary_data(Timer::total_wall_time);
        const auto cpus  = timer.get_summary_data(Timer::total_cpu_time);
        double     total = 0, total_cpu = 0;
        for (std::size_t s = 0; s < stages.size(); ++s)
          {
            const auto it = walls.find(stages[s]);
            stage_walls[s].push_back(it == walls.end() ? 0.0 : it->second);
            total += stage_walls[s].back();
          }
        for (const auto &entry : cpus)
          total_cpu += entry.second;
        totals.push_back(total);
        cpu.push_back(total_cpu);
      }
    if (status != "ok")
      m = Measures();
    std::replace(status.begin(), status.end(), ',', ';'); // one CSV cell
    std::replace(status.begin(), status.end(), '\n', ' ');

    std::vector<std::string> row = {status,
                                    reference.name,
                                    std::to_string(m.dofs),
                                    std::to_string(m.cells),
                                    std::to_string(m.hb_unknowns),
                                    m.time_samples ? std::to_string(m.time_samples) : std::string(),
                                    text(m.spectrum_error),
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
                                    text(status_mib("VmHWM") - resident),
                                    text(*std::min_element(totals.begin(), totals.end())),
                                    text(median(totals)),
                                    text(*std::max_element(totals.begin(), totals.end())),
                                    text(median(cpu))};
    for (const std::vector<double> &walls : stage_walls)
      row.push_back(text(median(walls)));
    m.points.resize(scene.study.backbone_omega_values.size());
    for (const std::optional<MainBranchPoint> &p : m.points)
      row.push_back(p ? text(p->energy) : "");
    return row;
  }
} // namespace nsm
