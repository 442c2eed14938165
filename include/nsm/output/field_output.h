// Files of the mode fields: CSV at full precision, ParaView VTU/PVD through
// deal.II's DataOut, and the grids the plotting script reads.
#pragma once

#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/verification/fields.h>
#include <nsm/base/csv.h>

#include <string>
#include <vector>

namespace nsm
{
  struct FieldOutputOptions
  {
    unsigned int time_samples; ///< per period: CSV rows, snapshots, plots
    bool         vtk;
    bool         plots;
    /// The VTK files' time axis in periods (t / T, as the plots), not in t.
    bool vtk_time_over_period = false;
  };

  /// Writes field_<index>_* files; returns the paths written.
  std::vector<std::string> write_field(const std::string        &directory,
                                       unsigned int              index,
                                       const PeriodicField      &field,
                                       const Discretisation     &discretisation,
                                       const FieldOutputOptions &options);

  /// fields.csv (index, Omega, segment, energy) and, with VTK, fields.pvd
  /// (the space-time files over the backbone points, "time" = Omega).
  std::vector<std::string> write_field_collection(const std::string                &directory,
                                                  const std::vector<PeriodicField> &fields,
                                                  bool                              vtk);
} // namespace nsm
