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

  /// Bytes the run of `scene` needs at its peak, an upper estimate: the mesh
  /// and the sparse stiffness and mass matrices (measured per cell and per
  /// nonzero on this code), the band factors, the harmonic balance's dense
  /// matrices and samples, and the fields kept for output.
  std::size_t estimated_memory(const Scene &scene);

  /// Bytes the run may use: Resources/Memory limit if set, else the memory
  /// the machine has available (MemAvailable), and never more than the
  /// process's address-space limit leaves.
  std::size_t available_memory(const ResourcesParameters &resources);

  /// Throws InputError, naming the entries that drive the estimate (`d`'s
  /// Cells and Degree), if `need` bytes are more than is available.
  void check_memory(std::size_t need, const ResourcesParameters &resources, const DiscretisationParameters &d);

  /// "memory: about N MiB estimated at the peak, M MiB available", for the
  /// run summary.
  std::string memory_note(std::size_t need, const ResourcesParameters &resources);
} // namespace nsm
