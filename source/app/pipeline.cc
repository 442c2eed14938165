#include <nsm/model/automatic_range.h>
#include <nsm/model/band_cells.h>
#include <nsm/model/bar_model.h>
#include <nsm/continuation/accumulation_tongue.h>
#include <nsm/continuation/checkpoint.h>
#include <nsm/continuation/continuation.h>
#include <nsm/continuation/main_branch.h>
#include <nsm/output/field_output.h>
#include <nsm/verification/fields.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/output/output_directory.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/memory_estimate.h>
#include <nsm/app/pipeline.h>
#include <nsm/app/run_record.h>
#include <nsm/app/run_result.h>
#include <nsm/output/plots.h>
#include <nsm/base/checkpoint_reader.h>
#include <nsm/base/interruption.h>
#include <nsm/base/text.h>
#include <nsm/base/progress.h>
#include <nsm/model/receptance.h>
#include <nsm/output/result_tables.h>
#include <nsm/scene/scene_entries.h>
#include <nsm/verification/doubled_harmonics.h>
#include <nsm/verification/harmonics_estimate.h>
#include <nsm/verification/orbit_refinement.h>
#include <nsm/verification/space_estimate.h>
#include <nsm/verification/stage_runner.h>
#include <nsm/output/forced_response_table.h>
#include <nsm/model/damped_receptance.h>
#include <nsm/model/load_modes.h>
#include <nsm/output/floquet_report.h>
#include <nsm/verification/time_verification.h>
#include <nsm/verification/refinement_checkpoint.h>
#include <nsm/verification/verification_checkpoint.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

namespace nsm
{
  namespace
  {
    std::string describe(const Discretisation &d)
    {
      std::ostringstream s;
      s << "discretisation: FE_Q(" << d.fe().degree << "), " << d.n_cells()
        << " cells, " << d.n_dofs() << " DoFs, h in [" << d.min_cell_size()
        << ", " << d.max_cell_size() << "]";
      return s.str();
    }

    /// A field asked for at an Omega where the computed branch is a tongue or
    /// another family.
    std::string off_main_field_note(const BackbonePoint &p)
    {
      std::ostringstream s;
      s.precision(6);
      s << "field at Omega = " << p.omega;
      if (p.branch == Branch::other && !moves_at_omega(p))
        s << " is on another family, not on the main branch (harmonic " << p.measures.leading_harmonic
          << ", not the fundamental, leads its contact end's swing)";
      else if (p.branch == Branch::other)
        s << " is on another family, not on the main branch (contact fraction " << p.measures.contact_fraction
          << ", below the mode's before it by more than Main contact drop)";
      else
        {
          s << " is on a resonance tongue";
          if (p.resonance.harmonic > 0)
            s << " of w_" << p.resonance.mode << " / " << p.resonance.harmonic << " = " << p.resonance.omega;
          s << ", not on the main branch (energy " << p.measures.energy
            << ", above the main branch beyond it by more than Tongue share)";
        }
      return s.str();
    }

    /// A field is solved on the computed branch; beyond its first or last
    /// point (before grazing, or past where it was lost) Newton could only
    /// land on something that was not traced. Empty if omega is on it, else
    /// why not.
    std::string off_branch(const Backbone &backbone, const double omega)
    {
      const double low = *backbone.omega_reached(-1), high = *backbone.omega_reached(1);
      if (omega >= low && omega <= high)
        return "";
      std::ostringstream s;
      s.precision(8);
      s << "beyond the computed branch, " << low << " to " << high << " (how it ended: "
        << backbone_end_name(backbone.end) << ")";
      return s.str();
    }

    /// The summary line of a field's verification.
    std::string field_verification(const PeriodicField &field, const Discretisation &discretisation,
                                   const ContactLaw &law, const OutputParameters &output)
    {
      const PointVerification v = verify_in_time(field, discretisation, law, output);
      std::ostringstream      s;
      s.precision(6);
      s << "field at Omega = " << field.omega() << " verified in time: one-period defect / g0 "
        << v.time.periodicity_defect << " (" << (v.verified ? "periodic" : "NOT periodic")
        << " to Verify tolerance), after " << output.verify_periods << " periods "
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
      // A median needs three points at least: fewer are listed.
      if (defects.size() >= 3)
        s << "; one-period defect / g0: median " << defects[defects.size() / 2] << ", max " << defects.back();
      for (std::size_t i = 0; defects.size() < 3 && i < defects.size(); ++i)
        s << (i == 0 ? "; one-period defect / g0 of each: " : ", ") << defects[i];
      return s.str();
    }

    /// "resumed from ..." for the summary.
    std::string resume_note(const ContinuationCheckpoint &c)
    {
      std::ostringstream s;
      s.precision(8);
      s << "resumed from " << checkpoint_file << ": " << c.points.size() << " points kept, "
        << (c.complete ? "the continuation had ended" :
            c.step     ? "going on from Omega = " :
                         "the interrupted arclength segment traced again from Omega = ");
      if (!c.complete)
        s << c.points.back().omega;
      return s.str();
    }

    /// The stages of one run, in order: those a study's row runs too (the
    /// mesh, the receptance, the harmonic balance: StageRunner), and the
    /// run's own. Each is timed on the runner's clock, and adds its tables,
    /// fields and notes to the report or the output stage.
    class SceneRun
    {
    public:
      /// With `resume`, the continuation and the verification go on from the
      /// checkpoints in Output/Directory.
      SceneRun(const Scene &scene, RunReport &report, const bool resume)
        : scene_(scene)
        , report_(report)
        , resume_(resume)
      {}

