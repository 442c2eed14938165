// Text from the user, as messages show it.
#pragma once

#include <string>

namespace nsm
{
  /// `text` with each control character (newline, tab, NUL, ...) written as
  /// \xNN, so that a message that quotes it stays on one line.
  std::string printable(const std::string &text);

  /// Whether `text` holds a control character.
  bool has_control_character(const std::string &text);
} // namespace nsm
