#include <nsm/continuation/accumulation_tongue.h>
#include <nsm/continuation/constants.h>
#include <nsm/continuation/main_branch.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace nsm
{
  namespace
  {
    /// The climb's main points between `low` and W_acc, highest Omega first
    /// (the family beyond W_acc starts beyond it).
    std::vector<std::size_t> climb_down(const std::vector<BackbonePoint> &points, const double low,
                                        const double w_acc)
    {
      std::vector<std::size_t> climb;
      for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].branch == Branch::main && points[i].omega >= low && points[i].omega <= w_acc)
          climb.push_back(i);
      std::stable_sort(climb.begin(), climb.end(),
                       [&](std::size_t a, std::size_t b) { return points[a].omega > points[b].omega; });
      return climb;
    }

    /// The accumulation point's tongue as one row: its points may lie on
    /// several segments (collect_tongues starts a row per run). Its feet are
    /// the main points next to it.
    void merge_accumulation_rows(Backbone &backbone)
    {
      std::vector<Tongue>   kept;
      std::optional<Tongue> merged;
      for (const Tongue &t : backbone.tongues)
        if (!at_accumulation_point(t.resonance))
          kept.push_back(t);
        else if (!merged)
          merged = t;
        else
          merged->max_energy = std::max(merged->max_energy, t.max_energy), merged->points += t.points;
      const auto [lo, hi]        = accumulation_span(backbone.points);
      const BackbonePoint *below = nearest_on_side(backbone.points, lo, -1, true);
      const BackbonePoint *above = nearest_on_side(backbone.points, hi, +1, true);
      merged->foot_begin         = below ? below->omega : lo;
      merged->foot_end           = above ? above->omega : hi;
      kept.push_back(*merged);
      backbone.tongues = std::move(kept);
    }
  } // namespace

  std::pair<double, double> accumulation_span(const std::vector<BackbonePoint> &points)
  {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const BackbonePoint &p : points)
      if (p.branch == Branch::tongue && at_accumulation_point(p.resonance))
        lo = std::min(lo, p.omega), hi = std::max(hi, p.omega);
    return {lo, hi};
  }

  std::size_t name_accumulation_tongue(Backbone &backbone, const std::vector<double> &estimates,
                                       const BranchParameters &params)
  {
    std::vector<BackbonePoint> &points = backbone.points;
    const double                passed = accumulation_passed(params);
    if (std::isnan(passed) || estimates.size() != points.size())
      return 0;
    const double m   = params.harmonic_balance.harmonics;
    const double low = params.accumulation_omega * (1 - continuation_constants::accumulation_reach / (m * m));
    // A branch that starts inside the zone (the uniform bar's, at W_acc)
    // does not climb into it. It starts where it was traced from, in the
    // range or not.
    if (points.empty() || !(*backbone.traced_from() < low))
      return 0;
    // A point without an estimate (M / 2 did not converge, or not on the
    // same motion) tells nothing: the walk goes on past it.
    std::optional<double> from;
    for (const std::size_t i : climb_down(points, low, params.accumulation_omega))
      {
        if (std::isnan(estimates[i]))
          continue;
        if (!(estimates[i] > params.continuation.tongue_share))
          break;
        from = points[i].omega;
      }
    if (!from)
      return 0;
    // M / 2's truncated zone reaches 4 times as far below W_acc as M's.
    const double w_acc = params.accumulation_omega;
    const double start = w_acc * (1 - (1 - *from / w_acc) / continuation_constants::halved_truncation_reach);
    std::size_t  named = 0;
    for (BackbonePoint &p : points)
      if (p.branch != Branch::other && p.omega >= start && p.omega <= passed &&
          !(p.branch == Branch::tongue && at_accumulation_point(p.resonance)))
        {
          p.branch    = Branch::tongue;
          p.resonance = accumulation_resonance(w_acc);
          ++named;
        }
    if (named == 0)
      return 0;
    backbone.tongues = collect_tongues(points);
    merge_accumulation_rows(backbone);
    return named;
  }
} // namespace nsm
