#include <nsm/continuation/constants.h>
#include <nsm/continuation/main_branch.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace nsm
{
  namespace
  {
    /// harmonic_excess() with the total energy given.
    double excess(const std::vector<double> &energies, const unsigned int k, const double total)
    {
      if (k < continuation_constants::first_compared_harmonic || k >= energies.size())
        return 0;
      // The geometric mean of the same-parity neighbours follows a smooth
      // decay, and the odd-even alternation of symmetric motions.
      const bool   above    = k + 2 < energies.size();
      const double envelope = above ? std::sqrt(energies[k - 2] * energies[k + 2]) : energies[k - 2];
      return (energies[k] - envelope) / total;
    }

    double total_of(const std::vector<double> &energies)
    {
      return std::accumulate(energies.begin(), energies.end(), 0.0);
    }

    /// The labels' one rule: more than `share` above the envelope (the least
    /// energy at the point's Omega or beyond) is a tongue.
    bool exceeds_envelope(const double energy, const double envelope, const double share)
    {
      return energy > (1 + share) * envelope;
    }
  } // namespace

  bool moves_at_omega(const BackbonePoint &point)
  {
    return point.measures.leading_harmonic == 1;
  }

  double harmonic_excess(const std::vector<double> &energies, const unsigned int k)
  {
    return excess(energies, k, total_of(energies));
  }

  SpectralExcess spectral_excess(const std::vector<double> &energies)
  {
    const double   total = total_of(energies);
    SpectralExcess worst{0, -std::numeric_limits<double>::infinity()};
    for (unsigned int k = continuation_constants::first_compared_harmonic; k < energies.size(); ++k)
      if (const double share = excess(energies, k, total); share > worst.share)
        worst = {k, share};
    return worst.harmonic == 0 ? SpectralExcess{0, 0.0} : worst;
  }

  InternalResonance resonance_of(const Receptance &receptance, const unsigned int k, const double omega)
  {
    const std::vector<double> &poles = receptance.poles();
    unsigned int               j     = 0;
    for (unsigned int i = 1; i < poles.size(); ++i)
      if (std::abs(std::sqrt(poles[i]) - k * omega) < std::abs(std::sqrt(poles[j]) - k * omega))
        j = i;
    return poles.empty() ? InternalResonance{0, 0, k} :
                           InternalResonance{std::sqrt(poles[j]) / k, j + 1, k};
  }

  std::vector<bool> above_envelope(const std::vector<BackbonePoint> &points,
                                   const double                      direction,
                                   const double                      share,
                                   const std::vector<bool>          &among)
  {
    const auto counted = [&](const std::size_t i) { return among.empty() || among[i]; };
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (counted(i))
        order.push_back(i);
    // From the far end back, so that the running minimum is the envelope;
    // points at one Omega share it.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return direction * points[a].omega > direction * points[b].omega;
    });
    std::vector<bool> above(points.size());
    double            least = std::numeric_limits<double>::infinity();
    for (std::size_t n = 0; n < order.size();)
      {
        std::size_t end = n;
        while (end < order.size() && points[order[end]].omega == points[order[n]].omega)
          least = std::min(least, points[order[end++]].measures.energy);
        for (; n < end; ++n)
          above[order[n]] = exceeds_envelope(points[order[n]].measures.energy, least, share);
      }
    return above;
  }

  std::vector<bool> behind_front(const std::vector<BackbonePoint> &points,
                                 const double                      direction,
                                 const std::vector<bool>          &above,
                                 const std::vector<bool>          &among)
  {
    std::vector<bool> behind(points.size());
    double            front = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        if (i > 0 && points[i].segment != points[i - 1].segment)
          front = -std::numeric_limits<double>::infinity();
        if (above[i] || !(among.empty() || among[i]))
          continue;
        behind[i] = direction * points[i].omega < front;
        if (!behind[i])
          front = direction * points[i].omega;
      }
    return behind;
  }

  namespace
  {
    /// Per point: on the lower envelope of the points `among` and not behind
    /// its segment's front.
    std::vector<bool> on_envelope(const std::vector<BackbonePoint> &points, const double direction,
                                  const double share, const std::vector<bool> &among)
    {
      const std::vector<bool> above  = above_envelope(points, direction, share, among);
      const std::vector<bool> behind = behind_front(points, direction, above, among);
      std::vector<bool>       on(points.size());
      for (std::size_t i = 0; i < points.size(); ++i)
        on[i] = among[i] && !above[i] && !behind[i];
      return on;
    }

    /// The indices of the points in the direction of continuation (trace
    /// order among points at one Omega).
    std::vector<std::size_t> along_omega(const std::vector<BackbonePoint> &points, const double direction)
    {
      std::vector<std::size_t> order(points.size());
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return direction * points[a].omega < direction * points[b].omega;
      });
      return order;
    }
  } // namespace

  InternalResonance named_if_near(const InternalResonance &r, const double lo, const double hi)
  {
    const double distance = r.omega < lo ? lo - r.omega : r.omega > hi ? r.omega - hi : 0.0;
    return distance <= continuation_constants::resonance_name_tolerance * r.omega ? r : InternalResonance{0, 0, 0};
  }

  namespace
  {
    /// Per point: on the lower envelope of its own segment's points and not
    /// behind that segment's front; other segments' points, of whatever
    /// family, play no part.
    std::vector<bool> on_own_envelope(const std::vector<BackbonePoint> &points, const double direction,
                                      const double share)
    {
      std::vector<bool> own(points.size());
      for (std::size_t first = 0; first < points.size();)
        {
          std::size_t end = first;
          while (end < points.size() && points[end].segment == points[first].segment)
            ++end;
          std::vector<bool> segment(points.size());
          std::fill(segment.begin() + first, segment.begin() + end, true);
          const std::vector<bool> on = on_envelope(points, direction, share, segment);
          std::copy(on.begin() + first, on.begin() + end, own.begin() + first);
          first = end;
        }
      return own;
    }
  } // namespace

  std::vector<bool> main_family(const std::vector<BackbonePoint> &points,
                                const double                      direction,
                                const double                      share,
                                const double                      drop)
  {
    const std::vector<bool> own = on_own_envelope(points, direction, share);
    std::vector<bool>       family(points.size(), true);
    double                  most = -std::numeric_limits<double>::infinity();
    for (const std::size_t i : along_omega(points, direction))
      {
        const double contact = points[i].measures.contact_fraction;
        if (contact < most - drop || (own[i] && !moves_at_omega(points[i])))
          family[i] = false;
        else if (own[i])
          most = std::max(most, contact);
      }
    // A point the family's envelope passes through is main unless a higher
    // harmonic leads it; without it the envelope may pass through another.
    for (bool removed = true; removed;)
      {
        removed                     = false;
        const std::vector<bool> on = on_envelope(points, direction, share, family);
        for (std::size_t i = 0; i < points.size(); ++i)
          if (on[i] && !moves_at_omega(points[i]))
            family[i] = false, removed = true;
      }
    return family;
  }

  namespace
  {
    /// The resonance a tongue point belongs to: the harmonic that stands out
    /// of its spectrum (the fundamental with fewer than 4 harmonics, when
    /// none can).
    InternalResonance tongue_resonance(HarmonicBalance &hb, const BackbonePoint &point)
    {
      hb.set_omega(point.omega);
      const unsigned int k = spectral_excess(hb.harmonic_energies(point.x)).harmonic;
      return resonance_of(hb.receptance(), std::max(k, 1u), point.omega);
    }

    /// The fundamental near the branch's own mode is the branch itself, not an
    /// internal resonance: an excursion named so (with fewer than 4
    /// harmonics, where none can stand out) is the branch's own shape.
    bool is_own_fundamental(const InternalResonance &r, const unsigned int mode)
    {
      return r.harmonic == 1 && r.mode == mode;
    }

    void mark(BackbonePoint &point, const Branch branch, const InternalResonance &r = {0, 0, 0})
    {
      point.branch    = branch;
      point.resonance = branch == Branch::tongue ? r : InternalResonance{0, 0, 0};
    }

    /// A point of the mode's family above its envelope whose excursion, over
    /// Omega in [lo, hi], names r: main if r is the branch's own fundamental
    /// (other if a higher harmonic leads the point), else a tongue point,
    /// named if w_j / k lies near.
    void mark_excursion(BackbonePoint &point, const InternalResonance &r, const unsigned int mode, const double lo,
                        const double hi)
    {
      if (!is_own_fundamental(r, mode))
        mark(point, Branch::tongue, named_if_near(r, lo, hi));
      else
        mark(point, moves_at_omega(point) ? Branch::main : Branch::other);
    }

    /// Labels the run [first, end) of the main family's points off its
    /// envelope: a tongue named from its most energetic point, or main if
    /// that names the branch's own fundamental.
    void label_run(HarmonicBalance &hb, const unsigned int mode, std::vector<BackbonePoint> &points,
                   const std::size_t first, const std::size_t end)
    {
      const auto   begin = points.begin() + first, stop = points.begin() + end;
      const auto   top   = std::max_element(begin, stop, [](const BackbonePoint &a, const BackbonePoint &b) {
        return a.measures.energy < b.measures.energy;
      });
      const auto [lo, hi] = std::minmax_element(begin, stop, [](const BackbonePoint &a, const BackbonePoint &b) {
        return a.omega < b.omega;
      });
      const InternalResonance r = tongue_resonance(hb, *top);
      for (auto p = begin; p != stop; ++p)
        mark_excursion(*p, r, mode, lo->omega, hi->omega);
    }
  } // namespace

  namespace
  {
    /// Labels every point (label_sides' `only`).
    constexpr std::size_t every_point = std::numeric_limits<std::size_t>::max();

    /// label_branches on one side of the accumulation point; with `only` a point's index,
    /// the tongue runs other than the one holding that point are left
    /// unnamed (their names cost a spectrum each).
    void label_side(HarmonicBalance &hb, const BranchParameters &params, std::vector<BackbonePoint> &points,
                    const std::size_t only)
    {
      const auto             &c         = params.continuation;
      const double            direction = branch_direction(params.contact);
      const std::vector<bool> family    = main_family(points, direction, c.tongue_share, c.main_contact_drop);
      const std::vector<bool> on        = on_envelope(points, direction, c.tongue_share, family);
      for (std::size_t first = 0; first < points.size();)
        {
          if (!family[first] || on[first])
            {
              mark(points[first], family[first] ? Branch::main : Branch::other);
              ++first;
              continue;
            }
          std::size_t end = first;
          while (end < points.size() && family[end] && !on[end])
            ++end;
          if (only == every_point || (first <= only && only < end))
            label_run(hb, c.mode, points, first, end);
          else
            for (std::size_t i = first; i < end; ++i)
              mark(points[i], Branch::tongue);
          first = end;
        }
    }

    /// Whether omega lies beyond `passed` (accumulation_passed) in
    /// `direction`; never where `passed` is NaN, so that every point is then
    /// on one side.
    bool beyond(const double omega, const double direction, const double passed)
    {
      return direction * (omega - passed) > 0;
    }
  } // namespace

  namespace
  {
    /// label_branches; with `only` a point's index (not every_point), named as
    /// label_side says.
    void label_sides(HarmonicBalance &hb, const BranchParameters &params, std::vector<BackbonePoint> &points,
                     const std::size_t only)
    {
      // The two sides of the accumulation point are labelled apart: nothing on
      // one side vetoes a family on the other (doc/method.md, "The
      // accumulation point").
      const double direction = branch_direction(params.contact), passed = accumulation_passed(params);
      for (const bool side_beyond : {false, true})
        {
          std::vector<std::size_t>   side;
          std::vector<BackbonePoint> part;
          // The point's index on this side; every_point if it lies on the other.
          std::size_t only_here = every_point;
          for (std::size_t i = 0; i < points.size(); ++i)
            if (beyond(points[i].omega, direction, passed) == side_beyond)
              {
                if (only == i)
                  only_here = side.size();
                side.push_back(i), part.push_back(std::move(points[i]));
              }
          if (only == every_point)
            label_side(hb, params, part, every_point);
          else if (only_here != every_point)
            label_side(hb, params, part, only_here);
          for (std::size_t k = 0; k < side.size(); ++k)
            points[side[k]] = std::move(part[k]);
        }
    }
  } // namespace

  void label_branches(HarmonicBalance &hb, const BranchParameters &params, std::vector<BackbonePoint> &points)
  {
    label_sides(hb, params, points, every_point);
  }

  double accumulation_passed(const BranchParameters &params)
  {
    if (branch_direction(params.contact) < 0)
      return std::numeric_limits<double>::quiet_NaN();
    const double m = params.harmonic_balance.harmonics;
    return params.accumulation_omega * (1 + continuation_constants::accumulation_reach / (m * m));
  }

  double most_contact_before(const std::vector<BackbonePoint> &points, const double omega, const double direction,
                             const double share, const double passed)
  {
    const std::vector<bool> own  = on_own_envelope(points, direction, share);
    const bool              side = beyond(omega, direction, passed);
    double                  most = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < points.size(); ++i)
      if (own[i] && points[i].branch != Branch::other && direction * (points[i].omega - omega) < 0 &&
          beyond(points[i].omega, direction, passed) == side)
        most = std::max(most, points[i].measures.contact_fraction);
    return most;
  }

  void label_point(HarmonicBalance                  &hb,
                   const BranchParameters           &params,
                   const std::vector<BackbonePoint> &points,
                   BackbonePoint                    &point,
                   const std::optional<std::size_t>  position)
  {
    std::vector<BackbonePoint> with = points;
    const std::size_t          at   = position ? std::min(*position, with.size()) : with.size();
    with.insert(with.begin() + at, point);
    label_sides(hb, params, with, at);
    point.branch    = with[at].branch;
    point.resonance = with[at].resonance;
    hb.set_omega(point.omega);
  }

  double envelope_at(const std::vector<BackbonePoint> &points, const double omega, const double direction,
                     const double passed)
  {
    const bool side  = beyond(omega, direction, passed);
    double     least = std::numeric_limits<double>::infinity();
    for (const BackbonePoint &q : points)
      if (q.branch != Branch::other && direction * (q.omega - omega) >= 0 && beyond(q.omega, direction, passed) == side)
        least = std::min(least, q.measures.energy);
    return least;
  }

  std::vector<std::pair<double, double>> main_gaps(const std::vector<BackbonePoint> &points, const double direction,
                                                   const std::optional<double> end, const std::optional<double> start)
  {
    std::vector<double> main;
    for (const BackbonePoint &p : points)
      if (p.branch == Branch::main)
        main.push_back(p.omega);
    std::sort(main.begin(), main.end(), [&](double a, double b) { return direction * a < direction * b; });
    if (!main.empty() && end)
      main.push_back(*end);
    if (!main.empty() && start)
      main.insert(main.begin(), *start);
    std::vector<std::pair<double, double>> gaps;
    for (std::size_t i = 1; i < main.size(); ++i)
      gaps.emplace_back(main[i - 1], main[i]);
    return gaps;
  }

  std::vector<std::pair<double, double>> main_gaps_wider_than(const std::vector<BackbonePoint> &points,
                                                              const double direction, const double width,
                                                              const std::optional<double> end,
                                                              const std::optional<double> start)
  {
    std::vector<std::pair<double, double>> gaps = main_gaps(points, direction, end, start);
    gaps.erase(std::remove_if(gaps.begin(), gaps.end(),
                              [&](const auto &g) { return !(std::abs(g.second - g.first) > width); }),
               gaps.end());
    return gaps;
  }

  std::vector<Tongue> collect_tongues(const std::vector<BackbonePoint> &points)
  {
    std::vector<Tongue> tongues;
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        const BackbonePoint &p = points[i];
        if (p.branch != Branch::tongue)
          continue;
        const BackbonePoint *before = i > 0 ? &points[i - 1] : nullptr;
        const bool continues = before && before->branch == Branch::tongue &&
                               before->resonance.mode == p.resonance.mode &&
                               before->resonance.harmonic == p.resonance.harmonic &&
                               before->resonance.omega == p.resonance.omega;
        if (!continues)
          {
            const double foot = before ? before->omega : p.omega;
            tongues.push_back({p.resonance, foot, foot, 0, 0});
          }
        Tongue &t    = tongues.back();
        t.max_energy = std::max(t.max_energy, p.measures.energy);
        ++t.points;
        t.foot_end = i + 1 < points.size() ? points[i + 1].omega : p.omega;
      }
    return tongues;
  }
} // namespace nsm
