// The memory a scene's run needs, estimated before any work, so that a
// scene the machine cannot hold is refused at once (exit 2) instead of
// running out of memory half-way.
#pragma once


#include <nsm/scene/discretisation_parameters.h>
#include <nsm/scene/resources_parameters.h>

#include <cstddef>
#include <string>

namespace nsm
{
  struct Scene;

  /// The memory a run needs at its peak, and its largest part.
  struct MemoryEstimate
  {
    double      bytes        = 0;
    double      largest_part = 0;
    std::string drivers; ///< the entries that set the largest part
  };

  /// The run of `scene`, an upper estimate: the mesh and the sparse
  /// stiffness and mass matrices (measured per cell and per nonzero on this
  /// code), the band factors, the receptance frequencies' rows, the harmonic
  /// balance's dense matrices and samples, the backbone's points (up to
  /// Continuation/Max steps) and the fields kept for output.
  MemoryEstimate estimated_memory(const Scene &scene);

  /// Bytes the run may use: Resources/Memory limit if set, else the memory
  /// the machine has available (MemAvailable), and never more than the
  /// process's address-space limit leaves.
  std::size_t available_memory(const ResourcesParameters &resources);

  /// Throws InputError, naming the entries that drive the estimate's largest
  /// part, if `need` is more than is available.
  void check_memory(const MemoryEstimate &need, const ResourcesParameters &resources);

  /// "memory: about N MiB estimated at the peak, M MiB available", for the
  /// run summary.
  std::string memory_note(const MemoryEstimate &need, const ResourcesParameters &resources);
} // namespace nsm
