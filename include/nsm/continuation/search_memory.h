// What each Newton start of the gap search (gap_filling.h) gave, kept for the
// searches of the gaps left after it: a landing shortens a gap, and the gap is
// searched again, from many of the same guesses. Newton from one guess at one
// Omega is deterministic, so a start is solved once in the run; a solution
// kept is labelled again against the labels of its new search.
#pragma once

#include <nsm/continuation/branch_context.h>

#include <map>
#include <optional>
#include <tuple>
#include <vector>

namespace nsm
{
  /// A Newton start: its Omega and the Omegas of the two points its guess is
  /// drawn between (the M / 2 branch's point three times for its own guess).
  using SearchStart = std::tuple<double, double, double>;

  class SearchMemory
  {
  public:
    /// The solution from `guess` at `omega` (BranchContext::solve with both
    /// Newton methods, segment 0), solved on first asking for `start`; empty
    /// if Newton failed. Later askings return the same object unsolved.
    const std::optional<BackbonePoint> &solve(BranchContext &context, double omega, const SearchStart &start,
                                              const std::vector<double> &guess);

  private:
    std::map<SearchStart, std::optional<BackbonePoint>> solutions_;
  };
} // namespace nsm