      void mesh(const BarModel &bar)
      {
        bar_ = &bar;
        if (scene_.discretisation.cells == 0)
          timed("cells for the band", [&] {
            const BandCells choice       = cells_for_band(bar, scene_);
            scene_.discretisation.cells = choice.cells;
            scene_.discretisation.check_cells();
            scene_.check_consistency(false);
            report_.notes.push_back(describe(choice, scene_.discretisation.degree));
          });
        // An automatic range is read off the initial mesh for the band of
        // an adaptive refinement, and again off the refined one for the run.
        const auto band = [&](const Discretisation &initial_mesh) {
          Scene initial = scene_;
          if (resolves_range())
            resolve_automatic_range(initial.continuation, initial.contact, initial.output.fields_at,
                                    initial_mesh);
          return initial.refinement_band();
        };
        for (std::string &note : stages_.mesh(bar, scene_.discretisation, band, scene_.output.progress_every))
          report_.notes.push_back(std::move(note));
        report_.notes.push_back(describe(discretisation()));
        if (resolves_range())
          for (std::string &note : resolve_automatic_range(scene_.continuation, scene_.contact,
                                                           scene_.output.fields_at, discretisation()))
            report_.notes.push_back(std::move(note));
      }

      /// Every stage run, in order, with its wall and CPU time.
      std::vector<StageTiming> timings() const { return stages_.timings(); }

      /// What the continuation reads of the scene (its automatic range set).
      BranchParameters branch() const { return BranchParameters(scene_); }

      /// The run follows the branch: for the backbone or for fields.
      bool traces_branch() const { return (scene_.output.backbone || scene_.output.fields()) && !backbone_failed_; }

      /// Whether the backbone's continuation failed beside forced curves
      /// (harmonic_balance_beside_forcing).
      bool backbone_failed() const { return backbone_failed_; }

      /// The run uses the Omega range: for the branch or the forced curves.
      bool resolves_range() const { return traces_branch() || scene_.forcing.enabled(); }

      void spectrum()
      {
        // An adaptive mesh's modes are known once it is made (Scene checks the others).
        const unsigned int modes = discretisation().n_dofs() - 2;
        if (scene_.output.spectrum_modes > modes)
          throw InputError("parameter 'Output/Spectrum modes' = " + std::to_string(scene_.output.spectrum_modes) +
                           " is out of range: allowed an integer in [0, " + std::to_string(modes) +
                           "], the clamped-clamped modes of the adaptive mesh");
        timed("spectrum", [&] {
          tables_.push_back(spectrum_table(discretisation(), scene_.output.spectrum_modes));
        });
      }

      void set_up_receptance() { stages_.set_up_receptance(scene_.receptance, scene_.receptance_band()); }

      void receptance()
      {
        timed("receptance", [&] { tables_.push_back(receptance_table(stages_.receptance(), scene_.output)); });
      }

      void harmonic_balance()
      {
        const auto resume = [&](HarmonicBalance &hb) {
          ContinuationCheckpoint checkpoint =
            read_checkpoint(scene_.output.directory + "/" + checkpoint_file, branch(), hb);
          companions_ = checkpoint.companions;
          check_companion(verification_checkpoint_file);
          check_companion(refinement_checkpoint_file);
          report_.notes.push_back(resume_note(checkpoint));
          return checkpoint;
        };
        stages_.harmonic_balance(scene_.harmonic_balance, scene_.contact, branch(),
                                 resume_ ? StageRunner::Resume(resume) : StageRunner::Resume());
        if (!hb().law().rigid())
          report_.notes.push_back("compliant wall: " + hb().law().stiffness_note(hb().receptance()(0.0).gamma));
        report_.notes.push_back(backbone_note());
        report_.events = backbone().events;
        if (const std::string why =
              range_without_points(backbone(), scene_.continuation, branch_direction(scene_.contact));
            !why.empty())
          throw InputError(why);
        report_.result = backbone_result(backbone(), *bar_, scene_.contact, scene_.continuation);
      }

      /// The backbone of a scene that also drives the bar: a numerical
      /// failure of its continuation (a grazing start that converges nowhere)
      /// is recorded, the run exits 3 after writing the rest, and the forced
      /// curves, which do not need it, are traced without it.
      void harmonic_balance_beside_forcing()
      {
        try
          {
            harmonic_balance();
          }
        catch (const RangeOutsideBranch &e)
          {
            throw InputError(std::string(e.what()) +
                             "; the forced curves need no backbone: with Output/Backbone = false they are traced "
                             "over this range alone");
          }
        catch (const NumericalError &e)
          {
            backbone_failed_ = true;
            record_failure(std::string("the backbone (its points, checks, tables and fields; the forced curves "
                                       "are traced without it): ") + e.what());
          }
      }

      /// A request the run could not meet: it writes the rest and exits 3,
      /// naming each (stderr, summary, manifest).
      void record_failure(const std::string &what)
      {
        report_.failure += (report_.failure.empty() ? "" : "; ") + what;
      }

      /// A curve asked for that has no point is a failure.
      void record_empty(const std::vector<ForcedCurve> &curves)
      {
        for (const ForcedCurve &curve : curves)
          if (curve.points.empty())
            record_failure(curve_name(curve) + ": " + no_point(curve));
      }

