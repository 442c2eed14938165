// The plots of a run or a study, drawn by the shipped Python script.
#pragma once

#include <nsm/scene/contact_parameters.h>

#include <string>
#include <vector>

namespace nsm
{
  /// What the plotting script left: the plots drawn, or why there are none.
  struct PlotResult
  {
    /// The plots it finished (each whole: the script renames it into place)
    /// and its log (directory/plots.log), also when it failed or was stopped.
    std::vector<std::string> files;
    /// Empty if the plots were drawn; else why not: the script's last line
    /// (a missing matplotlib, a file limit, a full disk...) or the stop.
    std::string failure;
    /// The signal (SIGINT, SIGTERM, SIGHUP) that ended the plotting; 0 if none.
    int stopped_by = 0;
  };

  /// Runs the shipped plotting script on the files in `directory` (each
  /// figure says `caption`: which scene, mesh and M drew it), with its
  /// log in directory/plots.log, in a process group of its own: a stop
  /// signal reaches this process only, which ends the script at once (one
  /// that came before the plots began does not: a stopped run draws what it
  /// computed). A plot
  /// is an output like any other: its failure never discards the files
  /// computed, and is reported to the caller, not thrown.
  ///
  /// The log names each plot under `shown_as` (the output directory a run's
  /// staging directory becomes), or under `directory` if it is empty. The
  /// script is plot_script()'s.
  PlotResult make_plots(const ContactParameters &contact, const std::string &directory, const std::string &caption,
                        const std::string &shown_as = "");

  /// The plotting script, found relative to the running program: an
  /// installed one's PREFIX/share/nsm-bar/plot_results.py (cmake --install),
  /// or the build tree's scripts/ beside the program (copied at each build).
  /// Empty if neither exists (a program copied alone: its plots fail, naming
  /// where it looked).
  std::string plot_script();
} // namespace nsm
