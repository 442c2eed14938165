// Gaps in the main branch that the continuation left, not the solutions:
// Newton started from the branch with half the harmonics finds main
// solutions inside most of them (tests/benchmarks/study_coverage).
#pragma once

#include <nsm/continuation/branch_context.h>

namespace nsm
{
  /// With `Fill gaps wider than` > 0, once the continuation has reached the
  /// end of its range or lost the branch (not at Max steps or a stop): every
  /// gap between main points wider than that (the labels of the points
  /// traced so far, in the range; up to the range's end only if the branch
  /// reached it) is searched from the points inside it of the branch traced
  /// with half the harmonics, its main points first, each group nearest the
  /// gap's start first, each at its own Omega with its higher harmonics zero
  /// (Newton with a line search, as a leap). A solution the labels put on
  /// the main branch starts a new segment of sequential steps, which ends
  /// where it folds or before it passes the gap's far side; what is left of
  /// the gap is searched again. A gap with no such landing stays. Stop
  /// signals wait until the filling ends.
  void fill_gaps(BranchContext &context, Backbone &backbone);
} // namespace nsm
