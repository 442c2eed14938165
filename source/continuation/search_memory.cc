#include <nsm/continuation/search_memory.h>

#include <utility>

namespace nsm
{
  const std::optional<BackbonePoint> &SearchMemory::solve(BranchContext &context, const double omega,
                                                          const SearchStart &start, const std::vector<double> &guess)
  {
    const auto known = solutions_.find(start);
    if (known != solutions_.end())
      return known->second;
    BackbonePoint                point;
    std::optional<BackbonePoint> solution;
    if (context.solve(omega, guess, 0, point, BranchContext::Newton::both))
      solution = std::move(point);
    return solutions_.emplace(start, std::move(solution)).first->second;
  }
} // namespace nsm
