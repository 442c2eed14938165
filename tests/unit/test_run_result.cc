// The Result block's first line (app/run_result.h): where the branch was
// traced from grazing outside the scene's range, the line says so.
#include <nsm/app/run_result.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hb_model.h"

namespace
{
  /// The Result block's first line for two written points at 1.6 and 1.7 of a
  /// branch traced over `span`, the scene's range 1.5 to 2.2.
  std::string first_line(const std::pair<double, double> span)
  {
    const nsm::Scene    scene = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
    const nsm::BarModel bar(scene.bar);
    nsm::Backbone       backbone = testing_helpers::two_point_backbone();
    backbone.traced_span         = span;
    if (span.second > 0)
      backbone.traced_start = span.first;
    return nsm::backbone_result(backbone, bar, scene.contact, scene.continuation).front();
  }
} // namespace

TEST(RunResult, SaysWhereTheBranchWasTracedFromOutsideTheRange)
{
  const std::string note = "traced from grazing at Omega = 1.2, outside the range, and written from "
                           "Continuation/Omega min = 1.5 on";
  EXPECT_NE(first_line({1.2, 1.7}).find(note), std::string::npos) << first_line({1.2, 1.7});
  // Traced from inside the range, or with no span kept (a point written
  // first): no note.
  EXPECT_EQ(first_line({1.55, 1.7}).find("traced from grazing"), std::string::npos);
  EXPECT_EQ(first_line({0, 0}).find("traced from grazing"), std::string::npos);
  // The written points start the line either way.
  EXPECT_EQ(first_line({1.2, 1.7}).rfind("backbone from Omega = 1.6 to 1.7", 0), 0u);
}
