#include <nsm/base/text.h>
#include <nsm/output/floquet_report.h>

#include <map>

namespace nsm
{
  std::string floquet_summary(const std::vector<ForcedCurve> &curves, const ForcedVerifications &verifications)
  {
    unsigned int                        points = 0, converged = 0, settled = 0, agree = 0;
    std::map<std::string, unsigned int> outside;
    for (std::size_t c = 0; c < verifications.size(); ++c)
      for (std::size_t i = 0; i < verifications[c].size(); ++i)
        if (const auto &v = verifications[c][i]; v && v->floquet)
          {
            ++points;
            if (!v->floquet->converged())
              continue;
            ++converged;
            settled += v->floquet->from_settled ? 1 : 0;
            agree += (v->floquet->beyond_plus_one() % 2 == 1) == !curves[c].points[i].stable;
            if (const std::string kind = v->floquet->instability(); !kind.empty())
              ++outside[kind];
          }
    if (points == 0)
      return "";
    unsigned int unstable = 0;
    std::string  kinds;
    for (const auto &[kind, count] : outside)
      {
        unstable += count;
        kinds += (kinds.empty() ? "" : ", ") + std::to_string(count) + " " + kind;
      }
    return "forced response's Floquet multipliers (the stepped model's orbit by shooting from each point verified, "
           "compliant wall): " +
           std::to_string(points) + " points, the shooting converged at " + std::to_string(converged) +
           (settled > 0 ? " (" + std::to_string(settled) +
                            " of them from where the integration in time ended, the point's own start stalling)" :
                          std::string()) +
           "; " +
           std::to_string(unstable) + " with a multiplier outside the unit circle" +
           (kinds.empty() ? "" : " (the largest: " + kinds + ")") +
           "; the fold test agrees (an odd number of real multipliers beyond +1 where det J < 0) at " +
           std::to_string(agree) + " of " + std::to_string(converged);
  }

  std::vector<std::string> floquet_events(const std::vector<ForcedCurve> &curves,
                                          const ForcedVerifications      &verifications)
  {
    std::vector<std::string> events;
    for (std::size_t c = 0; c < verifications.size(); ++c)
      {
        const ForcedPoint        *before = nullptr;
        const FloquetMultipliers *last   = nullptr;
        for (std::size_t i = 0; i < verifications[c].size(); ++i)
          {
            const auto &v = verifications[c][i];
            if (!v || !v->floquet || !v->floquet->converged())
              continue;
            const ForcedPoint &p = curves[c].points[i];
            if (last && last->instability() != v->floquet->instability())
              events.push_back(
                curve_name(curves[c]) + ": Floquet, " +
                (v->floquet->instability().empty() ? std::string("every multiplier back inside the unit circle") :
                                                     "the largest multiplier outside the unit circle (" +
                                                       v->floquet->instability() + ", modulus " +
                                                       significant(v->floquet->largest(), 7) + ")") +
                " between Omega " + significant(before->omega, 7) + " and " + significant(p.omega, 7));
            before = &p;
            last   = &*v->floquet;
          }
      }
    return events;
  }
} // namespace nsm