      /// Writes the continuation's checkpoint and the points verified and refined so far
      /// (a stop signal ended the run).
      /// The verification's and the refinement's checkpoints are written
      /// first: the continuation's records their hashes (its companions),
      /// under its model fingerprint, so that neither is taken edited.
      void write_checkpoints(const std::string &directory)
      {
        CheckpointCompanions companions;
        const auto companion = [&](const char *file, auto &&write) {
          std::ostringstream text;
          write(text);
          companions[file] = fnv1a(text.str().data(), text.str().size());
          report_.files.push_back(
            write_checksummed(directory + "/" + file, [&](std::ostream &out) { out << text.str(); }));
        };
        if (present(verifications_) > 0)
          companion(verification_checkpoint_file, [&](std::ostream &out) {
            write_verification_checkpoint(out, backbone(), verifications_, scene_.output);
          });
        if (present(orbits_) > 0)
          companion(refinement_checkpoint_file, [&](std::ostream &out) {
            write_refinement_checkpoint(out, backbone(), orbits_, scene_.output);
          });
        if ((report_.resumable = backbone().checkpoint != nullptr))
          report_.files.push_back(write_checksummed(directory + "/" + checkpoint_file, [&](std::ostream &out) {
            write_checkpoint(out, *backbone().checkpoint, scene_.computation_entries, hb(), companions);
          }));
      }

      /// A companion checkpoint (verification.resume, refinement.resume) is
      /// read only if the continuation's checkpoint recorded its text.
      void check_companion(const char *file) const
      {
        const std::string path = scene_.output.directory + "/" + file;
        if (!std::ifstream(path).good())
          return;
        const auto recorded = companions_.find(file);
        if (recorded == companions_.end() || recorded->second != text_hash(path))
          throw InputError("command line: --resume: '" + printable(path) + "' is not the one the interrupted run "
                           "wrote with its " + checkpoint_file + " (edited, or another run's): run the scene "
                           "without --resume");
      }

      /// The points a stage holds (computed, or kept from a checkpoint).
      template <typename T>
      static std::size_t present(const std::vector<std::optional<T>> &points)
      {
        return std::count_if(points.begin(), points.end(), [](const auto &p) { return p.has_value(); });
      }

      /// "resumed STAGE: N points from FILE (kept only with the same SETTINGS)".
      void note_resumed(const std::string &stage, const std::size_t kept, const std::string &file,
                        const std::string &settings)
      {
        report_.notes.push_back("resumed " + stage + ": " + std::to_string(kept) + " points from " + file +
                                " (kept only with the same " + settings + ")");
      }

      /// After a per-point stage's summary line: where a stop signal ended it.
      void note_stop(const std::string &verb)
      {
        if (const int signal = point_stop_signal(); signal != 0)
          {
            cut_short_ = true;
            report_.result.back() += std::string(" (stopped by ") + stop_signal_name(signal) +
                                     " before the other points: --resume " + verb + " them)";
          }
      }

      /// Each point's energy error against the same motion with half the
      /// harmonics (Output/Error estimate), summarised over the main points.
      void estimate_errors()
      {
        EstimateSummary summary;
        timed("error estimate", [&] {
          Progress progress("error estimate", scene_.output.progress_every);
          std::vector<bool> elsewhere;
          estimates_ = estimate_energy_errors(hb(), branch(), backbone(), progress, &elsewhere);
          // The estimates show where the truncation sets the climb into the
          // accumulation point: the Result block's lines follow its labels.
          // (Not after a stop: the points left have no estimate yet.)
          if (point_stop_signal() == 0 && name_accumulation_tongue(backbone(), estimates_, branch()) > 0)
            relabelled();
          summary    = summarise_estimates(backbone(), estimates_, elsewhere);
          report_.result.push_back(estimate_summary(summary, scene_.harmonic_balance.harmonics));
          note_stop("estimates");
        });
        if (point_stop_signal() != 0)
          {
            cut_short_ = true; // the checks are left out
            return;
          }
        timed("estimate check with 2M", [&] {
          const DoubledHarmonicsCheck check = check_with_doubled_harmonics(
            discretisation(), scene_.receptance, branch(), backbone(), estimates_, used_band());
          report_.result.push_back(doubled_harmonics_summary(check));
          if (const std::string warning = doubled_harmonics_warning(check); !warning.empty())
            report_.result.push_back("warning: " + warning);
          note_stop("checks");
        });
        if (point_stop_signal() != 0)
          {
            cut_short_ = true; // the band check is left out
            return;
          }
        timed("band check", [&] {
          const SpaceVerdict verdict =
            space_verdict(space_->band(discretisation(), used_band()), space_->energy_changes(backbone()),
                          summary.estimated > 0 ? summary.median : std::nan(""), discretisation());
          report_.result.push_back(verdict.summary);
          if (!verdict.warning.empty())
            report_.result.push_back("warning: " + verdict.warning);
        });
      }

      /// Whether a stop signal left part of the work out: the continuation,
      /// or a per-point stage, ended before its last point.
      bool cut_short() const { return cut_short_ || backbone().end == BackboneEnd::interrupted; }

      /// The forced work (curves, verification, curves in F) a stop signal left out, a line per stage.
      const std::vector<std::string> &forced_left_out() const { return forced_left_out_; }

