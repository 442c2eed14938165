// Files a run writes: CSV tables written whole or not at all.
#pragma once

#include <algorithm>
#include <functional>
#include <iosfwd>
#include <string>
#include <variant>
#include <vector>

namespace nsm
{
  /// A number, or a label such as a branch name.
  using CsvCell = std::variant<double, std::string>;

  /// A table held in memory until it is written.
  struct CsvTable
  {
    std::string                       file_name;
    std::vector<std::string>          columns;
    std::vector<std::vector<CsvCell>> rows;
  };

  /// Writes `table` to directory/file_name with full double precision:
  /// first to a temporary file, then renamed, so no half-written file
  /// remains. Throws NumericalError if any value is not finite (a NaN is
  /// never written). Returns the path written.
  std::string write_csv(const std::string &directory, const CsvTable &table);

  /// The fields of `text` between `delimiter`s, empty ones included ("a,,"
  /// has three).
  std::vector<std::string> split_fields(const std::string &text, char delimiter);

  /// Reads a CSV file that write_csv wrote, every cell as text; a missing
  /// file gives a table without columns. Throws InputError if a row's
  /// length differs from the header's.
  CsvTable read_csv(const std::string &path);

  /// Cell c of a row that read_csv read: always text.
  inline const std::string &text_cell(const std::vector<CsvCell> &row, const std::size_t c)
  {
    return std::get<std::string>(row[c]);
  }

  /// The index of the column `name` of `table`; columns.size() if it has none.
  inline std::size_t column_of(const CsvTable &table, const std::string &name)
  {
    return std::find(table.columns.begin(), table.columns.end(), name) - table.columns.begin();
  }

  /// Writes `path` through `write` into path.partial, renamed to path once
  /// complete, so no half-written file remains. Returns the path.
  std::string write_atomically(const std::string                         &path,
                               const std::function<void(std::ostream &)> &write);
} // namespace nsm
