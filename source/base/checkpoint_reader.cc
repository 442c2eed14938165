#include <nsm/base/checkpoint_reader.h>
#include <nsm/base/csv.h>
#include <nsm/base/errors.h>
#include <nsm/base/text.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <ios>

namespace nsm
{
  std::string exact(const double value)
  {
    std::ostringstream s;
    s << std::hexfloat << value;
    return s.str();
  }

  namespace
  {
    constexpr const char *checksum_key = "checksum ";

    std::string checksum_line(const std::string &text)
    {
      char line[48];
      std::snprintf(line, sizeof line, "%s%016llx\n", checksum_key,
                    static_cast<unsigned long long>(fnv1a(text.data(), text.size())));
      return line;
    }

    /// Where the checksum line of `text` starts: after its last but one
    /// newline (the text before it is what was hashed).
    std::size_t checksum_start(const std::string &text)
    {
      const std::size_t last = text.size() < 2 ? std::string::npos : text.rfind('\n', text.size() - 2);
      return last == std::string::npos ? 0 : last + 1;
    }

    std::string whole_file(std::ifstream &file)
    {
      std::ostringstream whole;
      whole << file.rdbuf();
      return whole.str();
    }
  } // namespace

  std::uint64_t fnv1a(const void *bytes, const std::size_t size, std::uint64_t hash)
  {
    const auto *byte = static_cast<const unsigned char *>(bytes);
    for (std::size_t i = 0; i < size; ++i)
      hash = (hash ^ byte[i]) * 1099511628211ull;
    return hash;
  }

  std::string write_checksummed(const std::string &path, const std::function<void(std::ostream &)> &write)
  {
    std::ostringstream text;
    write(text);
    return write_atomically(path, [&](std::ostream &out) { out << text.str() << checksum_line(text.str()); });
  }

  std::uint64_t text_hash(const std::string &path)
  {
    std::ifstream file(path);
    if (!file)
      return 0;
    const std::string text = whole_file(file);
    return fnv1a(text.data(), checksum_start(text));
  }

  CheckpointReader::CheckpointReader(const std::string &path)
    : path_(path)
  {
    std::ifstream file(path);
    if (!(opened_ = static_cast<bool>(file)))
      return;
    const std::string text = whole_file(file);
    const std::size_t body = checksum_start(text);
    intact_                = text.compare(body, std::string::npos, checksum_line(text.substr(0, body))) == 0;
    in_.str(text.substr(0, body));
  }

  std::string CheckpointReader::text_line()
  {
    if (!intact_)
      throw InputError("command line: --resume: '" + printable(path_) +
                       "' is not a checkpoint nsm-bar wrote whole (its checksum does not match its text: the file "
                       "was damaged or edited): run the scene without --resume");
    std::string line;
    if (!std::getline(in_, line))
      damaged("it ends early");
    ++number_;
    return line;
  }

  std::string CheckpointReader::text_read()
  {
    const std::streamoff read = in_.tellg();
    return in_.str().substr(0, read < 0 ? in_.str().size() : static_cast<std::size_t>(read));
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
