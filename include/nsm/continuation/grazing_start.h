// The first point of a branch: just beyond the grazing of clamped-free mode
// Continuation/Mode (above w_j with the physical sign, below with eq. (5)),
// from an impulsive-contact guess, moving away until Newton converges.
#pragma once

#include <nsm/continuation/branch_context.h>

namespace nsm
{
  /// The start point, recorded in the run summary; sets the context's span.
  /// Throws InputError for a mode beyond the spectrum or a grazing energy
  /// above Energy max, NumericalError if nothing converges within 5 % of w_j.
  BackbonePoint start_at_grazing(BranchContext &context, Backbone &backbone);
} // namespace nsm
