// Text from the user, and numbers, as messages show them.
#pragma once

#include <cstddef>
#include <string>

namespace nsm
{
  /// `text` with each control character (newline, tab, NUL, DEL, and the C1
  /// controls U+0080 to U+009F such as CSI) and each byte that is not part of
  /// valid UTF-8 written as \xNN, so that a message that quotes it stays on
  /// one line, is valid text and moves no terminal's cursor.
  std::string printable(const std::string &text);

  /// Whether `text` holds a control character (C0, DEL or C1).
  bool has_control_character(const std::string &text);

  /// Whether `text` is valid UTF-8 (shortest forms, no surrogates): what a
  /// scene value must be, since deal.II's parameter tree and the JSON and XML
  /// it writes hold text only.
  bool is_valid_utf8(const std::string &text);

  /// Where the first byte of `text` that is not valid UTF-8 lies, or npos.
  std::size_t first_invalid_utf8(const std::string &text);

  /// `value` to `digits` significant digits, whatever its scale (energies go
  /// down to 1e-20 with small gaps), as messages and notes print numbers.
  std::string significant(double value, int digits);

  /// "1 restart", "2 restarts": `n` and `noun`, plural with an s.
  std::string counted(std::size_t n, const std::string &noun);
} // namespace nsm