      /// The band the backbone used: M times its highest Omega (its points
      /// lie in the range; M Omega max if it has none).
      double used_band() const
      {
        double omega = 0;
        for (const BackbonePoint &p : backbone().points)
          omega = std::max(omega, p.omega);
        return scene_.harmonic_balance.harmonics * (omega > 0 ? omega : scene_.continuation.omega_max);
      }

      /// The mesh with every cell halved that the band check compares
      /// against, made before the harmonic balance.
      void set_up_band_check()
      {
        timed("band check set-up", [&] {
          space_ = std::make_unique<SpaceReference>(discretisation(), scene_.receptance, branch());
        });
      }

      void verify_in_time()
      {
        timed("verification in time", [&] {
          Progress progress("verification in time", scene_.output.progress_every);
          Verifications known;
          if (resume_)
            {
              known = read_verification_checkpoint(scene_.output.directory + "/" + verification_checkpoint_file,
                                                   backbone(), scene_.output);
              note_resumed("verification in time", present(known), verification_checkpoint_file,
                           "Verify steps and periods");
            }
          verifications_ = verify_backbone(hb(), discretisation(), backbone(), scene_.output, progress, known);
          report_.result.push_back(verification_summary(verifications_, scene_));
          note_stop("verifies");
        });
      }

      /// The refinement's dense modes, checked before any other work.
      void check_refinement_size() const
      {
        if (discretisation().n_dofs() > max_refined_dofs)
          throw InputError("parameter 'Output/Refine in time' = true is out of range: allowed for at most " +
                           std::to_string(max_refined_dofs) + " DoFs (dense modes); the mesh has " +
                           std::to_string(discretisation().n_dofs()));
      }

      void refine_in_time()
      {
        timed("refinement in time", [&] {
          Progress progress("refinement in time", scene_.output.progress_every);
          std::vector<std::optional<PeriodicOrbit>> known;
          if (resume_)
            {
              known = read_refinement_checkpoint(scene_.output.directory + "/" + refinement_checkpoint_file,
                                                 backbone(), scene_.output, discretisation().n_dofs());
              note_resumed("refinement in time", present(known), refinement_checkpoint_file, "Refine every");
            }
          orbits_ = refine_backbone(hb(), discretisation(), backbone(), scene_.output, progress, std::move(known));
          report_.result.push_back(refinement_summary(backbone(), orbits_, scene_.output));
          note_stop("shoots");
        });
      }

      /// The largest |u| over the bar at each backbone point (Output/Bar
      /// amplitude), from the point's field.
      void bar_amplitudes()
      {
        timed("bar amplitude", [&] {
          Progress progress("bar amplitude", scene_.output.progress_every);
          for (std::size_t i = 0; i < backbone().points.size() && point_stop_signal() == 0; ++i)
            {
              const PeriodicField field(hb(), discretisation(), backbone().points[i]);
              bar_amplitudes_.push_back(field.max_displacement(scene_.field_time_samples()));
              progress.update([&] { return "point " + std::to_string(i + 1) + " of " +
                                           std::to_string(backbone().points.size()); });
            }
          // A stop leaves the column out rather than part-filled.
          if (bar_amplitudes_.size() < backbone().points.size())
            {
              bar_amplitudes_.clear();
              cut_short_ = true;
            }
        });
      }

      void backbone_tables()
      {
        tables_.push_back(backbone_table(backbone(), estimates_, verifications_, orbits_, bar_amplitudes_));
        if (scene_.output.harmonics_table)
          tables_.push_back(harmonics_table(hb(), backbone()));
        tables_.push_back(tongue_table(backbone()));
        tables_.push_back(grazing_table(discretisation(), scene_.continuation.mode, scene_.contact));
        tables_.push_back(resonance_table(stages_.resonances()));
      }

      /// One curve per Forcing/Amplitudes, frc.csv, and the Result lines
      /// (the peaks against the backbone's main branch where it was traced).
      void forced_response()
      {
        timed("forced response", [&] {
          const std::unique_ptr<LoadModes> load =
            drive_modes(stages_.receptance(), discretisation(), scene_.forcing.shape);
          const DampedReceptance   damped(stages_.receptance(), scene_.damping, load.get());
          ForcedHarmonicBalance   forced(scene_.harmonic_balance, scene_.contact, damped);
          std::vector<ForcedCurve> curves;
          Progress                 progress("forced response", scene_.output.progress_every);
          // A stop signal ends the stage between curves (each takes a second
          // or so): the curves traced are written.
          for (const double amplitude : scene_.forcing.amplitudes)
            {
              if (point_stop_signal() != 0)
                {
                  forced_left_out_.push_back("forced response's curves from F = " + significant(amplitude, 4) + " on");
                  break;
                }
              curves.push_back(trace_forced_curve(forced, scene_.harmonic_balance, scene_.continuation,
                                                  scene_.continuation.omega_min, scene_.continuation.omega_max,
                                                  amplitude));
              progress.update([&] {
                return "curve F = " + significant(amplitude, 4) + " traced, " +
                       std::to_string(curves.back().points.size()) + " points";
              });
            }
          record_empty(curves);
          const ForcedVerifications verifications = verify_forced_curves(forced, curves);
          if (!curves.empty())
            tables_.push_back(forced_response_table(curves, verifications));
          if (!verifications.empty())
            report_.result.push_back(forced_verification_summary(curves, verifications));
          if (const std::string line = floquet_summary(curves, verifications); !line.empty())
            report_.result.push_back(line);
          for (std::string &event : floquet_events(curves, verifications))
            report_.events.push_back(std::move(event));
          if (load)
            report_.result.push_back("forced response: the drive F cos(W t) acts per unit length along the whole bar "
                                     "(Forcing/Shape = uniform): each F below is a force per length");
          for (std::string &line : forced_response_summary(curves, traces_branch() ? &backbone() : nullptr))
            report_.result.push_back(std::move(line));
          std::vector<ForcedCurve> force_curves = force_response(forced);
          record_empty(force_curves);
          if (!force_curves.empty())
            tables_.push_back(forced_response_table(force_curves, {}, "force_response.csv"));
          for (std::string &line : force_response_summary(force_curves))
            report_.result.push_back(std::move(line));
          for (const std::vector<ForcedCurve> *traced : {&curves, &force_curves})
            for (std::string &event : forced_response_events(*traced))
              report_.events.push_back(std::move(event));
        });
      }

