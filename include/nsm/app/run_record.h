// The record every output folder holds of how it was made: the command line,
// the code's version, deal.II's and Trilinos's, the date and the machine.
#pragma once

#include <string>
#include <vector>

namespace nsm
{
  /// The command line as a shell would take it back (each argument quoted
  /// where it needs to be, control characters and bytes that are not UTF-8
  /// shown as \xNN).
  std::string quoted_command_line(const std::vector<std::string> &arguments);

  /// The record's opening lines, one fact per line ("command: ...",
  /// "version: ...", "deal.II: ...", "Trilinos: ...", "date: ...",
  /// "machine: ..."), for the command line `command_line`.
  std::string record_header(const std::string &command_line);
} // namespace nsm
