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
  /// succeeded. Throws InputError or NumericalError.
  RunReport run_scene(const Scene &scene);
} // namespace nsm
