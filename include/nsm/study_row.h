// One row of a study: a full run of the stages the study's measures need,
// for one combination of the swept parameters, with its errors against the
// exact references and its costs.
#pragma once

#include <nsm/scene.h>

#include <string>
#include <vector>

namespace nsm
{
  /// study.csv columns after the swept parameters', the last ones the
  /// main-branch energy at each of `study`'s Backbone omegas. peak_memory_mib
  /// is the row's peak resident memory above the process's at its start.
  /// Columns whose name starts with "wall_", "cpu_" or "peak_" are costs that
  /// vary between runs; every other column is reproducible.
  std::vector<std::string> study_row_columns(const StudyParameters &study);

  /// Runs `scene` (a study's combination) Study/Repeats times and returns
  /// the cells of study_row_columns(), as text. A numerical failure is
  /// reported in the row's status, its measures left empty.
  std::vector<std::string> measure_study_row(const Scene &scene);
} // namespace nsm
