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

  /// Limits deal.II to one thread, as a study's MPI_InitFinalize does: its
  /// FEValues gives other last bits with more threads (gradients with 2
  /// threads against 1, measured), so results would depend on the machine's
  /// cores, and a study's row would not be its scene's plain run bit for
  /// bit. These 1D problems gain no time from threads (prm/seed.prm: 0.53 s
  /// both ways). Every program that computes results calls it first.
  void use_one_thread();
} // namespace nsm