      /// One curve in F per Forcing/Omegas, over [0, Amplitude max]; a stop
      /// signal ends them between curves, as the frequency-response curves.
      std::vector<ForcedCurve> force_response(ForcedHarmonicBalance &forced)
      {
        std::vector<ForcedCurve> curves;
        Progress                 progress("forced response", scene_.output.progress_every);
        for (const double omega : scene_.forcing.omegas)
          {
            if (point_stop_signal() != 0)
              {
                forced_left_out_.push_back("force response's curves from Omega = " + significant(omega, 6) + " on");
                break;
              }
            curves.push_back(trace_force_curve(forced, scene_.harmonic_balance, scene_.continuation, omega,
                                               scene_.forcing.force_range()));
            progress.update([&] {
              return "curve in F at Omega " + significant(omega, 6) + " traced, " +
                     std::to_string(curves.back().points.size()) + " points";
            });
          }
        return curves;
      }

      /// Every Forcing/Verify every-th point of each curve integrated in
      /// time; empty without it. A stop signal ends it at a point, and the
      /// summary says what it left out.
      ForcedVerifications verify_forced_curves(ForcedHarmonicBalance &forced, const std::vector<ForcedCurve> &curves)
      {
        const unsigned int every = scene_.forcing.verify_every;
        ForcedVerifications verifications;
        if (every == 0)
          return verifications;
        Progress     progress("forced response's verification in time", scene_.output.progress_every);
        unsigned int verified = 0;
        // One entry per point of every curve, so that a stop signal leaves
        // the curves after it unverified, not missing.
        for (const ForcedCurve &curve : curves)
          verifications.emplace_back(curve.points.size());
        for (std::size_t c = 0; c < curves.size(); ++c)
          {
            const ForcedCurve &curve = curves[c];
            forced.set_forcing(curve.forcing);
            for (std::size_t i = 0; i < curve.points.size(); i += every)
              {
                // The static response (Omega = 0, a curve from the range's
                // default start) has no period to integrate over.
                if (!(curve.points[i].omega > 0))
                  continue;
                if (point_stop_signal() != 0)
                  {
                    forced_left_out_.push_back("the forced response's verification in time from F = " +
                                               significant(curve.forcing, 4) + ", Omega = " +
                                               significant(curve.points[i].omega, 6) + " on");
                    return verifications;
                  }
                forced.set_omega(curve.points[i].omega);
                const unsigned int periods =
                  scene_.forcing.verify_periods > 0 ?
                    scene_.forcing.verify_periods :
                    steady_state_periods(forced.receptance(), curve.points[i].omega, ForcingParameters::max_verify_periods);
                ForcedVerification &v = verifications[c][i].emplace(
                  verify_forced_point(forced, curve.points[i].x, scene_.output.verify_steps, periods));
                // The integration's end is a start for the shooting where
                // the point is stable by the fold test and the integration
                // stayed on it: an integration settles only on an attracting
                // orbit, which beside an unstable point is another one.
                const bool settled_on_it =
                  curve.points[i].stable && stays_on(v, curve.points[i].measures.tip_amplitude);
                if (scene_.forcing.floquet)
                  v.floquet = floquet_multipliers(forced, curve.points[i].x, scene_.output.verify_steps,
                                                  settled_on_it ? v.settled : std::vector<double>());
                ++verified;
                progress.update([&] {
                  return std::to_string(verified) + " points verified (F = " + significant(curve.forcing, 4) + ", Omega " +
                         significant(curve.points[i].omega, 6) + ", " + std::to_string(periods) + " periods)";
                });
              }
          }
        return verifications;
      }

      void fields()
      {
        timed("fields", [&] {
          const auto &o = scene_.output;
          Progress    progress("fields", o.progress_every);
          const auto  report_count = [&] { return std::to_string(fields_.size()) + " fields"; };
          for (const double omega : o.fields_at)
            {
              const std::optional<BackbonePoint> point = field_point(omega);
              if (!point)
                continue;
              fields_.emplace_back(hb(), discretisation(), *point);
              if (const BackbonePoint &p = fields_.back().point(); p.branch != Branch::main)
                report_.result.push_back(off_main_field_note(p)); // a field's family is part of the result
              if (o.verify_in_time)
                report_.notes.push_back(field_verification(fields_.back(), discretisation(), hb().law(), scene_.output));
              if (o.refine_in_time)
                report_.notes.push_back(field_refinement(fields_.back()));
              progress.update(report_count);
            }
          for (std::size_t i = 0; o.fields_every > 0 && i < backbone().points.size(); i += o.fields_every)
            {
              fields_.emplace_back(hb(), discretisation(), backbone().points[i]);
              progress.update(report_count);
            }
        });
      }

