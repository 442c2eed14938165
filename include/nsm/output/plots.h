// The plots of a run or a study, drawn by the shipped Python script.
#pragma once

#include <nsm/scene/scene.h>

#include <string>
#include <vector>

namespace nsm
{
  /// Runs the shipped plotting script on the files in `directory`, with
  /// its log in directory/plots.log; returns the files it wrote and the log.
  /// Throws NumericalError with the log's last line if it fails.
  std::vector<std::string> make_plots(const Scene::Contact &contact, const std::string &directory);
} // namespace nsm
