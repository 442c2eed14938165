#include <nsm/adaptive_refinement.h>
#include <nsm/bar_model.h>
#include <nsm/continuation.h>
#include <nsm/field_output.h>
#include <nsm/fields.h>
#include <nsm/harmonic_balance.h>
#include <nsm/output_directory.h>
#include <nsm/discretisation.h>
#include <nsm/pipeline.h>
#include <nsm/progress.h>
#include <nsm/receptance.h>
#include <nsm/spectrum.h>
#include <nsm/time_verification.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <memory>
#include <ostream>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// Times one stage (wall and process CPU) into the report.
    template <typename Work>
    void timed(RunReport &report, const std::string &name, Work &&work)
    {
      const auto    wall0 = std::chrono::steady_clock::now();
      const clock_t cpu0  = std::clock();
      work();
      report.stages.push_back(
        {name,
         std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(),
         double(std::clock() - cpu0) / CLOCKS_PER_SEC});
    }

    std::string describe(const Discretisation &d)
    {
      std::ostringstream s;
      s << "discretisation: FE_Q(" << d.fe().degree << "), " << d.n_cells()
        << " cells, " << d.n_dofs() << " DoFs, h in [" << d.min_cell_size()
        << ", " << d.max_cell_size() << "]";
      return s.str();
    }

    CsvTable spectrum_table(const Discretisation &d, const unsigned int modes)
    {
      const ModalData free =
        compute_spectrum(d, EndCondition::clamped_free, modes, false);
      const ModalData clamped =
        compute_spectrum(d, EndCondition::clamped_clamped, modes, false);
      const std::size_t n = std::min(free.eigenvalues.size(), clamped.eigenvalues.size());
      CsvTable table{"spectrum.csv",
                     {"j", "omega_clamped_free", "omega_clamped_clamped"},
                     {}};
      for (std::size_t j = 0; j < n; ++j)
        table.rows.push_back({double(j + 1),
                              std::sqrt(free.eigenvalues[j]),
                              std::sqrt(clamped.eigenvalues[j])});
      return table;
    }

    CsvTable receptance_table(const Receptance &receptance, const Scene &scene)
    {
      CsvTable table{"receptance.csv", {"omega", "gamma", "dgamma_domega2"}, {}};
      for (const double w : scene.output.receptance_frequencies)
        {
          const ReceptanceValue v = receptance(w);
          table.rows.push_back({w, v.gamma, v.dgamma_domega2});
        }
      return table;
    }
    using Verifications = std::vector<std::optional<PointVerification>>;

    /// The verification columns of one row; empty cells for a point not verified.
    std::vector<CsvCell> verification_cells(const std::optional<PointVerification> &v)
    {
      if (!v)
        return std::vector<CsvCell>(6, std::string());
      return {v->verified ? "true" : "false", v->time.periodicity_defect, v->time.periodicity_defect_end,
              v->time.energy_drift, v->impulse_ratio, v->time.contact_fraction};
    }

    CsvTable backbone_table(const Backbone &backbone, const Verifications &verifications)
    {
      CsvTable table{"backbone.csv",
                     {"segment", "Omega", "energy", "energy_spread", "max_contact_force",
                      "contact_fraction", "newton_iterations", "residual", "branch",
                      "resonance_mode", "resonance_harmonic"},
                     {}};
      if (!verifications.empty())
        for (const char *c : {"verified", "periodicity_defect", "periodicity_defect_end", "energy_drift",
                              "impulse_ratio", "verified_contact_fraction"})
          table.columns.push_back(c);
      for (std::size_t i = 0; i < backbone.points.size(); ++i)
        {
          const BackbonePoint &p = backbone.points[i];
          table.rows.push_back({double(p.segment), p.omega, p.measures.energy,
                                p.measures.energy_spread, p.measures.max_contact_force,
                                p.measures.contact_fraction, double(p.newton_iterations),
                                p.residual, branch_name(p.branch),
                                double(p.resonance.mode), double(p.resonance.harmonic)});
          if (!verifications.empty())
            for (CsvCell &cell : verification_cells(verifications[i]))
              table.rows.back().push_back(std::move(cell));
        }
      return table;
    }

    /// A field asked for at an Omega where the computed branch is a tongue.
    std::string tongue_field_note(const BackbonePoint &p)
    {
      std::ostringstream s;
      s.precision(6);
      s << "field at Omega = " << p.omega << " is on the resonance tongue of w_" << p.resonance.mode << " / "
        << p.resonance.harmonic << " = " << p.resonance.omega << ", not on the main branch (energy "
        << p.measures.energy << ", above the main branch beyond it by more than Tongue share)";
      return s.str();
    }

    /// The summary line of a field's verification.
    std::string field_verification(const PeriodicField &field, const Discretisation &discretisation, const Scene &scene)
    {
      const PointVerification v = verify_in_time(field, discretisation, scene);
      std::ostringstream      s;
      s.precision(6);
      s << "field at Omega = " << field.omega() << " verified in time: one-period defect / g0 "
        << v.time.periodicity_defect << " (" << (v.verified ? "periodic" : "NOT periodic")
        << " to Verify tolerance), after " << scene.output.verify_periods << " periods "
        << v.time.periodicity_defect_end << ", impulse ratio " << v.impulse_ratio;
      return s.str();
    }

    /// "verification in time: ..." for the run summary.
    std::string verification_summary(const Verifications &verifications, const Scene &scene)
    {
      std::vector<double> defects;
      unsigned int        flagged = 0;
      for (const auto &v : verifications)
        if (v)
          {
            defects.push_back(v->time.periodicity_defect);
            flagged += !v->verified;
          }
      std::sort(defects.begin(), defects.end());
      std::ostringstream s;
      s << "verification in time: " << defects.size() << " points, " << flagged
        << " not periodic to Verify tolerance = " << scene.output.verify_tolerance;
      if (!defects.empty())
        s << "; one-period defect / g0: median " << defects[defects.size() / 2] << ", max " << defects.back();
      return s.str();
    }

    CsvTable tongue_table(const Backbone &backbone)
    {
      CsvTable table{"tongues.csv",
                     {"mode", "harmonic", "omega_resonance", "foot_omega_begin",
                      "foot_omega_end", "max_energy", "points"},
                     {}};
      for (const Tongue &t : backbone.tongues)
        table.rows.push_back({double(t.resonance.mode), double(t.resonance.harmonic),
                              t.resonance.omega, t.foot_begin, t.foot_end, t.max_energy,
                              double(t.points)});
      return table;
    }

    CsvTable resonance_table(const std::vector<InternalResonance> &resonances)
    {
      CsvTable table{"resonances.csv", {"omega", "mode", "harmonic"}, {}};
      for (const InternalResonance &r : resonances)
        table.rows.push_back({r.omega, double(r.mode), double(r.harmonic)});
      return table;
    }
    /// Runs a program with these arguments, without a shell (no character of
    /// an argument is interpreted), its output to `log`; returns whether it
    /// exited with status 0.
    bool run_program(const std::vector<std::string> &arguments, const std::string &log)
    {
      std::vector<char *> argv;
      for (const std::string &a : arguments)
        argv.push_back(const_cast<char *>(a.c_str()));
      argv.push_back(nullptr);
      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                       O_WRONLY | O_CREAT | O_TRUNC, 0644);
      posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
      pid_t      pid;
      const bool spawned =
        posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0;
      posix_spawn_file_actions_destroy(&actions);
      int status = 0;
      return spawned && waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
             WEXITSTATUS(status) == 0;
    }

  } // namespace

  RunReport run_scene(const Scene &scene)
  {
    RunReport             report;
    std::vector<CsvTable> tables;

    const bool needs_spectrum   = scene.output.spectrum_modes > 0;
    const bool needs_receptance = !scene.output.receptance_frequencies.empty();
    const bool needs_fields     = scene.output.fields();
    const bool needs_backbone   = scene.output.backbone || needs_fields;
    const bool needs_mesh       = needs_spectrum || needs_receptance || needs_backbone;
    // The cross-section is checked even when nothing else is to be done.
    const BarModel bar(scene.bar);
    if (!needs_mesh)
      {
        report.notes.push_back("the scene requests no output: nothing to do");
        return report;
      }

    // Checked before any work: an unwritable directory is known now.
    OutputDirectory output(scene.output.directory);
    std::unique_ptr<Discretisation> discretisation;
    timed(report, "mesh and assembly", [&] {
      discretisation = std::make_unique<Discretisation>(bar, scene.discretisation);
    });
    if (scene.discretisation.refinement == Refinement::adaptive)
      timed(report, "adaptive refinement", [&] {
        Progress progress("adaptive refinement", scene.output.progress_every);
        for (std::string &note :
             refine_adaptively(*discretisation, scene.discretisation, scene.refinement_band(), &progress))
          report.notes.push_back(std::move(note));
      });
    report.notes.push_back(describe(*discretisation));

    if (needs_spectrum)
      timed(report, "spectrum", [&] {
        tables.push_back(spectrum_table(*discretisation, scene.output.spectrum_modes));
      });
    std::unique_ptr<Receptance> receptance;
    if (needs_receptance || needs_backbone)
      timed(report, "receptance set-up", [&] {
        receptance = std::make_unique<Receptance>(*discretisation, scene.receptance, scene.receptance_band());
      });
    if (needs_receptance)
      timed(report, "receptance", [&] { tables.push_back(receptance_table(*receptance, scene)); });
    std::unique_ptr<HarmonicBalance> hb;
    Backbone                         backbone;
    std::vector<InternalResonance>   resonances;
    if (needs_backbone)
      timed(report, "harmonic balance", [&] {
        hb         = std::make_unique<HarmonicBalance>(scene, *receptance);
        resonances = internal_resonances(*receptance, scene);
        backbone   = compute_backbone(*hb, scene, resonances);
        std::ostringstream s;
        s << "backbone: " << backbone.points.size() << " points (" << backbone.main_points()
          << " main, " << backbone.points.size() - backbone.main_points() << " on "
          << backbone.tongues.size() << " tongues), " << backbone.leaps << " leaps, "
          << backbone.folds.size() << " folds, " << hb->n_unknowns() << " unknowns";
        report.notes.push_back(s.str());
        for (const std::string &event : backbone.events)
          report.notes.push_back("  " + event);
      });

    Verifications verifications;
    if (scene.output.verify_in_time)
      timed(report, "verification in time", [&] {
        Progress progress("verification in time", scene.output.progress_every);
        verifications = verify_backbone(*hb, *discretisation, backbone, scene, progress);
        report.notes.push_back(verification_summary(verifications, scene));
      });
    if (scene.output.backbone)
      {
        tables.push_back(backbone_table(backbone, verifications));
        tables.push_back(tongue_table(backbone));
        tables.push_back(resonance_table(resonances));
      }

    std::vector<PeriodicField> fields;
    if (needs_fields)
      timed(report, "fields", [&] {
        const auto &o = scene.output;
        Progress    progress("fields", o.progress_every);
        const auto  report_count = [&] { return std::to_string(fields.size()) + " fields"; };
        for (const double omega : o.fields_at)
          {
            fields.emplace_back(*hb, *discretisation, solve_on_branch(*hb, scene, backbone, omega),
                                scene.contact.sign);
            if (const BackbonePoint &p = fields.back().point(); p.branch == Branch::tongue)
              report.notes.push_back(tongue_field_note(p));
            if (o.verify_in_time)
              report.notes.push_back(field_verification(fields.back(), *discretisation, scene));
            progress.update(report_count);
          }
        for (std::size_t i = 0; o.fields_every > 0 && i < backbone.points.size(); i += o.fields_every)
          {
            fields.emplace_back(*hb, *discretisation, backbone.points[i], scene.contact.sign);
            progress.update(report_count);
          }
      });

    timed(report, "output", [&] {
      const std::string &directory = output.staging();
      for (const CsvTable &table : tables)
        report.files.push_back(write_csv(directory, table));
      const FieldOutputOptions options{scene.field_time_samples(), scene.output.vtk, scene.output.plots};
      Progress progress("output", scene.output.progress_every);
      for (std::size_t i = 0; i < fields.size(); ++i)
        {
          for (std::string &f : write_field(directory, i, fields[i], *discretisation, options))
            report.files.push_back(std::move(f));
          progress.update([&] {
            return std::to_string(i + 1) + " of " + std::to_string(fields.size()) + " fields written";
          });
        }
      if (!fields.empty())
        for (std::string &f : write_field_collection(directory, fields, scene.output.vtk))
          report.files.push_back(std::move(f));
    });
    if (scene.output.plots)
      timed(report, "plots", [&] {
        for (std::string &f : make_plots(scene, output.staging()))
          report.files.push_back(std::move(f));
      });
    report.files = output.commit(report.files);
    return report;
  }

  std::vector<std::string> make_plots(const Scene &scene, const std::string &directory)
  {
    std::ostringstream gap;
    gap.precision(17);
    gap << scene.contact.gap;
    const std::string log_path = directory + "/plots.log";
    const bool ok = run_program({NSM_PYTHON, NSM_PLOT_SCRIPT, directory, "--gap", gap.str()}, log_path);
    std::vector<std::string> files;
    std::string              last;
    std::ifstream            log(log_path);
    for (std::string line; std::getline(log, line); last = line)
      if (line.rfind("wrote ", 0) == 0)
        files.push_back(line.substr(6));
    // The log goes with the failed run's staging directory: its last line is kept.
    if (!ok)
      throw NumericalError("the plotting script failed: " + last);
    files.push_back(log_path);
    return files;
  }

  void print_report(const RunReport &report, std::ostream &out)
  {
    out << "Run summary\n";
    out << "  " << std::left << std::setw(24) << "stage" << std::right
        << std::setw(12) << "wall [s]" << std::setw(12) << "cpu [s]" << '\n';
    for (const StageTiming &s : report.stages)
      out << "  " << std::left << std::setw(24) << s.name << std::right
          << std::fixed << std::setprecision(4) << std::setw(12)
          << s.wall_seconds << std::setw(12) << s.cpu_seconds << '\n';
    out.unsetf(std::ios::fixed);
    out << std::setprecision(6);
    for (const std::string &note : report.notes)
      out << "  " << note << '\n';
    out << "  files written: " << (report.files.empty() ? "none" : "") << '\n';
    for (const std::string &f : report.files)
      out << "    " << f << '\n';
  }
} // namespace nsm
