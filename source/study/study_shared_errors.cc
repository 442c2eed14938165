#include <nsm/base/text.h>
#include <nsm/study/study_shared_errors.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace nsm
{
  namespace
  {
    /// Whether a row's energy errors are comparable: it measured some, and
    /// its continuation did not end inside the Backbone omegas.
    bool takes_part(const CsvTable &table, const std::vector<CsvCell> &row)
    {
      return !text_cell(row, column_of(table, "energy_error_max")).empty() &&
             text_cell(row, column_of(table, "energy_error_partial")) != "yes";
    }
  } // namespace

  void add_shared_errors(CsvTable &table, const std::vector<double> &omegas,
                         const std::vector<std::optional<double>> &reference)
  {
    // energy_at_<Omega> columns, one per Backbone omega, in order.
    std::size_t first = 0;
    while (first < table.columns.size() && table.columns[first].rfind("energy_at_", 0) != 0)
      ++first;
    std::vector<std::size_t> shared;
    for (std::size_t i = 0; i < omegas.size() && i < reference.size() && first + i < table.columns.size(); ++i)
      if (reference[i] && std::all_of(table.rows.begin(), table.rows.end(), [&](const std::vector<CsvCell> &row) {
            return !takes_part(table, row) || !text_cell(row, first + i).empty();
          }))
        shared.push_back(i);
    for (const std::string &c : shared_error_columns())
      table.columns.push_back(c);
    for (std::vector<CsvCell> &row : table.rows)
      {
        if (!takes_part(table, row) || shared.empty())
          {
            row.insert(row.end(), 3, std::string());
            continue;
          }
        std::vector<double> errors;
        for (const std::size_t i : shared)
          errors.push_back(std::abs(std::stod(text_cell(row, first + i)) / *reference[i] - 1));
        std::sort(errors.begin(), errors.end());
        row.push_back(std::to_string(shared.size()));
        row.push_back(significant(errors.back(), 17));
        row.push_back(significant(errors[errors.size() / 2], 17));
      }
  }
} // namespace nsm
