#include <nsm/base/progress.h>

#include <iostream>

namespace nsm
{
  Progress::Progress(std::string stage, const double interval_seconds)
    : stage_(std::move(stage))
    , interval_(interval_seconds)
    , last_(Clock::now())
  {}

  void Progress::update(const std::function<std::string()> &what)
  {
    if (interval_ <= 0)
      return;
    const Clock::time_point now = Clock::now();
    if (std::chrono::duration<double>(now - last_).count() < interval_)
      return;
    last_ = now;
    std::cerr << "nsm-bar: " << stage_ << ": " << what() << std::endl;
  }
} // namespace nsm
