// Gaps in the main branch that the continuation left, not the solutions: a
// leap lands on the first solution it finds, often on another family, and
// Newton from the mode predicted along its trend finds the mode inside many
// of them (doc/method.md, "Searching the main branch's gaps").
#pragma once

#include <nsm/continuation/branch_context.h>

namespace nsm
{
  /// With `Fill gaps wider than` > 0, once the continuation has reached the
  /// end of its range or lost the branch (not at Max steps or a stop): every
  /// gap between main points wider than that (the labels of the points
  /// traced so far, in the range; up to the range's end only if the branch
  /// reached it) is searched, each once: Newton (with a line search, as a
  /// leap) from the mode predicted along the main branch's trend at Omegas
  /// an eighth of the width apart (the secant and the start's own unknowns
  /// within the trend's span beyond the gap's start, the line to the far
  /// side's main point across it), then from the points inside it of the
  /// branch traced with half the harmonics, its main points first. A
  /// solution below Energy max that
  /// the labels put on the main branch starts a new segment of sequential
  /// steps, which ends where it folds, climbs above the tongue threshold or
  /// before it passes the gap's far side; without one, the branch is traced
  /// back from the far side's main point. The backbone is labelled again and
  /// the gaps left are searched in turn. Each Newton start (its Omega and
  /// guess) is solved once in the run, and its solution labelled again in a
  /// later search; a gap whose far side lies within a start's spacing of a
  /// gap searched before is searched from the branch with half the harmonics
  /// first (its solutions there are known). Each search is recorded
  /// (Backbone::gap_searches) for the Result block. Stop signals wait until
  /// the search ends.
  void fill_gaps(BranchContext &context, Backbone &backbone);
} // namespace nsm
