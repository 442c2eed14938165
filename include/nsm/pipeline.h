// One run of a scene: the stages its requested outputs need, timed, then the
// files, then the summary.
#pragma once

#include <nsm/output.h>
#include <nsm/scene.h>

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
  };

  /// Runs every stage the scene asks for; writes nothing unless all of them
  /// succeeded. Throws InputError or NumericalError.
  RunReport run_scene(const Scene &scene);

  void print_report(const RunReport &report, std::ostream &out);
} // namespace nsm