      /// Writes the tables and fields into the directory's staging area.
      void write(const std::string &directory)
      {
        timed("output", [&] {
          for (const CsvTable &table : tables_)
            report_.files.push_back(write_csv(directory, table));
          if (!report_.events.empty())
            report_.files.push_back(write_atomically(directory + "/continuation.log", [&](std::ostream &out) {
              for (const std::string &event : report_.events)
                out << event << '\n';
            }));
          const FieldOutputOptions options{scene_.field_time_samples(), scene_.output.vtk, scene_.output.plots,
                                           scene_.output.vtk_time_over_period};
          Progress progress("output", scene_.output.progress_every);
          for (std::size_t i = 0; i < fields_.size(); ++i)
            {
              for (std::string &f : write_field(directory, i, fields_[i], discretisation(), options))
                report_.files.push_back(std::move(f));
              progress.update([&] {
                return std::to_string(i + 1) + " of " + std::to_string(fields_.size()) + " fields written";
              });
            }
          if (!fields_.empty())
            for (std::string &f : write_field_collection(directory, fields_, scene_.output.vtk))
              report_.files.push_back(std::move(f));
        });
      }

      /// Draws the plots; returns the signal that ended them, 0 if none. A
      /// failure of the plotting environment is noted (report_.plot_failure):
      /// the files computed are kept either way.
      int plots(const std::string &directory)
      {
        PlotResult        plots;
        const std::string caption = "scene " + scene_.origin + ": FE_Q(" +
                                    std::to_string(discretisation().fe().degree) + ") x " +
                                    std::to_string(discretisation().n_cells()) + " cells, M = " +
                                    std::to_string(scene_.harmonic_balance.harmonics) +
                                    (scene_.contact.wall == Wall::compliant ?
                                       ", compliant wall k = " + scene_entries::format_value(scene_.contact.stiffness) :
                                       "");
        timed("plots", [&] { plots = make_plots(scene_.contact, directory, caption, scene_.output.directory); });
        for (std::string &f : plots.files)
          report_.files.push_back(std::move(f));
        if (!plots.failure.empty() && plots.stopped_by == 0)
          report_.plot_failure = plots.failure;
        return plots.stopped_by;
      }

    private:
      template <typename Work>
      void timed(const std::string &name, Work &&work)
      {
        stages_.timed(name, std::forward<Work>(work));
      }

      Discretisation        &discretisation() { return stages_.discretisation(); }
      const Discretisation  &discretisation() const { return stages_.discretisation(); }
      HarmonicBalance       &hb() { return stages_.hb(); }
      const HarmonicBalance &hb() const { return stages_.hb(); }
      Backbone              &backbone() { return stages_.backbone(); }
      const Backbone        &backbone() const { return stages_.backbone(); }

      /// The point of a field at omega: solved on the branch, or else (off
      /// the computed branch, or no converged solution there) the nearest
      /// main point within Continuation/Search reach.
      std::optional<BackbonePoint> field_point(const double omega)
      {
        std::string why = off_branch(backbone(), omega);
        if (!why.empty())
          return nearest_main_point(omega, why);
        try
          {
            return solve_on_branch(hb(), branch(), backbone(), omega);
          }
        catch (const NumericalError &e)
          {
            return nearest_main_point(omega, e.what());
          }
      }

      /// The main point nearest omega within Continuation/Search reach, said
      /// in a note; none if there is none within reach: the failure is
      /// recorded (the run exits 3 after writing the rest), naming the
      /// nearest main Omega on each side.
      std::optional<BackbonePoint> nearest_main_point(const double omega, const std::string &why)
      {
        const auto          &p       = backbone().points;
        const BackbonePoint *below   = nearest_on_side(p, omega, -1, true);
        const BackbonePoint *above   = nearest_on_side(p, omega, 1, true);
        const BackbonePoint *nearest = nearest_on_side(p, omega, 0, true);
        std::ostringstream s;
        s.precision(8);
        if (nearest && std::abs(nearest->omega - omega) <= scene_.continuation.search_reach)
          {
            s << "field at Omega = " << omega << " (Output/Fields at) moved to the nearest main point, Omega = "
              << nearest->omega << " (" << why << "; within Continuation/Search reach = "
              << scene_.continuation.search_reach << ")";
            report_.result.push_back(s.str());
            return *nearest;
          }
        s << "parameter 'Output/Fields at' = " << omega << ": " << why
          << ", and no main point within Continuation/Search reach = " << scene_.continuation.search_reach
          << "; nearest main points: " << (below ? std::to_string(below->omega) : std::string("none"))
          << " below, " << (above ? std::to_string(above->omega) : std::string("none")) << " above";
        record_failure(s.str());
        return std::nullopt;
      }

