// What a run or a study reports when it ends: the result in a few lines, its
// stages with their wall and CPU times, notes (DoFs, refinement), the
// continuation's events and the files written. Printed as the run summary.
#pragma once

#include <nsm/base/stage_clock.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace nsm
{
  struct RunReport
  {
    /// The answer first: range, main points, tongues, energies, verdicts.
    std::vector<std::string> result;
    /// The continuation's folds and leaps (continuation.log).
    std::vector<std::string> events;
    std::vector<StageTiming> stages;
    std::vector<std::string> notes; ///< DoFs, refinement, memory
    std::vector<std::string> files;
    /// The signal (SIGINT, SIGTERM, SIGHUP) that stopped the run early; 0 if none.
    int stopped_by = 0;
    /// The stopped run wrote its continuation's checkpoint: --resume goes on from it.
    bool resumable = false;
    /// A request the run could not meet after writing everything else
    /// (a field with no main point within reach); the run exits 3.
    std::string failure;
    /// Why the plots were not drawn (the plotting environment failed); the
    /// rest is written, and the run exits 5 (an output error).
    std::string plot_failure;
  };

  /// The run summary: the result, the stages' times, the notes, the files written.
  /// With `verbose`, the continuation's events are printed too; otherwise a
  /// line counts them and names continuation.log.
  void print_report(const RunReport &report, std::ostream &out, bool verbose = false);
} // namespace nsm
