// Reading back a checkpoint nsm-bar wrote for --resume (continuation.resume,
// verification.resume): its lines one at a time, numbers in hexadecimal
// floating point. A line that is not what the writer wrote is refused with
// an InputError naming --resume, the file and the line.
#pragma once

#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>

namespace nsm
{
  /// `value` in hexadecimal floating point: exact, and read back by
  /// CheckpointReader::number.
  std::string exact(double value);

  class CheckpointReader
  {
  public:
    explicit CheckpointReader(const std::string &path);

    /// Whether the file could be opened.
    bool opened() const { return static_cast<bool>(in_); }

    /// The next line whole.
    std::string text_line();

    /// The next line, which must be `line` (a format line).
    void expect(const std::string &line);

    /// The next line, which must start with `key`: the rest of it.
    std::istringstream next(const std::string &key);

    /// The next token of `in`: a finite number.
    double number(std::istringstream &in);

    /// The next token of `in`: a whole number in [0, limit].
    std::size_t count(std::istringstream &in, std::size_t limit);

    [[noreturn]] void damaged(const std::string &why) const;

  private:
    std::string   path_;
    std::ifstream in_;
    unsigned int  number_ = 0; ///< lines read
  };
} // namespace nsm
