// The end of the range reached on a tongue's flank: the labels judge a point
// by the least energy written at its Omega or beyond, so with nothing beyond
// the range's end the flank would stay main. The main branch below it is
// looked for at the end itself.
#pragma once

#include <nsm/continuation/branch_context.h>

namespace nsm
{
  /// Called when `segment` has reached the far end of the range. If the
  /// segment came down to it (its last point lies more than Tongue share
  /// below one of its points: the main branch hardens, a tongue's far flank
  /// descends) or climbed to it (its last point lies more than Tongue share
  /// above one of its points) with more than Max contact change less contact
  /// than written within Search reach (a tongue's near flank; the rising main
  /// branch keeps its contact), Newton at the far end looks for the branch
  /// below, from the
  /// segment's first point, an impulsive contact, the last point before the
  /// segment and every earlier point within Search reach that the envelope of
  /// the points so far puts on the main branch.
  /// The lowest solution more than Tongue share below the last point, above
  /// the least energy written within Search reach divided by Leap energy
  /// ratio, and with at least the last point's contact fraction, is appended
  /// as `segment + 1`; the labels then read the flank as
  /// the tongue it is. Returns whether one was found.
  bool find_branch_below_at_end(BranchContext &context, Backbone &backbone, unsigned int segment);
} // namespace nsm
