#include <nsm/base/text.h>
#include <nsm/output/forced_response_table.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace nsm
{
  namespace
  {
    /// The main branch's energy at omega, between the main points that
    /// bracket it (sorted by Omega); none outside them.
    std::optional<double> main_energy_at(const Backbone &backbone, const double omega)
    {
      std::vector<std::pair<double, double>> main;
      for (const BackbonePoint &p : backbone.points)
        if (p.branch == Branch::main)
          main.emplace_back(p.omega, p.measures.energy);
      std::sort(main.begin(), main.end());
      const auto after = std::lower_bound(main.begin(), main.end(), std::make_pair(omega, -HUGE_VAL));
      if (after == main.begin() || after == main.end())
        return std::nullopt;
      const auto &[w0, e0] = *(after - 1);
      const auto &[w1, e1] = *after;
      return w1 == w0 ? e0 : e0 + (e1 - e0) * (omega - w0) / (w1 - w0);
    }
  } // namespace

  CsvTable forced_response_table(const std::vector<ForcedCurve> &curves)
  {
    CsvTable table{"frc.csv",
                   {"forcing", "Omega", "energy", "tip_amplitude", "phase", "contact_fraction", "max_contact_force",
                    "input_power", "dissipated_power", "residual"},
                   {}};
    for (const ForcedCurve &curve : curves)
      for (const ForcedPoint &p : curve.points)
        {
          const ForcedMeasures &m = p.measures;
          table.rows.push_back({curve.forcing, p.omega, m.energy, m.tip_amplitude, m.phase, m.contact_fraction,
                                m.max_contact_force, m.input_power, m.dissipated_power, p.residual});
        }
    return table;
  }

  std::vector<std::string> forced_response_summary(const std::vector<ForcedCurve> &curves,
                                                   const Backbone                 *backbone)
  {
    std::vector<std::string> lines;
    for (const ForcedCurve &curve : curves)
      {
        std::string line = "forced response F = " + significant(curve.forcing, 4) + ": " +
                           std::to_string(curve.points.size()) + " points";
        if (curve.points.empty())
          {
            lines.push_back(line + " (the start did not converge)");
            continue;
          }
        const auto by_omega = [](const ForcedPoint &a, const ForcedPoint &b) { return a.omega < b.omega; };
        const auto [low, high] = std::minmax_element(curve.points.begin(), curve.points.end(), by_omega);
        line += " on [" + significant(low->omega, 6) + ", " + significant(high->omega, 6) + "]" +
                (curve.finished ? "" : ", stopped before the range's end (a step failed at Min step or Max steps ran out)");
        if (curve.rejected > 0)
          line += ", " + std::to_string(curve.rejected) + " steps above the tolerance not written";
        const ForcedPoint &peak = *std::max_element(curve.points.begin(), curve.points.end(),
                                                    [](const ForcedPoint &a, const ForcedPoint &b) {
                                                      return a.measures.energy < b.measures.energy;
                                                    });
        line += "; peak at Omega " + significant(peak.omega, 6) + ", energy " + significant(peak.measures.energy, 4) +
                ", phase lag " + significant(peak.measures.phase, 4) + " (pi/2 = 1.571), contact fraction " +
                significant(peak.measures.contact_fraction, 3);
        if (backbone)
          {
            const std::optional<double> main = main_energy_at(*backbone, peak.omega);
            line += main ? "; the backbone's main branch there: energy " + significant(*main, 4) + ", peak / main - 1 = " +
                             significant(peak.measures.energy / *main - 1, 3) :
                           "; no main backbone point brackets the peak's Omega";
          }
        lines.push_back(line);
      }
    return lines;
  }
} // namespace nsm
