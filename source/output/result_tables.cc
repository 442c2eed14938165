#include <nsm/model/discretisation.h>
#include <nsm/model/receptance.h>
#include <nsm/model/automatic_range.h>
#include <nsm/output/result_tables.h>
#include <nsm/verification/orbit_refinement.h>
#include <nsm/model/spectrum.h>

#include <algorithm>
#include <cmath>

namespace nsm
{
  namespace
  {
    /// The verification columns of one row; empty cells for a point not verified.
    std::vector<CsvCell> verification_cells(const std::optional<PointVerification> &v)
    {
      if (!v)
        return std::vector<CsvCell>(7, std::string());
      return {v->verified ? "true" : "false", v->time.periodicity_defect, v->time.periodicity_defect_end,
              v->time.energy_drift, v->impulse_ratio, v->time.contact_fraction, v->time.energy_start};
    }

    /// The orbit columns of one row; empty cells for a point not refined or
    /// whose orbit was not found.
    std::vector<CsvCell> orbit_cells(const BackbonePoint &p, const std::optional<PeriodicOrbit> &o)
    {
      if (!o || !o->converged)
        return std::vector<CsvCell>(6, std::string());
      return {o->energy, hb_energy_error(p, *o), o->contact_fraction, o->floquet_max, o->stable ? "true" : "false",
              o->isolation};
    }
  } // namespace

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

  CsvTable receptance_table(const Receptance &receptance, const OutputParameters &output)
  {
    CsvTable table{"receptance.csv", {"omega", "gamma", "dgamma_domega2"}, {}};
    for (const double w : output.receptance_frequencies)
      {
        const ReceptanceValue v = receptance(w);
        table.rows.push_back({w, v.gamma, v.dgamma_domega2});
      }
    return table;
  }

  CsvTable backbone_table(const Backbone &backbone, const std::vector<double> &estimates,
                          const Verifications &verifications, const RefinedOrbits &orbits,
                          const std::vector<double> &bar_amplitudes)
  {
    CsvTable table{"backbone.csv",
                   {"segment", "Omega", "energy", "energy_spread", "max_contact_force", "max_contact_displacement",
                    "contact_fraction", "newton_iterations", "residual", "branch",
                    "resonance_mode", "resonance_harmonic", "leading_harmonic"},
                   {}};
    if (!estimates.empty())
      table.columns.push_back("energy_error_estimate");
    if (!bar_amplitudes.empty())
      table.columns.push_back("max_displacement");
    if (!verifications.empty())
      for (const char *c : {"verified", "periodicity_defect", "periodicity_defect_end", "energy_drift",
                            "impulse_ratio", "verified_contact_fraction", "verified_energy"})
        table.columns.push_back(c);
    if (!orbits.empty())
      for (const char *c : {"orbit_energy", "hb_energy_error", "orbit_contact_fraction", "floquet_max", "stable",
                            "isolation"})
        table.columns.push_back(c);
    for (std::size_t i = 0; i < backbone.points.size(); ++i)
      {
        const BackbonePoint &p = backbone.points[i];
        table.rows.push_back({double(p.segment), p.omega, p.measures.energy,
                              p.measures.energy_spread, p.measures.max_contact_force,
                              p.measures.max_contact_displacement,
                              p.measures.contact_fraction, double(p.newton_iterations),
                              p.residual, branch_name(p.branch),
                              double(p.resonance.mode), double(p.resonance.harmonic),
                              double(p.measures.leading_harmonic)});
        if (!estimates.empty())
          table.rows.back().push_back(std::isfinite(estimates[i]) ? CsvCell(estimates[i]) : CsvCell(std::string()));
        if (!bar_amplitudes.empty())
          table.rows.back().push_back(bar_amplitudes[i]);
        if (!verifications.empty())
          for (CsvCell &cell : verification_cells(verifications[i]))
            table.rows.back().push_back(std::move(cell));
        if (!orbits.empty())
          for (CsvCell &cell : orbit_cells(p, orbits[i]))
            table.rows.back().push_back(std::move(cell));
      }
    return table;
  }

  CsvTable harmonics_table(HarmonicBalance &hb, const Backbone &backbone)
  {
    CsvTable table{"harmonics.csv", {"point", "Omega", "branch", "k", "is_sine", "force", "displacement"}, {}};
    for (std::size_t i = 0; i < backbone.points.size(); ++i)
      {
        const BackbonePoint &p = backbone.points[i];
        hb.set_omega(p.omega);
        const FourierCoefficients c = hb.coefficients(p.x);
        for (std::size_t j = 0; j < c.order.size(); ++j)
          table.rows.push_back({double(i), p.omega, branch_name(p.branch), double(c.order[j]), double(c.is_sine[j]),
                                c.force[j], c.displacement[j]});
      }
    return table;
  }

  CsvTable tongue_table(const Backbone &backbone)
  {
    CsvTable table{"tongues.csv",
                   {"mode", "harmonic", "omega_resonance", "foot_omega_begin",
                    "foot_omega_end", "max_energy", "points", "kind"},
                   {}};
    for (const Tongue &t : backbone.tongues)
      table.rows.push_back({double(t.resonance.mode), double(t.resonance.harmonic),
                            t.resonance.omega, t.foot_begin, t.foot_end, t.max_energy,
                            double(t.points), resonance_kind(t.resonance)});
    return table;
  }

  CsvTable grazing_table(const Discretisation &d, const unsigned int mode, const ContactParameters &contact)
  {
    const ModeFrequencies f = mode_frequencies(d, mode, contact);
    return {"grazing.csv",
            {"mode", "omega", "energy", "accumulation_omega"},
            {{double(mode), f.free, f.grazing_energy, d.bar().accumulation_frequency(mode)}}};
  }

  CsvTable resonance_table(const std::vector<InternalResonance> &resonances)
  {
    CsvTable table{"resonances.csv", {"omega", "mode", "harmonic"}, {}};
    for (const InternalResonance &r : resonances)
      table.rows.push_back({r.omega, double(r.mode), double(r.harmonic)});
    return table;
  }
} // namespace nsm
