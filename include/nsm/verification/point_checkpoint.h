// The per-point lines of a checkpoint of backbone points (verification.resume,
// refinement.resume): "point INDEX OMEGA ..." up to "end".
#pragma once

#include <nsm/base/checkpoint_reader.h>
#include <nsm/continuation/backbone.h>

#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace nsm
{
  /// Writes the point lines and "end": for each point held, "point INDEX
  /// OMEGA" (exact) and what write(point) adds to the line.
  template <typename T, typename Write>
  void write_point_lines(std::ostream &out, const Backbone &backbone, const std::vector<std::optional<T>> &points,
                         Write &&write)
  {
    for (std::size_t i = 0; i < points.size(); ++i)
      if (points[i])
        {
          out << "point " << i << ' ' << exact(backbone.points[i].omega);
          write(*points[i]);
          out << '\n';
        }
    out << "end\n";
  }

  /// Starts reading a point checkpoint: false if there is no file; else the
  /// format line checked, and the numbers of its "settings" line in
  /// `settings`.
  inline bool start_point_checkpoint(CheckpointReader &reader, const std::string &format_line,
                                     std::istringstream &settings)
  {
    if (!reader.opened())
      return false;
    reader.expect(format_line);
    settings = reader.next("settings ");
    return true;
  }

  /// Reads the point lines up to "end": for each, checks that INDEX is a
  /// point of `backbone` with that OMEGA (exact) and calls read(index, rest),
  /// `rest` the line's remaining numbers. A line that is not one refuses the
  /// file (CheckpointReader::damaged).
  template <typename Read>
  void read_point_lines(CheckpointReader &reader, const Backbone &backbone, Read &&read)
  {
    const std::string key = "point ";
    for (std::string line = reader.text_line(); line != "end"; line = reader.text_line())
      {
        if (line.compare(0, key.size(), key) != 0)
          reader.damaged("'point' or 'end' expected");
        std::istringstream row(line.substr(key.size()));
        const std::size_t  i = reader.count(row, backbone.points.size());
        if (i == backbone.points.size() || reader.number(row) != backbone.points[i].omega)
          reader.damaged("a point of the resumed backbone expected");
        read(i, row);
      }
  }
} // namespace nsm
