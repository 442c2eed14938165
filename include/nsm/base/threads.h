// The one thread every computing program runs deal.II on.
#pragma once

namespace nsm
{
  /// Limits deal.II to one thread, as a study's MPI_InitFinalize does: its
  /// FEValues gives other last bits with more threads (gradients with 2
  /// threads against 1, measured), so results would depend on the machine's
  /// cores, and a study's row would not be its scene's plain run bit for
  /// bit. These 1D problems gain no time from threads (prm/seed.prm: 0.53 s
  /// both ways). Every program that computes results calls it first.
  void use_one_thread();
} // namespace nsm
