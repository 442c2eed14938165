#include <nsm/continuation/forced_response.h>
#include <nsm/model/bar_model.h>
#include <nsm/model/damped_receptance.h>
#include <nsm/model/load_modes.h>
#include <nsm/output/forced_response_table.h>
#include <nsm/model/discretisation.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/model/receptance.h>
#include <nsm/model/spectrum.h>
#include <nsm/study/study_measures.h>
#include <nsm/verification/stage_runner.h>
#include <nsm/verification/time_verification.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace nsm
{
  namespace
  {
    /// max_j |w_h,j - w_j| / w_j over the exact frequencies w, or over as
    /// many as the mesh has modes (counted in `measured`).
    double spectrum_error(const Discretisation &d, const std::vector<double> &w, unsigned int &measured)
    {
      const ModalData h     = compute_spectrum(d, EndCondition::clamped_free, w.size(), false);
      double          error = 0;
      for (std::size_t j = 0; j < h.eigenvalues.size(); ++j)
        error = std::max(error, std::abs(std::sqrt(h.eigenvalues[j]) - w[j]) / w[j]);
      measured = h.eigenvalues.size();
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
    void backbone_errors(HarmonicBalance &hb, const StudyScene &row, const Backbone &backbone,
                         const RowReference &reference, RowMeasures &m)
    {
      std::vector<double> energy, force, fraction;
      const Scene &scene = row.scene;
      m.points.assign(row.study.backbone_omega_values.size(), std::nullopt);
      for (std::size_t i = 0; i < m.points.size(); ++i)
        try
          {
            const double        omega = row.study.backbone_omega_values[i];
            const BackbonePoint p     = solve_on_branch(hb, BranchParameters(scene), backbone, omega, true);
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
    void main_point_errors(const Backbone &backbone, const ExactBar &bar, const ContactLaw &law, RowMeasures &m)
    {
      std::vector<double> errors;
      for (const BackbonePoint &p : backbone.points)
        if (p.branch == Branch::main)
          if (const std::optional<double> e = bar.first_mode_energy(p.omega, law))
            errors.push_back(std::abs(p.measures.energy - *e) / *e);
      if (errors.empty())
        return;
      std::sort(errors.begin(), errors.end());
      m.main_error_median = errors[errors.size() / 2];
      m.main_error_q90    = errors[(errors.size() * 9) / 10];
    }

    /// The one-period defects of the main-branch points found at the
    /// Backbone omegas, integrated in time on the row's own FE model.
    /// The row's forced-response curves, one per Forcing/Amplitudes, and
    /// their peaks against its main branch: the largest |E / E_main - 1| and
    /// the phase lags' extremes.
    void forced_peaks(const Receptance &receptance, const Discretisation &discretisation, const Scene &scene,
                      const Backbone &backbone, RowMeasures &m)
    {
      const std::unique_ptr<LoadModes> load = drive_modes(receptance, discretisation, scene.forcing.shape);
      const DampedReceptance           damped(receptance, scene.damping, load.get());
      ForcedHarmonicBalance  forced(scene.harmonic_balance, scene.contact, damped);
      for (const double amplitude : scene.forcing.amplitudes)
        {
          const ForcedCurve curve = trace_forced_curve(forced, scene.harmonic_balance, scene.continuation,
                                                       scene.continuation.omega_min, scene.continuation.omega_max,
                                                       amplitude);
          if (curve.points.empty())
            continue;
          ++m.forced_curves;
          m.forced_curves_whole += curve.whole();
          // The Result line's verdict (forced_peak): a peak compared, or why not.
          const ForcedPeak peak = forced_peak(curve, &backbone);
          m.forced_peaks_at_range_end += peak.left_out == PeakLeftOut::at_range_end;
          m.forced_peaks_linear += peak.left_out == PeakLeftOut::linear;
          if (!peak.nonlinear_peak())
            continue;
          m.forced_peak_phase_min = std::min(m.forced_peak_phase_min.value_or(peak.phase), peak.phase);
          m.forced_peak_phase_max = std::max(m.forced_peak_phase_max.value_or(peak.phase), peak.phase);
          if (peak.distance)
            {
              ++m.forced_peaks_compared;
              m.forced_peak_distance_max =
                std::max(m.forced_peak_distance_max.value_or(0.0), std::abs(*peak.distance));
            }
        }
    }

    void time_defects(HarmonicBalance &hb, const Discretisation &d, const Scene &scene, RowMeasures &m)
    {
      std::vector<double> defects;
      for (const BackbonePoint &p : m.solved)
        {
          const PeriodicField field(hb, d, p);
          defects.push_back(verify_in_time(field, d, hb.law(), scene.output).time.periodicity_defect);
        }
      if (defects.empty())
        return;
      std::sort(defects.begin(), defects.end());
      m.time_defect_median = defects[defects.size() / 2];
      m.time_defect_max    = defects.back();
    }

    /// A continuation that stopped short (not at the range's end) strictly
    /// between the least and the largest Backbone omega.
    bool ended_inside(const BackboneEnd end, const std::optional<double> &reached, const std::vector<double> &omegas)
    {
      if (end == BackboneEnd::range || !reached || omegas.empty())
        return false;
      const auto [low, high] = std::minmax_element(omegas.begin(), omegas.end());
      return *reached > *low && *reached < *high;
    }
  } // namespace

  const std::vector<std::string> &study_stages()
  {
    static const std::vector<std::string> stages = {"mesh", "refinement", "spectrum", "receptance set-up",
                                                    "receptance", "harmonic balance", "energy solves",
                                                    "verification in time", "forced response"};
    return stages;
  }

  RowReference no_reference(const StudyScene &row)
  {
    RowReference         r;
    const std::size_t n = row.study.backbone_omega_values.size();
    r.energies.assign(n, std::nullopt);
    r.forces.assign(n, std::nullopt);
    r.fractions.assign(n, std::nullopt);
    return r;
  }

  RowReference reference_of(const StudyScene &row, const FineReference *fine)
  {
    const Scene                     &scene = row.scene;
    RowReference                     r     = no_reference(row);
    const StudyParameters        &study = row.study;
    const std::size_t             n     = study.backbone_omega_values.size();
    const std::optional<ExactBar> exact = ExactBar::of(BarModel(scene.bar));
    const ContactLaw              law(scene.contact);
    const bool                    mode = scene.continuation.mode == 1 && exact && exact->knows_first_mode(law);
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
              r.energies[i] = exact->first_mode_energy(study.backbone_omega_values[i], law);
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

  RowMeasures measure_run(const StudyScene &row, const RowReference &reference, StageRunner &stages)
  {
    const Scene   &scene = row.scene;
    RowMeasures    m;
    const BarModel bar(scene.bar);
    const bool     exact = reference.exact_bar;
    stages.mesh(bar, scene.discretisation, [&](const Discretisation &) { return scene.refinement_band(); });
    const Discretisation &d = stages.discretisation();
    m.dofs                  = d.n_dofs();
    m.cells                 = d.n_cells();
    const StudyParameters &study = row.study;
    if (study.spectrum_modes > 0 && exact)
      stages.timed("spectrum", [&] { m.spectrum_error = spectrum_error(d, reference.frequencies, m.spectrum_modes); });
    if (study.receptance_frequency_values.empty() && study.backbone_omega_values.empty())
      return m;
    stages.set_up_receptance(scene.receptance, scene.receptance_band());
    if (!study.receptance_frequency_values.empty() && exact)
      stages.timed("receptance", [&] {
        m.receptance_error = receptance_error(stages.receptance(), study.receptance_frequency_values, reference.gammas);
      });
    if (study.backbone_omega_values.empty())
      return m;
    const BranchParameters branch(scene);
    stages.harmonic_balance(scene.harmonic_balance, scene.contact, branch);
    HarmonicBalance &hb       = stages.hb();
    const Backbone  &backbone = stages.backbone();
    m.hb_unknowns             = hb.n_unknowns();
    m.time_samples            = hb.n_samples();
    m.main_points             = backbone.main_points();
    m.newton_iterations = backbone.newton_cost.converged_iterations + backbone.newton_cost.failed_iterations;
    m.failed_solves     = backbone.newton_cost.failed_solves;
    m.backbone_end      = backbone_end_name(backbone.end);
    m.omega_reached     = backbone.omega_reached(branch_direction(scene.contact));
    m.energy_error_partial = ended_inside(backbone.end, m.omega_reached, study.backbone_omega_values);
    if (reference.mode_bar)
      main_point_errors(backbone, *reference.mode_bar, ContactLaw(scene.contact), m);
    stages.timed("energy solves", [&] { backbone_errors(hb, row, backbone, reference, m); });
    if (study.verify_in_time)
      stages.timed("verification in time", [&] { time_defects(hb, d, scene, m); });
    if (study.forced_peaks)
      stages.timed("forced response", [&] { forced_peaks(stages.receptance(), d, scene, backbone, m); });
    return m;
  }
} // namespace nsm
