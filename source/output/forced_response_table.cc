#include <nsm/base/text.h>
#include <nsm/continuation/constants.h>
#include <nsm/output/forced_response_table.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace nsm
{
  namespace
  {
    /// The main branch's energy at an Omega, read between the main points
    /// that bracket it, and how far apart they lie.
    struct MainEnergy
    {
      double energy;
      double bracket;
    };

    std::optional<MainEnergy> main_energy_at(const Backbone &backbone, const double omega)
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
      return MainEnergy{w1 == w0 ? e0 : e0 + (e1 - e0) * (omega - w0) / (w1 - w0), w1 - w0};
    }

    /// The point of most energy of a curve with points.
    const ForcedPoint &peak_point(const ForcedCurve &curve)
    {
      return *std::max_element(curve.points.begin(), curve.points.end(),
                               [](const ForcedPoint &a, const ForcedPoint &b) {
                                 return a.measures.energy < b.measures.energy;
                               });
    }

    /// The swept parameter's value at p: W, or F on a curve in F.
    double swept_value(const ForcedCurve &curve, const ForcedPoint &p)
    {
      return curve.sweep == ForcedSweep::omega ? p.omega : p.forcing;
    }

    /// The points of least and most swept value of a curve with points.
    std::pair<const ForcedPoint &, const ForcedPoint &> extent_ends(const ForcedCurve &curve)
    {
      const auto [low, high] = std::minmax_element(curve.points.begin(), curve.points.end(),
                                                   [&](const ForcedPoint &a, const ForcedPoint &b) {
                                                     return swept_value(curve, a) < swept_value(curve, b);
                                                   });
      return {*low, *high};
    }

    /// Whether `peak` lies at an end of the curve's extent: a curve still
    /// climbing there has no peak inside its range.
    bool at_range_end(const ForcedCurve &curve, const ForcedPoint &peak)
    {
      const auto [low, high] = extent_ends(curve);
      return swept_value(curve, peak) == swept_value(curve, low) || swept_value(curve, peak) == swept_value(curve, high);
    }

    /// Why an energy is not read against the main branch there.
    constexpr const char *no_main_bracket_text = ", no main backbone point on both sides";

    /// "E / main - 1 = d (main points b apart)".
    std::string distance_text(const double distance, const double bracket)
    {
      return ", against the backbone's main branch " + significant(100 * distance, 3) + " % (its main points " +
             significant(bracket, 2) + " apart there)";
    }

    /// The energy at omega against the main branch, or why there is none.
    std::string against_backbone(const Backbone *backbone, const double omega, const double energy)
    {
      if (!backbone)
        return "";
      const std::optional<MainEnergy> main = main_energy_at(*backbone, omega);
      return main ? distance_text(energy / main->energy - 1, main->bracket) : no_main_bracket_text;
    }
  } // namespace

  namespace
  {
    /// Why the peak of a curve with points is not compared, before the
    /// backbone is read (none if nothing but the backbone can stop it).
    PeakLeftOut left_out_by_curve(const ForcedCurve &curve, const ForcedPoint &peak)
    {
      if (!curve.whole())
        return PeakLeftOut::not_whole;
      if (at_range_end(curve, peak))
        return PeakLeftOut::at_range_end;
      if (peak.measures.contact_fraction == 0)
        return PeakLeftOut::linear;
      return PeakLeftOut::none;
    }
  } // namespace

  ForcedPeak forced_peak(const ForcedCurve &curve, const Backbone *backbone)
  {
    const ForcedPoint &peak = peak_point(curve);
    ForcedPeak         result{peak.omega,   peak.measures.energy, peak.measures.phase, peak.measures.contact_fraction,
                      std::nullopt, std::nullopt,          left_out_by_curve(curve, peak)};
    if (result.left_out != PeakLeftOut::none)
      return result;
    if (!backbone)
      result.left_out = PeakLeftOut::no_backbone;
    else if (const std::optional<MainEnergy> main = main_energy_at(*backbone, peak.omega))
      result.distance = peak.measures.energy / main->energy - 1, result.bracket = main->bracket;
    else
      result.left_out = PeakLeftOut::no_main_bracket;
    return result;
  }

  namespace
  {

    /// A crossing of the fundamental's phase lag through pi / 2: Omega and
    /// energy, linear between two points of a segment; `linear` where
    /// neither point touches the wall (the linear response's resonance).
    struct Quadrature
    {
      double omega, energy;
      bool   linear;
    };

    std::vector<Quadrature> quadratures(const ForcedCurve &curve)
    {
      std::vector<Quadrature> found;
      for (std::size_t i = 1; i < curve.points.size(); ++i)
        {
          const ForcedPoint &p = curve.points[i - 1], &q = curve.points[i];
          const double       a = p.measures.phase - M_PI / 2, b = q.measures.phase - M_PI / 2;
          // A lag that wraps from pi to -pi (the drive's antiphase, far
          // above a resonance) changes sign about pi/2 without crossing it.
          if (p.segment != q.segment || a * b > 0 || a == b || std::abs(b - a) > M_PI)
            continue;
          // On the linear response a lag that falls through pi/2 as W rises
          // is an anti-resonance (the contact end's amplitude at its least,
          // between two modes), not a phase resonance.
          const bool linear = p.measures.contact_fraction == 0 && q.measures.contact_fraction == 0;
          if (linear && (b - a) * (q.omega - p.omega) < 0)
            continue;
          const double t = a / (a - b);
          found.push_back({p.omega + t * (q.omega - p.omega),
                           p.measures.energy + t * (q.measures.energy - p.measures.energy), linear});
        }
      return found;
    }

    /// The index of the first of the curve's last `far_points` points (the
    /// trace from Omega max).
    std::size_t far_begin(const ForcedCurve &curve, const std::size_t far_points)
    {
      return curve.points.size() - std::min(far_points, curve.points.size());
    }

    /// How the trace from Omega max, the curve's last `far_points` points,
    /// is split: "a segment of its own" or "N segments of their own".
    std::string far_segments(const ForcedCurve &curve, const std::size_t far_points)
    {
      std::size_t segments = 0;
      for (std::size_t i = far_begin(curve, far_points); i < curve.points.size(); ++i)
        segments += i == 0 || curve.points[i].segment != curve.points[i - 1].segment;
      return segments == 1 ? "a segment of its own" : std::to_string(segments) + " segments of their own";
    }

    /// " (after turning at Omega w)" where the trace from Omega max (the
    /// curve's last `far_points` points) went below where it stopped: down
    /// the linear response and back up another branch.
    std::string far_turn(const ForcedCurve &curve, const std::size_t far_points, const double reached)
    {
      double lowest = reached;
      for (std::size_t i = far_begin(curve, far_points); i < curve.points.size(); ++i)
        lowest = std::min(lowest, curve.points[i].omega);
      const std::string turn = significant(lowest, 6);
      return turn != significant(reached, 6) ? " (after turning at Omega " + turn + ")" : "";
    }

    /// The curve's points, Omega extent, and how its tracing went.
    std::string extent(const ForcedCurve &curve)
    {
      const bool in_omega = curve.sweep == ForcedSweep::omega;
      const auto value    = [&](const ForcedPoint &p) { return swept_value(curve, p); };
      const auto [lowest, highest] = extent_ends(curve);
      const double low = value(lowest), high = value(highest);
      std::string text = std::to_string(curve.points.size()) + " points on " + (in_omega ? "" : "F in ") + "[" +
                         significant(low, 6) + ", " + significant(high, 6) + "]";
      if (curve.out_of_steps)
        text += ", stopped before the range's end: Continuation/Max steps reached (" +
                counted(curve.points.size(), "point") + " written; raise it to go on)";
      else if (const auto &far = curve.from_far_end; far && std::isnan(far->stopped))
        text += std::string(", the start at Omega min converged nowhere: traced from Omega max = ") +
                significant(high, 6) +
                (far->met() ? " down to Omega min" : " until it stopped at Omega " + significant(far->reached, 6));
      else if (!curve.finished && far && far->met())
        text += ", traced from both ends of the range, the trace from Omega min stopping at Omega " +
                significant(far->stopped, 6) + " and the one from Omega max = " + significant(high, 6) +
                " joining its path at Omega " + significant(far->reached, 6) + " (" +
                counted(far->points, "point") + ", " + far_segments(curve, far->points) + ")";
      else if (!curve.finished && far && far->points == 0)
        text += ", stopped before the range's end at Omega " + significant(far->stopped, 6) +
                " (no step, restart or leap went on); traced again from Omega max, no point converged there";
      else if (!curve.finished && far)
        text += ", stopped before the range's end at Omega " + significant(far->stopped, 6) +
                " (no step, restart or leap went on), then traced again from Omega max = " +
                significant(high, 6) + " until it stopped at Omega " + significant(far->reached, 6) +
                far_turn(curve, far->points, far->reached) + " (" + counted(far->points, "point") + ", " +
                far_segments(curve, far->points) + ")";
      else if (!curve.finished)
        text += ", stopped before the range's end (no step, restart or leap went on)";
      if (curve.restarts + curve.leaps > 0)
        text += ", " + counted(curve.restarts, "restart") + " at corners, " + counted(curve.leaps, "leap") +
                " past stalls";
      if (curve.min_step_refinements > 0)
        text += ", Continuation/Min step divided by " +
                significant(continuation_constants::forced_min_step_division, 3) + " " +
                counted(curve.min_step_refinements, "time") + " where nothing else went on";
      if (curve.rejected > 0)
        text += ", " + counted(curve.rejected, "step") + " above the tolerance not written";
      if (curve.retraced > 0)
        text += ", " + counted(curve.retraced, "point") +
                " not written where the stepper came back along the curve past a corner or went round a loop of it again";
      const auto unstable =
        std::count_if(curve.points.begin(), curve.points.end(), [](const ForcedPoint &p) { return !p.stable; });
      text += "; " + std::to_string(unstable) + " unstable by the fold test";
      // Where the verdict flips back and forth at one corner, its value is
      // said once, with how many times.
      std::vector<std::pair<std::string, unsigned int>> changes;
      for (std::size_t i = 1; i < curve.points.size(); ++i)
        if (curve.points[i].segment == curve.points[i - 1].segment &&
            curve.points[i].stable != curve.points[i - 1].stable)
          {
            const std::string at = significant(value(curve.points[i]), 6);
            if (!changes.empty() && changes.back().first == at)
              ++changes.back().second;
            else
              changes.emplace_back(at, 1);
          }
      for (std::size_t c = 0; c < changes.size(); ++c)
        text += (c == 0 ? std::string(", the verdict changing along the curve at ") + (in_omega ? "Omega " : "F ") :
                          std::string(", ")) +
                changes[c].first + (changes[c].second > 1 ? " (" + std::to_string(changes[c].second) + " times)" : "");
      return text;
    }
  } // namespace

  std::string curve_name(const ForcedCurve &curve)
  {
    return curve.sweep == ForcedSweep::omega ? "forced response F = " + significant(curve.forcing, 4) :
                                               "force response at Omega " + significant(curve.omega, 6);
  }

  CsvTable forced_response_table(const std::vector<ForcedCurve> &curves, const ForcedVerifications &verifications,
                                 const std::string &name)
  {
    CsvTable table{name,
                   {"forcing", "segment", "Omega", "energy", "tip_amplitude", "phase", "contact_fraction", "stable",
                    "max_contact_force", "input_power", "dissipated_power", "residual"},
                   {}};
    if (!verifications.empty())
      for (const char *column : {"verified_tip_amplitude", "verified_energy", "verified_drift"})
        table.columns.push_back(column);
    const bool floquet = std::any_of(verifications.begin(), verifications.end(), [](const auto &curve) {
      return std::any_of(curve.begin(), curve.end(), [](const auto &v) { return v && v->floquet; });
    });
    if (floquet)
      for (const char *column : {"floquet_largest", "floquet_real", "floquet_imag", "floquet_beyond_one"})
        table.columns.push_back(column);
    for (std::size_t c = 0; c < curves.size(); ++c)
      for (std::size_t i = 0; i < curves[c].points.size(); ++i)
        {
          const ForcedPoint    &p = curves[c].points[i];
          const ForcedMeasures &m = p.measures;
          table.rows.push_back({p.forcing, double(p.segment), p.omega, m.energy, m.tip_amplitude, m.phase,
                                m.contact_fraction, double(p.stable), m.max_contact_force, m.input_power, m.dissipated_power,
                                p.residual});
          if (verifications.empty())
            continue;
          const std::optional<ForcedVerification> &v = verifications[c][i];
          for (const double value : {v ? v->tip_amplitude : 0.0, v ? v->energy : 0.0, v ? v->drift : 0.0})
            table.rows.back().push_back(v ? CsvCell(value) : CsvCell(std::string()));
          if (!floquet)
            continue;
          // The largest multiplier, where the shooting converged.
          const bool known = v && v->floquet && v->floquet->converged();
          const std::complex<double> largest = known ? v->floquet->values.front() : 0.0;
          for (const double value : {std::abs(largest), largest.real(), largest.imag(),
                                     known ? double(v->floquet->beyond_plus_one()) : 0.0})
            table.rows.back().push_back(known ? CsvCell(value) : CsvCell(std::string()));
        }
    return table;
  }

  std::string forced_verification_summary(const std::vector<ForcedCurve> &curves,
                                          const ForcedVerifications      &verifications)
  {
    // The stable points' agreement; the unstable ones only as left or kept.
    std::vector<double> amplitude, energy, drift;
    unsigned int        fewest = std::numeric_limits<unsigned int>::max(), most = 0;
    unsigned int        points = 0, unstable = 0, left = 0;
    const double        within = forced_verification_constants::stays_within;
    for (std::size_t c = 0; c < curves.size(); ++c)
      for (std::size_t i = 0; i < curves[c].points.size(); ++i)
        if (const auto &v = verifications[c][i])
          {
            const ForcedPoint &p      = curves[c].points[i];
            const double       change = std::abs(v->tip_amplitude / p.measures.tip_amplitude - 1);
            ++points;
            fewest = std::min(fewest, v->periods);
            most   = std::max(most, v->periods);
            if (!p.stable)
              {
                ++unstable;
                left += stays_on(*v, p.measures.tip_amplitude) ? 0 : 1;
                continue;
              }
            amplitude.push_back(change);
            energy.push_back(std::abs(v->energy / p.measures.energy - 1));
            drift.push_back(v->drift);
          }
    if (points == 0)
      return "forced response verified in time: no point";
    const auto median_and_largest = [](std::vector<double> values) {
      std::sort(values.begin(), values.end());
      return "median " + significant(values[values.size() / 2], 2) + ", largest " + significant(values.back(), 2);
    };
    const std::string percent = significant(100 * within, 2) + " %";
    std::string       line =
      "forced response verified in time (the damped, driven model from each point's motion; the last of " +
      (fewest == most ? std::to_string(most) : std::to_string(fewest) + " to " + std::to_string(most)) +
      " periods integrated): " + std::to_string(points) + " points, " + std::to_string(amplitude.size()) +
      " stable and " + std::to_string(unstable) + " unstable by the fold test";
    if (!amplitude.empty())
      line += "; the stable ones: |tip amplitude / the point's - 1| " + median_and_largest(amplitude) +
              ", kept within " + percent + " on " +
              std::to_string(std::count_if(amplitude.begin(), amplitude.end(), [&](double a) { return a <= within; })) +
              "; |energy / the point's - 1| " + median_and_largest(energy) +
              "; the last period's drift max |u(L, t) - u(L, t - T)| / g0 " + median_and_largest(drift);
    if (unstable > 0)
      line += "; the unstable ones left by more than " + percent + ": " + std::to_string(left) + " of " +
              std::to_string(unstable);
    return line;
  }

  std::vector<std::string> forced_response_events(const std::vector<ForcedCurve> &curves)
  {
    std::vector<std::string> events;
    for (const ForcedCurve &curve : curves)
      for (std::size_t i = 1; i < curve.points.size(); ++i)
        {
          const ForcedPoint &p = curve.points[i - 1], &q = curve.points[i];
          const bool in_omega = curve.sweep == ForcedSweep::omega;
          if (p.segment == q.segment && p.stable != q.stable)
            events.push_back(curve_name(curve) + ": " + (q.stable ? "stable again" : "unstable (fold test)") +
                             (in_omega ? " between Omega " + significant(p.omega, 7) + " and " + significant(q.omega, 7) :
                                         " between F " + significant(p.forcing, 7) + " and " + significant(q.forcing, 7)) +
                             ", energy " +
                             significant(q.measures.energy, 4) + " (points " + std::to_string(i - 1) + " and " +
                             std::to_string(i) + " of the curve)");
        }
    return events;
  }

  std::string no_point(const ForcedCurve &curve)
  {
    return curve.sweep == ForcedSweep::omega ?
             std::string("no point: neither the start at Omega min nor the one at Omega max converged (the linear "
                         "response's guess; a smaller Forcing/Amplitudes value, or a range that starts farther "
                         "from the resonance, starts off the wall)") :
             std::string("no point: the start at F = 0 did not converge");
  }

  namespace
  {
    /// A Result line per curve: its name, then `describe(curve, peak)` with
    /// its point of most energy, or why it has no point.
    template <typename Describe>
    std::vector<std::string> curve_lines(const std::vector<ForcedCurve> &curves, const Describe &describe)
    {
      std::vector<std::string> lines;
      for (const ForcedCurve &curve : curves)
        lines.push_back(curve_name(curve) + ": " +
                        (curve.points.empty() ? no_point(curve) :
                                                describe(curve, peak_point(curve))));
      return lines;
    }
  } // namespace

  std::vector<std::string> force_response_summary(const std::vector<ForcedCurve> &curves)
  {
    return curve_lines(curves, [](const ForcedCurve &curve, const ForcedPoint &peak) {
      return extent(curve) + "; most energy at F " + significant(peak.forcing, 4) + ": energy " +
             significant(peak.measures.energy, 4) + ", phase lag " + significant(peak.measures.phase, 3) +
             ", contact fraction " + significant(peak.measures.contact_fraction, 2);
    });
  }

  namespace
  {
    /// What the Result line calls a curve's point of most energy.
    std::string peak_name(const PeakLeftOut left_out)
    {
      switch (left_out)
        {
          case PeakLeftOut::not_whole:
            return "; the most energy of the points traced";
          case PeakLeftOut::at_range_end:
            return "; no peak inside the range: the most energy at its end";
          default:
            return "; peak (most energy)";
        }
    }

    /// The peak against the backbone's main branch, or why it is not
    /// compared; nothing without a backbone, nor at the range's end (the
    /// peak's name says why).
    std::string against_backbone(const ForcedPeak &peak, const bool with_backbone)
    {
      if (!with_backbone)
        return "";
      switch (peak.left_out)
        {
          case PeakLeftOut::none:
            return distance_text(*peak.distance, *peak.bracket);
          case PeakLeftOut::no_main_bracket:
            return no_main_bracket_text;
          case PeakLeftOut::linear:
            return ", never touching the wall: the linear response, not compared with the backbone";
          case PeakLeftOut::not_whole:
            return ", not compared with the backbone: a stretch neither trace reached may hold the peak";
          default:
            return "";
        }
    }
  } // namespace

  std::vector<std::string> forced_response_summary(const std::vector<ForcedCurve> &curves,
                                                   const Backbone                 *backbone)
  {
    return curve_lines(curves, [backbone](const ForcedCurve &curve, const ForcedPoint &) {
      const ForcedPeak peak = forced_peak(curve, backbone);
      std::string      line = extent(curve) + peak_name(peak.left_out) + " at Omega " + significant(peak.omega, 6) +
                         ": energy " + significant(peak.energy, 4) + ", phase lag " + significant(peak.phase, 3) +
                         " (pi/2 at phase resonance), contact fraction " + significant(peak.contact_fraction, 2) +
                         against_backbone(peak, backbone != nullptr);
      for (const Quadrature &q : quadratures(curve))
        line += "; phase lag pi/2 at Omega " + significant(q.omega, 6) + ", energy " + significant(q.energy, 4) +
                (q.linear && backbone ? std::string(", never touching the wall: the linear response's resonance, "
                                                    "not compared with the backbone") :
                                        against_backbone(backbone, q.omega, q.energy));
      return line;
    });
  }
} // namespace nsm
