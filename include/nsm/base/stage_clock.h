// The one clock of a run's stages: deal.II's TimerOutput, wall and CPU time
// per named stage, read back in the order the stages were first entered. A
// run (app/pipeline.cc) and a study's row (study/study_measures.cc) are timed
// on it.
#pragma once

#include <deal.II/base/timer.h>

#include <sstream>
#include <string>
#include <vector>

namespace nsm
{
  /// A stage's cost, summed over its entries.
  struct StageTiming
  {
    std::string name;
    double      wall_seconds;
    double      cpu_seconds;
  };

  class StageClock
  {
  public:
    StageClock();

    /// Runs `work` as the stage `name`: its wall and CPU time add to the
    /// stage's, also when `work` throws.
    template <typename Work>
    decltype(auto) timed(const std::string &name, Work &&work)
    {
      enter(name);
      const dealii::TimerOutput::Scope scope(timer_, name);
      return work();
    }

    /// Every stage entered, in the order of its first entry.
    std::vector<StageTiming> timings() const;

  private:
    void enter(const std::string &name);

    std::ostringstream       quiet_; ///< TimerOutput's stream: it prints nothing
    dealii::TimerOutput      timer_;
    std::vector<std::string> order_;
  };
} // namespace nsm