      /// The summary line of a field point's orbit.
      std::string field_refinement(const PeriodicField &field) const
      {
        const BackbonePoint &p     = field.point();
        const PeriodicOrbit  orbit = refine_point(field, discretisation(), hb().law(), scene_.output, {});
        std::ostringstream  s;
        s.precision(6);
        s << "field at Omega = " << p.omega << " refined in time: ";
        if (!orbit.converged)
          s << "no orbit found from it (residual " << orbit.residual << " after " << orbit.newton_steps
            << " Newton steps)";
        else
          s << "orbit energy " << orbit.energy << ", HB energy error " << hb_energy_error(p, orbit)
            << ", contact fraction " << orbit.contact_fraction << ", largest |Floquet multiplier| "
            << orbit.floquet_max << (orbit.stable ? " (stable)" : " (unstable)") << ", isolation "
            << orbit.isolation;
        return s.str();
      }

      /// After the labels changed (the climb's truncated top named): the
      /// backbone's note and the Result block's lines follow them.
      void relabelled()
      {
        for (std::string &note : report_.notes)
          if (note.rfind("backbone: ", 0) == 0)
            note = backbone_note();
        report_.result = backbone_result(backbone(), *bar_, scene_.contact, scene_.continuation);
      }

      std::string backbone_note() const
      {
        std::ostringstream s;
        const unsigned int other = backbone().points_on(Branch::other);
        s << "backbone: " << backbone().points.size() << " points (" << backbone().main_points() << " main, "
          << backbone().points.size() - backbone().main_points() - other << " on " << backbone().tongues.size()
          << " tongues, " << other << " on other families), " << backbone().leaps << " leaps, "
          << backbone().folds.size() << " folds, "
          << hb().n_unknowns() << " unknowns";
        for (const auto &[harmonics, points] : backbone().fewer_harmonics_traced)
          s << (&harmonics == &backbone().fewer_harmonics_traced.front().first ?
                  "; traced for guesses where a leap or gap found none: the branch with M = " :
                  ", with M = ")
            << harmonics << " (" << points << " points)";
        return s.str();
      }

      Scene                           scene_; ///< with its automatic range set (automatic_range.h)
      RunReport                      &report_;
      const bool                      resume_; ///< --resume: checkpoints are read
      const BarModel                 *bar_ = nullptr;
      StageRunner                     stages_; ///< the stages a study's row runs too, and the clock
      std::vector<CsvTable>           tables_;
      Verifications                   verifications_;
      RefinedOrbits                   orbits_;
      std::vector<double>             bar_amplitudes_;
      std::vector<double>             estimates_; ///< per point; empty without Output/Error estimate
      std::unique_ptr<SpaceReference> space_;     ///< the band check's model (Output/Error estimate)
      bool cut_short_ = false; ///< a stop signal ended a stage before its last point
      std::vector<std::string>        forced_left_out_; ///< the forced work a stop signal left out, per stage
      bool                            backbone_failed_ = false; ///< harmonic_balance_beside_forcing failed
      std::vector<PeriodicField>      fields_;
      CheckpointCompanions            companions_; ///< of the checkpoint resumed from
    };
  } // namespace

  namespace
  {
    /// The scene as read, parameters.prm, in the output folder: before the
    /// plots, which read the run's settings (the gap, the wall, the drive's
    /// shape) from it.
    void write_parameters(const Scene &scene, const OutputDirectory &output, RunReport &report)
    {
      if (!scene.parameter_file.empty())
        report.files.push_back(write_atomically(output.staging() + "/parameters.prm", [&](std::ostream &out) {
          out << scene.parameter_file;
        }));
    }

    /// The run's summary.txt in its output folder: the record's header,
    /// then the summary as printed, with the continuation's events and every
    /// file, this one included, at its final path.
    void write_record(const std::string &command_line, const OutputDirectory &output, RunReport &report)
    {
      const std::string summary = output.staging() + "/summary.txt";
      report.files.push_back(summary);
      RunReport shown = report;
      shown.files     = output.final_paths(report.files);
      write_summary(summary, command_line, shown);
    }
  } // namespace

  namespace
  {
    /// The earlier output in `directory` (its manifest present): the command
    /// line its summary.txt records ("a run" if none); "" if it holds none.
    std::string earlier_output(const std::string &directory)
    {
      if (!std::ifstream(directory + "/" + OutputDirectory::manifest).good())
        return "";
      std::ifstream summary(directory + "/summary.txt");
      std::string   first;
      const std::string command = "command: ";
      if (std::getline(summary, first) && first.compare(0, command.size(), command) == 0)
        return first;
      return "a run whose command is not recorded";
    }

