// Over a fold or a resonance tongue to the branch beyond it: Newton at Omega
// values growing away from the segment's front, from three guesses, and from
// the branch with half the harmonics where those fail.
#pragma once

#include <nsm/continuation/branch_context.h>

#include <optional>

namespace nsm
{
  /// Tries W beyond the fold at distances growing from Initial step to Search
  /// reach times Omega (the last try exactly at the end of the range), from
  /// three guesses: the front of the segment (its furthest point up to where
  /// arclength first turned back before climbing a tongue), the segment's
  /// first point, which the resonance has not distorted yet, and an impulsive
  /// contact reaching the gap at that W. A landing must be below Leap energy
  /// ratio times the front's energy (far above it is a tongue's flank) and
  /// above the least energy written within reach behind the front divided by
  /// that ratio (a front high on a tongue must not bar the way down to the
  /// branch). If nothing lands, the last resort tries the last point before
  /// the segment as the only guess, and then (Leap from fewer harmonics) the
  /// main points within reach of the branch traced with half the harmonics,
  /// nearest first, at their own W: near dense resonances nothing else lies
  /// in Newton's basin (the seed bar at M = 160); and, where none lands, its
  /// main points beyond the reach, nearest first, rather than lose the
  /// branch (the seed bar at M = 320). A success
  /// appends the landing as the first point of `segment`; a failure records
  /// how the backbone ended (Backbone::end: lost, or energy_max where the only
  /// landings lay above Energy max) and what the Newton solves ended in.
  /// `first_fold` is the backbone index of the ended segment's first fold, as
  /// its tracer found it (SegmentTracer::first_fold; none: the front is
  /// sought up to the segment's last point).
  bool leap(BranchContext &context, Backbone &backbone, unsigned int segment,
            const std::optional<std::size_t> &first_fold = std::nullopt);
} // namespace nsm
