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
    /// The main points between `low` and `passed`, highest Omega first.
    std::vector<std::size_t> climb_down(const std::vector<BackbonePoint> &points, const double low,
                                        const double passed)
    {
      std::vector<std::size_t> climb;
      for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].branch == Branch::main && points[i].omega >= low && points[i].omega <= passed)
          climb.push_back(i);
      std::stable_sort(climb.begin(), climb.end(),
                       [&](std::size_t a, std::size_t b) { return points[a].omega > points[b].omega; });
      return climb;
    }

    /// The Omega of the main point nearest to `omega` on its `side` (-1
    /// below, +1 above); `omega` itself if there is none.
    double nearest_main(const std::vector<BackbonePoint> &points, const double omega, const double side)
    {
      double nearest = omega;
      for (const BackbonePoint &p : points)
        if (p.branch == Branch::main && side * (p.omega - omega) > 0 &&
            (nearest == omega || side * (p.omega - nearest) < 0))
          nearest = p.omega;
      return nearest;
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
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const BackbonePoint &p : backbone.points)
        if (p.branch == Branch::tongue && at_accumulation_point(p.resonance))
          lo = std::min(lo, p.omega), hi = std::max(hi, p.omega);
      merged->foot_begin = nearest_main(backbone.points, lo, -1);
      merged->foot_end   = nearest_main(backbone.points, hi, +1);
      kept.push_back(*merged);
      backbone.tongues = std::move(kept);
    }
  } // namespace

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
    // does not climb into it.
    if (points.empty() || !(points.front().omega < low))
      return 0;
    std::optional<double> from;
    for (const std::size_t i : climb_down(points, low, passed))
      {
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
