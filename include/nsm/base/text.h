// Text from the user, and numbers, as messages show them.
#pragma once

#include <string>

namespace nsm
{
  /// `text` with each control character (newline, tab, NUL, ...) written as
  /// \xNN, so that a message that quotes it stays on one line.
  std::string printable(const std::string &text);

  /// Whether `text` holds a control character.
  bool has_control_character(const std::string &text);

  /// `value` to `digits` significant digits, whatever its scale (energies go
  /// down to 1e-20 with small gaps), as messages and notes print numbers.
  std::string significant(double value, int digits);
} // namespace nsm
