// One run of a scene: the stages its requested outputs need, timed, then the
// files, then the summary.
#pragma once

#include <nsm/output/run_report.h>
#include <nsm/scene/scene.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace nsm
{
  /// Runs every stage the scene asks for; writes nothing unless all of them
  /// succeeded, or a stop signal asked for what was computed (with the
  /// continuation's checkpoint). With `resume`, the continuation goes on
  /// from the checkpoint an interrupted run of the same scene left in
  /// Output/Directory. The output folder holds the run's record: the scene
  /// as read (parameters.prm) and summary.txt, the record's header
  /// (run_record.h, for `command_line`) and the summary as printed with its
  /// events. Throws InputError or NumericalError.
  RunReport run_scene(const Scene &scene, bool resume = false, const std::string &command_line = "");
} // namespace nsm
