#include <nsm/base/checkpoint_reader.h>
#include <nsm/base/errors.h>
#include <nsm/base/text.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <ios>

namespace nsm
{
  std::string exact(const double value)
  {
    std::ostringstream s;
    s << std::hexfloat << value;
    return s.str();
  }

  CheckpointReader::CheckpointReader(const std::string &path)
    : path_(path)
    , in_(path)
  {}

  std::string CheckpointReader::text_line()
  {
    std::string line;
    if (!std::getline(in_, line))
      damaged("it ends early");
    ++number_;
    return line;
  }

  void CheckpointReader::expect(const std::string &line)
  {
    if (text_line() != line)
      damaged("'" + line + "' expected");
  }

  std::istringstream CheckpointReader::next(const std::string &key)
  {
    const std::string line = text_line();
    if (line.compare(0, key.size(), key) != 0)
      damaged("'" + key + "' expected");
    return std::istringstream(line.substr(key.size()));
  }

  double CheckpointReader::number(std::istringstream &in)
  {
    std::string token;
    in >> token;
    char *end = nullptr;
    errno     = 0;
    const double value = std::strtod(token.c_str(), &end);
    if (token.empty() || *end != '\0' || errno != 0 || !std::isfinite(value))
      damaged("a finite number expected");
    return value;
  }

  std::size_t CheckpointReader::count(std::istringstream &in, const std::size_t limit)
  {
    const double value = number(in);
    if (!(value >= 0 && value <= static_cast<double>(limit)) || value != static_cast<std::size_t>(value))
      damaged("a count in [0, " + std::to_string(limit) + "] expected");
    return static_cast<std::size_t>(value);
  }

  void CheckpointReader::damaged(const std::string &why) const
  {
    throw InputError("command line: --resume: '" + printable(path_) + "' is not a checkpoint nsm-bar wrote (line " +
                     std::to_string(number_) + ": " + why + "): run the scene without --resume");
  }
} // namespace nsm
