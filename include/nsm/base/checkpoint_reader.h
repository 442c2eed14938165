// Reading back a checkpoint nsm-bar wrote for --resume (continuation.resume,
// verification.resume, refinement.resume): its lines one at a time, numbers
// in hexadecimal floating point. The file ends in a checksum of all its
// text; a file whose checksum does not match, or a line that is not what
// the writer wrote, is refused with an InputError naming --resume, the file
// and the line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <sstream>
#include <string>

namespace nsm
{
  /// `value` in hexadecimal floating point: exact, and read back by
  /// CheckpointReader::number.
  std::string exact(double value);

  /// 64-bit FNV-1a of `size` bytes, continuing from `hash`: a change of any
  /// one byte changes it (each step is a bijection of the state).
  std::uint64_t fnv1a(const void *bytes, std::size_t size, std::uint64_t hash = 14695981039346656037ull);

  /// Writes a checkpoint whole (write_atomically): the text `write` makes,
  /// then "checksum H", H its FNV-1a hash in hexadecimal. Returns the path.
  std::string write_checksummed(const std::string &path, const std::function<void(std::ostream &)> &write);

  /// The text of the checkpoint at `path` before its checksum line, hashed
  /// (fnv1a); 0 if it cannot be read.
  std::uint64_t text_hash(const std::string &path);

  class CheckpointReader
  {
  public:
    explicit CheckpointReader(const std::string &path);

    /// Whether the file could be opened.
    bool opened() const { return opened_; }

    /// The next line whole.
    std::string text_line();

    /// The text of the lines read so far.
    std::string text_read();

    /// Whether every line before the checksum was read.
    bool finished() { return in_.peek() == std::char_traits<char>::eof(); }

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
    std::string        path_;
    bool               opened_ = false;
    bool               intact_ = false; ///< its checksum matches its text
    std::istringstream in_;             ///< the text before the checksum line
    unsigned int       number_ = 0;     ///< lines read
  };
} // namespace nsm
