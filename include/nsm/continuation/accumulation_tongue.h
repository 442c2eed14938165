// The climb into the accumulation point W_acc of the internal resonances
// (w_j / (2j - 1) -> W_acc) is the converged branch up to where the
// truncation sets its energy; that top is a tongue of the accumulation point,
// not the mode (doc/method.md, "The accumulation point").
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace nsm
{
  /// Names the climb's truncated top. Down in Omega from the last main point
  /// at or below W_acc, within W_acc (1 - accumulation_reach / M^2), the
  /// main points whose energy moves by more than Tongue share when the
  /// harmonics are halved (`estimates`, per point; NaN without one, passed
  /// over) mark M / 2's truncated zone, up to the first that does not; M's
  /// own zone reaches a quarter as deep below W_acc
  /// (halved_truncation_reach). The family's points (main and tongue) from
  /// there to where the accumulation point counts as passed
  /// (accumulation_passed) become tongue points of the accumulation point,
  /// one row of the tongues collected again. Nothing for a branch that
  /// does not cross W_acc (softening, or starting within W_acc (1 -
  /// accumulation_reach / M^2): the uniform bar's starts at W_acc) or without
  /// estimates. Returns the points it
  /// labelled (none when called again).
  std::size_t name_accumulation_tongue(Backbone &backbone, const std::vector<double> &estimates,
                                       const BranchParameters &params);

  /// The lowest and highest Omega of the points on the accumulation point's
  /// tongue (infinity and minus infinity if none).
  std::pair<double, double> accumulation_span(const std::vector<BackbonePoint> &points);
} // namespace nsm
