// The main-branch energy errors of a study's rows over the Backbone omegas
// they all share: rows that found the main branch at different Omegas (a gap,
// a tongue, another M) are compared on equal terms, not left out.
#pragma once

#include <nsm/base/csv.h>

#include <optional>
#include <vector>

namespace nsm
{
  /// The columns add_shared_errors appends to study.csv, last.
  inline const std::vector<std::string> &shared_error_columns()
  {
    static const std::vector<std::string> columns = {"shared_omegas", "energy_error_max_shared",
                                                     "energy_error_median_shared"};
    return columns;
  }

  /// Appends shared_error_columns() to every row of `table` (study.csv's,
  /// cells as text): the Backbone omegas (`omegas`, whose energies are the
  /// table's energy_at_ columns, in order) where the reference (`reference`)
  /// and every row that measured an energy error and ended beyond them
  /// (energy_error_partial = no) have a main-branch energy, counted; and each
  /// such row's largest and median relative energy error there. Empty where
  /// the row takes no part or no Omega is shared.
  void add_shared_errors(CsvTable &table, const std::vector<double> &omegas,
                         const std::vector<std::optional<double>> &reference);
} // namespace nsm
