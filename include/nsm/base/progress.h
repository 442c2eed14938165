// Progress lines on stderr for stages that can run for minutes.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace nsm
{
  /// Prints "nsm-bar: STAGE: what" on stderr at most once per interval,
  /// the first line one interval after the stage began, so that short runs
  /// print nothing. An interval of 0 turns it off (Output/Progress every).
  class Progress
  {
  public:
    Progress(std::string stage, double interval_seconds);

    /// Builds and prints the line only when one is due.
    void update(const std::function<std::string()> &what);

  private:
    using Clock = std::chrono::steady_clock;
    std::string       stage_;
    double            interval_;
    Clock::time_point last_;
  };
} // namespace nsm