    /// The scene file (canonical) whose default folder the run writes, or ""
    /// for an explicit Output/Directory; a resumed run keeps the one its
    /// output records. A run of an output's own record (DIR/parameters.prm)
    /// into DIR would replace the output it reruns: refused, naming --output.
    std::string default_folder_of(const Scene &scene, const bool resume)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      const fs::path  file = fs::canonical(scene.origin, error);
      if (error)
        return "";
      // A resumed output keeps the owner its manifest records.
      if (resume)
        return default_folder_owner(scene.output.directory);
      if (file.filename() == "parameters.prm" &&
          file.parent_path() == fs::weakly_canonical(scene.output.directory, error) && !error)
        throw InputError("parameter 'Output/Directory' = '" + printable(scene.output.directory) +
                         "' holds the output whose record is this scene, " + printable(scene.origin) +
                         ", which the run would replace: rerun it into another folder with --output DIR (so that "
                         "the two can be compared), or go on with a stopped run with nsm-bar " +
                         printable(scene.output.directory) + " --resume");
      return scene.output.directory_is_default ? file.string() : "";
    }
  } // namespace

  RunReport run_scene(const Scene &scene, const bool resume, const std::string &command_line)
  {
    const bool needs_spectrum   = scene.output.spectrum_modes > 0;
    const bool needs_receptance = !scene.output.receptance_frequencies.empty();
    const bool needs_fields     = scene.output.fields();
    const bool needs_backbone   = scene.output.backbone || needs_fields;
    RunReport  report;
    // The cross-section is checked even when nothing else is to be done.
    const BarModel bar(scene.bar);
    if (resume && !needs_backbone)
      throw InputError("command line: --resume goes on with a continuation, and the scene asks for no backbone "
                       "or field (Output/Backbone, Output/Fields at, Output/Fields every)");
    const bool needs_forced = scene.forcing.enabled();
    if (!needs_spectrum && !needs_receptance && !needs_backbone && !needs_forced)
      {
        report.notes.push_back("the scene requests no output: nothing to do");
        return report;
      }

    // Checked before any work: an unwritable directory is known now.
    const MemoryEstimate memory = estimated_memory(scene);
    check_memory(memory, scene.resources);
    if (!resume && std::ifstream(scene.output.directory + "/" + checkpoint_file).good())
      report.notes.push_back("Output/Directory held a stopped run's " + std::string(checkpoint_file) +
                             ": this run started again and replaces it (--resume goes on from one)");
    else if (!resume)
      if (const std::string earlier = earlier_output(scene.output.directory); !earlier.empty())
        report.notes.push_back("Output/Directory held an earlier run's output (" + earlier +
                               "): this run replaces it");
    OutputDirectory output(scene.output.directory, default_folder_of(scene, resume));
    report.notes.push_back(memory_note(memory, scene.resources));
    for (const std::string &line : scene.unused_entries())
      report.notes.push_back(line);
    SceneRun        run(scene, report, resume);
    run.mesh(bar);
    if (scene.output.refine_in_time)
      run.check_refinement_size();
    if (needs_spectrum)
      run.spectrum();
    if (needs_receptance || needs_backbone || needs_forced)
      run.set_up_receptance();
    if (needs_receptance)
      run.receptance();
    const bool estimates = scene.output.backbone && scene.output.error_estimate;
    if (estimates)
      run.set_up_band_check();
    if (needs_backbone && needs_forced)
      run.harmonic_balance_beside_forcing();
    else if (needs_backbone)
      run.harmonic_balance();
    const bool has_backbone = needs_backbone && !run.backbone_failed();
    // A stop asked for (SIGINT, SIGTERM) ends the continuation, the
    // verification or the refinement at its next point (the fields at the
    // end of their stage); the stages after it are left out, and what was
    // computed is written.
    std::vector<std::string> skipped;
    const auto               stage = [&](const bool wanted, const char *name, auto &&work) {
      if (!wanted)
        return;
      if (point_stop_signal() != 0)
        skipped.push_back(name);
      else
        work();
    };
    stage(estimates && has_backbone, "error estimate", [&] { run.estimate_errors(); });
    stage(scene.output.verify_in_time && has_backbone, "verification in time", [&] { run.verify_in_time(); });
    stage(scene.output.refine_in_time && has_backbone, "refinement in time", [&] { run.refine_in_time(); });
    stage(scene.output.bar_amplitude && has_backbone, "bar amplitude", [&] { run.bar_amplitudes(); });
    if (scene.output.backbone && has_backbone)
      run.backbone_tables();
    stage(needs_forced, "forced response", [&] { run.forced_response(); });
    skipped.insert(skipped.end(), run.forced_left_out().begin(), run.forced_left_out().end());
    stage(needs_fields && has_backbone, "fields", [&] { run.fields(); });
    run.write(output.staging());
    write_parameters(scene, output, report);
    // The plots are an output like the others, drawn also after a stop: a
    // stop while they are drawn ends them and keeps the rest; so does a
    // failure of the plotting environment (said in the summary, exit 5).
    if (scene.output.plots && run.plots(output.staging()) != 0)
      skipped.push_back("plots");
    std::vector<std::string> manifest_notes;
    const auto               note = [&](const std::string &text) {
      report.notes.insert(report.notes.begin(), text);
      manifest_notes.push_back(text);
    };
    // A stop that left nothing out (it came after the last point of every
    // stage that answers one) ends a complete run: exit 0, no checkpoint.
    const int stop = point_stop_signal();
    if (stop != 0 && skipped.empty() && !(needs_backbone && run.cut_short()))
      report.notes.push_back(std::string("a stop (") + stop_signal_name(stop) +
                             ") came after the last point of every stage, or in a stage's last curve (curves end "
                             "whole): the run is complete, nothing left out");
    else if ((report.stopped_by = stop) != 0)
      {
        std::string text = std::string("interrupted by ") + stop_signal_name(report.stopped_by) +
                           ": the output holds what was computed before";
        for (const std::string &s : skipped)
          text += (&s == &skipped.front() ? "; left out: " : "; ") + s;
        note(text);
        run.write_checkpoints(output.staging());
      }
    // A request the run could not meet (a field out of reach) is said in the
    // summary and the manifest too, not on stderr alone.
    if (!report.failure.empty())
      note("not written: " + report.failure);
    if (!report.plot_failure.empty())
      note("plots not drawn: " + report.plot_failure);
    report.stages = run.timings();
    write_record(command_line, output, report);
    report.files = output.commit(report.files, manifest_notes);
    return report;
  }

} // namespace nsm
