// The record every output folder holds of how it was made: the command line,
// the code's version, deal.II's and Trilinos's, the date and the machine.
#pragma once

#include <nsm/output/run_report.h>

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

  /// Writes summary.txt at `path` (whole, or not at all): the record's
  /// header for `command_line`, then the summary `report` as printed, with
  /// the continuation's events.
  void write_summary(const std::string &path, const std::string &command_line, const RunReport &report);
} // namespace nsm
