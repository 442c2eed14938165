// One row of a study: a full run of the stages the study's measures need,
// for one combination of the swept parameters, with its errors against the
// exact references and its costs.
#pragma once

#include <nsm/study/study_parameters.h>

#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  /// What a study measures of the main branch at one Omega.
  struct MainBranchPoint
  {
    double energy, max_contact_force, contact_fraction;
  };

  /// The fine backbone reference: its name, and its main-branch points at
  /// the study's Backbone omegas (empty where it found none).
  struct FineReference
  {
    std::string                                 name;
    std::vector<std::optional<MainBranchPoint>> points;
  };

  /// Runs `scene`'s backbone and returns its main-branch points at the
  /// study's Backbone omegas.
  std::vector<std::optional<MainBranchPoint>> main_branch_at(const StudyScene &row);

  /// study.csv columns after the swept parameters', the last ones the
  /// main-branch energy at each of `study`'s Backbone omegas. peak_memory_mib
  /// is the row's peak resident memory above the process's at its start.
  /// Columns whose name starts with "wall_", "cpu_" or "peak_" are costs that
  /// vary between runs; every other column is reproducible.
  std::vector<std::string> study_row_columns(const StudyParameters &study);

  /// Runs `scene` (a study's combination) Study/Repeats times and returns
  /// the cells of study_row_columns(), as text. Backbone errors are against
  /// the bar's exact mode if it has one, else against `fine` if given. A
  /// numerical failure is reported in the row's status, its measures left
  /// empty.
  std::vector<std::string> measure_study_row(const StudyScene &row, const FineReference *fine = nullptr);
} // namespace nsm
