#include <nsm/app/run_result.h>
#include <nsm/base/text.h>
#include <nsm/continuation/accumulation_tongue.h>
#include <nsm/continuation/main_branch.h>
#include <nsm/model/exact_references.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// Main-branch energies shown: the first and last main points and two
    /// between, evenly spread over the main points.
    constexpr unsigned int energy_samples = 4;
    /// The exact-mode error a main point is counted within (5 %).
    constexpr double exact_error_share = 0.05;

    /// In the order of Omega along the branch (filled gaps are traced last,
    /// gap_filling.h).
    std::vector<const BackbonePoint *> main_points(const Backbone &backbone, const double direction)
    {
      std::vector<const BackbonePoint *> main;
      for (const BackbonePoint &p : backbone.points)
        if (p.branch == Branch::main)
          main.push_back(&p);
      std::stable_sort(main.begin(), main.end(), [&](const BackbonePoint *a, const BackbonePoint *b) {
        return direction * a->omega < direction * b->omega;
      });
      return main;
    }

    /// How the backbone ended, naming the parameter that ended it.
    std::string ending(const Backbone &backbone, const double reached, const ContinuationParameters &c)
    {
      switch (backbone.end)
        {
          case BackboneEnd::range:
            {
              // The end of the range the branch reached (it runs down in Omega with eq. (5)).
              const double last  = reached;
              const bool   upper = std::abs(last - c.omega_max) <= std::abs(last - c.omega_min);
              return std::string("range: Continuation/") + (upper ? "Omega max = " : "Omega min = ") +
                     significant(upper ? c.omega_max : c.omega_min, 8);
            }
          case BackboneEnd::max_steps:
            return "max_steps: Continuation/Max steps = " + std::to_string(c.max_steps) + " points";
          case BackboneEnd::energy_max:
            return "energy_max: the branch goes on above Continuation/Energy max = " + significant(c.energy_max, 6);
          default:
            return backbone_end_name(backbone.end) + std::string(": continuation.log says how");
        }
    }

    std::string coverage(const Backbone &backbone, const std::size_t main, const double direction,
                         const ContinuationParameters &c)
    {
      std::ostringstream s;
      s.precision(6);
      const double reached = *backbone.omega_reached(direction);
      const auto   other   = backbone.points_on(Branch::other);
      s << "backbone from Omega = " << backbone.points.front().omega << " to " << reached
        << " (ended: " << ending(backbone, reached, c) << "): " << main << " main points, "
        << backbone.points.size() - main - other << " points on " << backbone.tongues.size() << " tongues, "
        << other << " on other families";
      // A branch traced from a grazing start outside the range is written
      // from the range's near end on.
      const double from = *backbone.traced_from(), near_end = direction > 0 ? c.omega_min : c.omega_max;
      if (direction * (from - near_end) < 0)
        s << "; traced from grazing at Omega = " << from << ", outside the range, and written from Continuation/"
          << (direction > 0 ? "Omega min = " : "Omega max = ") << near_end << " on";
      return s.str();
    }

    std::string energies(const std::vector<const BackbonePoint *> &main)
    {
      std::ostringstream s;
      s.precision(4);
      s << "energy on the main branch:";
      const std::size_t count = std::min<std::size_t>(energy_samples, main.size());
      for (std::size_t i = 0; i < count; ++i)
        {
          const BackbonePoint &p = *main[count == 1 ? 0 : i * (main.size() - 1) / (count - 1)];
          s << (i ? "," : "") << ' ' << p.measures.energy << " at " << std::setprecision(6) << p.omega
            << std::setprecision(4);
        }
      return s.str();
    }

    /// The widest gap between consecutive main points, and the entry that
    /// searches such gaps (no search: Fill gaps wider than = 0).
    std::string widest_gap(const Backbone &backbone, const double direction)
    {
      const std::vector<std::pair<double, double>> gaps = main_gaps(backbone.points, direction);
      const auto widest = std::max_element(gaps.begin(), gaps.end(), [](const auto &a, const auto &b) {
        return std::abs(a.second - a.first) < std::abs(b.second - b.first);
      });
      std::ostringstream s;
      s.precision(4);
      s << "widest gap between main points: " << std::abs(widest->second - widest->first) << std::setprecision(6)
        << " from Omega = " << widest->first << " to " << widest->second
        << " (Continuation/Fill gaps wider than searches such gaps)";
      return s.str();
    }

    /// The gap search's own work: Newton solves, failures, iterations and
    /// wall time.
    std::string gap_search_work(const Backbone &backbone)
    {
      const NewtonCost  &c = backbone.gap_search_cost;
      std::ostringstream s;
      s.precision(3);
      s << "the gap search's work: " << c.converged_solves + c.failed_solves << " Newton solves, "
        << c.failed_solves << " of them not converged, " << c.converged_iterations + c.failed_iterations
        << " iterations, " << backbone.gap_search_seconds << " s (of its starts, leaps and traced segments; "
        << "a branch with fewer harmonics traced for its guesses not counted)";
      return s.str();
    }

    /// What the gap search found in the gap (from, to): the record of the
    /// search of the gap nearest to it.
    std::string search_found(const Backbone &backbone, const double from, const double to)
    {
      const GapSearch *record = nullptr;
      for (const GapSearch &g : backbone.gap_searches)
        if (!record ||
            std::abs(g.from - from) + std::abs(g.to - to) < std::abs(record->from - from) + std::abs(record->to - to))
          record = &g;
      if (!record)
        return "not searched (the continuation ended before the gap search)";
      std::ostringstream s;
      // A gap the final labels widened (the climb's truncated top named
      // after the search) was searched as it stood then.
      if (record->from != from || record->to != to)
        s << std::setprecision(6) << "searched as the gap from Omega = " << record->from << " to " << record->to
          << ": ";
      s.precision(3);
      const unsigned int failed = record->starts - record->other_family - record->tongue - record->above_energy_max;
      s << record->starts << " Newton starts from the predicted mode: " << record->other_family
        << " converged on other families";
      // Those led by the fundamental with their most contact, those led by a
      // higher harmonic counted apart: "(N of contact ...; K led by ...)".
      const unsigned int by_contact = record->other_family - record->other_harmonic;
      const char        *open       = " (";
      if (by_contact > 0)
        {
          s << open;
          if (record->other_harmonic > 0)
            s << by_contact << " of ";
          s << "contact fraction at most " << record->most_contact;
          if (std::isfinite(record->contact_before))
            s << ", the mode's " << record->contact_before << " before the gap";
          else
            s << ", no main point of the mode before the gap beyond the accumulation point";
          open = "; ";
        }
      if (record->other_harmonic > 0)
        s << open << record->other_harmonic << " led by a harmonic k > 1";
      if (record->other_family > 0)
        s << ")";
      s << ", " << record->tongue << " on tongues, ";
      if (record->above_energy_max > 0)
        s << record->above_energy_max << " above Energy max, ";
      s << failed << " did not converge";
      if (record->landed)
        s << "; a segment it traced from Omega = " << std::setprecision(6) << *record->landed
          << " began on the main branch but is not main once the whole branch is labelled (its energy lies above "
             "the mode's beyond the gap, or its contact falls short of the mode's before it)";
      return s.str();
    }

    /// Every interval wider than Fill gaps wider than where no main point was
    /// found (up to the range's end if the branch reached it, from its near
    /// end if the branch was traced from outside it), with what the gap
    /// search found there.
    std::vector<std::string> unfound_stretches(const Backbone &backbone, const double direction,
                                               const ContinuationParameters &c)
    {
      const bool reached = backbone.end == BackboneEnd::range;
      const double far   = direction > 0 ? c.omega_max : c.omega_min, near = direction > 0 ? c.omega_min : c.omega_max;
      // From the range's near end too where the branch was traced from outside it.
      const bool entered = backbone.traced_start && !in_omega_range(c, *backbone.traced_start);
      std::vector<std::string> lines;
      for (const auto &[from, to] : main_gaps_wider_than(backbone.points, direction, c.fill_gaps_wider_than,
                                                         reached ? std::optional<double>(far) : std::nullopt,
                                                         entered ? std::optional<double>(near) : std::nullopt))
        {
          std::ostringstream s;
          s.precision(6);
          s << "no main point from Omega = " << from << " to " << to << ": " << search_found(backbone, from, to);
          lines.push_back(s.str());
        }
      return lines;
    }

    /// The main points' energy error against the uniform bar's exact mode,
    /// if the bar is uniform, the wall rigid and the force sign physical.
    std::vector<std::string> exact_errors(const std::vector<const BackbonePoint *> &main, const BarModel &bar,
                                          const ContactParameters &contact)
    {
      const std::optional<ExactBar> exact = ExactBar::of(bar);
      const ContactLaw               law(contact);
      if (!exact || !exact->knows_first_mode(law))
        return {};
      std::vector<double> errors;
      for (const BackbonePoint *p : main)
        if (const std::optional<double> e = exact->first_mode_energy(p->omega, law))
          errors.push_back(std::abs(p->measures.energy - *e) / *e);
      if (errors.empty())
        return {};
      std::sort(errors.begin(), errors.end());
      const auto within =
        std::count_if(errors.begin(), errors.end(), [](const double e) { return e <= exact_error_share; });
      std::ostringstream s;
      s.precision(3);
      s << "against the exact mode (" << exact->name() << "): main-point energy error median "
        << 100 * errors[errors.size() / 2] << " %, 90th percentile " << 100 * errors[errors.size() * 9 / 10]
        << " %, within " << 100 * exact_error_share << " %: " << within << " of " << errors.size();
      return {s.str()};
    }

    /// "; the climb's top ... is a tongue of the accumulation point" where
    /// name_accumulation_tongue named one; empty otherwise.
    std::string climb_top(const Backbone &backbone)
    {
      const auto count = std::count_if(backbone.points.begin(), backbone.points.end(), [](const BackbonePoint &p) {
        return p.branch == Branch::tongue && at_accumulation_point(p.resonance);
      });
      if (count == 0)
        return "";
      const auto [lo, hi] = accumulation_span(backbone.points);
      std::ostringstream s;
      s.precision(6);
      s << "; the climb's top from Omega = " << lo << " to " << hi << " (" << count
        << " points) is a tongue of the accumulation point: the truncation sets its energy there (a quarter as deep "
           "below W_acc as where halving the harmonics moves the energy by more than Continuation/Tongue share: the "
           "zone narrows like M^-2)";
      return s.str();
    }

    /// Where the branch crosses the accumulation point of its internal
    /// resonances: for a bar of one material, w_j / (2j - 1) -> pi / (2 tau)
    /// (WKB; tau = L sqrt(rho / E), the wave's travel time), and for mode n
    /// the resonances w_j = k W with 2j - 1 = k (2n - 1) crowd at (2n - 1)
    /// times it. A branch that starts below that point climbs into it.
    std::vector<std::string> accumulation_crossing(const std::vector<const BackbonePoint *> &main,
                                                   const Backbone &backbone, const BarModel &bar,
                                                   const ContinuationParameters &continuation, const double direction)
    {
      const double w_acc = bar.accumulation_frequency(continuation.mode);
      const double start = *backbone.traced_from();
      if (!(direction > 0 && start < w_acc && continuation.omega_max > w_acc))
        return {};
      const auto beyond = std::count_if(main.begin(), main.end(), [&](const BackbonePoint *p) { return p->omega > w_acc; });
      std::ostringstream s;
      s.precision(6);
      s << "the branch crosses the accumulation point W_acc = " << w_acc << " of its internal resonances (w_j / (2j - 1) -> "
        << (continuation.mode > 1 ? "(2n - 1) " : "") << "pi / (2 tau), tau = L sqrt(rho / E)): it starts below it, at "
        << start << ", the tongues crowd towards it, and the branch's climb into it is set by the truncation M; "
        << "beyond it the labels judge the branch on its own (the uniform bar's mode continued): " << beyond
        << " of the " << main.size() << " main points " << (beyond == 1 ? "lies" : "lie") << " beyond it";
      s << climb_top(backbone) << " (doc/method.md, \"The accumulation point\")";
      return {s.str()};
    }
  } // namespace

  std::vector<std::string> backbone_result(const Backbone &backbone, const BarModel &bar,
                                           const ContactParameters &contact, const ContinuationParameters &continuation)
  {
    if (backbone.points.empty())
      return {"backbone: no point"};
    const double                             direction = branch_direction(contact);
    const std::vector<const BackbonePoint *> main      = main_points(backbone, direction);
    std::vector<std::string> lines{coverage(backbone, main.size(), direction, continuation)};
    if (!main.empty())
      lines.push_back(energies(main));
    if (main.size() > 1 && continuation.fill_gaps_wider_than == 0)
      lines.push_back(widest_gap(backbone, direction));
    if (!main.empty() && continuation.fill_gaps_wider_than > 0)
      for (std::string &line : unfound_stretches(backbone, direction, continuation))
        lines.push_back(std::move(line));
    if (const NewtonCost &c = backbone.gap_search_cost; c.converged_solves + c.failed_solves > 0)
      lines.push_back(gap_search_work(backbone));
    for (std::string &line : accumulation_crossing(main, backbone, bar, continuation, direction))
      lines.push_back(std::move(line));
    for (std::string &line : exact_errors(main, bar, contact))
      lines.push_back(std::move(line));
    return lines;
  }
} // namespace nsm
