#include <nsm/base/stage_clock.h>

#include <algorithm>

namespace nsm
{
  StageClock::StageClock()
    : timer_(quiet_, dealii::TimerOutput::never, dealii::TimerOutput::cpu_and_wall_times)
  {}

  void StageClock::enter(const std::string &name)
  {
    if (std::find(order_.begin(), order_.end(), name) == order_.end())
      order_.push_back(name);
  }

  std::vector<StageTiming> StageClock::timings() const
  {
    const auto walls = timer_.get_summary_data(dealii::TimerOutput::total_wall_time);
    const auto cpus  = timer_.get_summary_data(dealii::TimerOutput::total_cpu_time);
    std::vector<StageTiming> timings;
    for (const std::string &name : order_)
      timings.push_back({name, walls.at(name), cpus.at(name)});
    return timings;
  }
} // namespace nsm
