// What a run or a study reports when it ends: its stages with their wall and
// CPU times, notes (DoFs, refinement, continuation events) and the files
// written. Printed as the run summary.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace nsm
{
  struct StageTiming
  {
    std::string name;
    double      wall_seconds;
    double      cpu_seconds;
  };

  struct RunReport
  {
    std::vector<StageTiming> stages;
    std::vector<std::string> notes; ///< DoFs, refinement, continuation events
    std::vector<std::string> files;
    /// The signal (SIGINT, SIGTERM) that stopped the run early; 0 if none.
    int stopped_by = 0;
    /// A request the run could not meet after writing everything else
    /// (a field with no main point within reach); the run exits 3.
    std::string failure;
  };

  /// The run summary: the stages' times, the notes, the files written.
  void print_report(const RunReport &report, std::ostream &out);
} // namespace nsm
