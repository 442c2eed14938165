#include <nsm/base/csv.h>

#include <deal.II/base/exceptions.h>
#include <nsm/base/errors.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <ext/stdio_filebuf.h>
#include <fcntl.h>

namespace nsm
{
  std::string write_csv(const std::string &directory, const CsvTable &table)
  {
    for (const auto &row : table.rows)
      for (const CsvCell &v : row)
        if (std::holds_alternative<double>(v) && !std::isfinite(std::get<double>(v)))
          throw NumericalError("a non-finite value was about to be written to " +
                               table.file_name + "; nothing was written");

    return write_atomically(directory + "/" + table.file_name, [&](std::ostream &out) {
      out.precision(std::numeric_limits<double>::max_digits10);
      for (std::size_t c = 0; c < table.columns.size(); ++c)
        out << (c ? "," : "") << table.columns[c];
      out << '\n';
      for (const auto &row : table.rows)
        {
          for (std::size_t c = 0; c < row.size(); ++c)
            {
              out << (c ? "," : "");
              std::visit([&](const auto &value) { out << value; }, row[c]);
            }
          out << '\n';
        }
    });
  }

  std::vector<std::string> split_fields(const std::string &text, const char delimiter)
  {
    std::vector<std::string> fields;
    std::stringstream        in(text);
    for (std::string field; std::getline(in, field, delimiter);)
      fields.push_back(field);
    if (!text.empty() && text.back() == delimiter)
      fields.emplace_back();
    return fields;
  }

  CsvTable read_csv(const std::string &path)
  {
    CsvTable      table{std::filesystem::path(path).filename(), {}, {}};
    std::ifstream in(path);
    std::string   line;
    if (!std::getline(in, line))
      return table;
    table.columns = split_fields(line, ',');
    while (std::getline(in, line))
      {
        std::vector<CsvCell> row;
        for (std::string &cell : split_fields(line, ','))
          row.emplace_back(std::move(cell));
        if (row.size() != table.columns.size())
          throw InputError(path + ": a row has " + std::to_string(row.size()) + " cells, the header " +
                           std::to_string(table.columns.size()));
        table.rows.push_back(std::move(row));
      }
    return table;
  }

  std::string write_atomically(const std::string                         &path,
                               const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".partial";
    std::error_code   error;
    // A leftover, or a link planted in its place, is removed (not followed),
    // and the file is made anew: never opened through a link.
    std::filesystem::remove(temporary, error);
    const int descriptor = open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (descriptor < 0)
      throw OutputError("cannot write " + path + ": " + std::strerror(errno));
    __gnu_cxx::stdio_filebuf<char> file(descriptor, std::ios::out);
    std::ostream                   out(&file);
    out.precision(17);
    try
      {
        write(out);
      }
    catch (const dealii::StandardExceptions::ExcIO &)
      {
        out.setstate(std::ios::failbit); // a writer that checks its stream (deal.II's VTU)
      }
    // The last buffer is written by close(): it is checked too.
    out.flush();
    const bool closed = file.close() != nullptr;
    if (out.fail() || !closed || (std::filesystem::rename(temporary, path, error), error))
      {
        std::filesystem::remove(temporary, error);
        throw OutputError("cannot write " + path + " whole (disk full or file size limit?)");
      }
    return path;
  }
} // namespace nsm
