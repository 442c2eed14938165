// The program's exit codes (doc/output.md) and the one line that says why a
// run failed, from the exception that ended it.
#pragma once

#include <exception>
#include <string>

namespace nsm
{
  namespace exit_codes
  {
    constexpr int done      = 0;
    constexpr int input     = 2; ///< bad input: the line names the parameter and its range
    constexpr int numerical = 3; ///< a numerical failure (a point that did not converge is never written)
    constexpr int other     = 4; ///< any other error (a library's)
    constexpr int output    = 5; ///< a file not written whole, memory run out, plots not drawn
    constexpr int internal  = 6; ///< a bug in nsm-bar: a failed check of its own logic (base/assertions.h)
  } // namespace exit_codes

  /// "nsm-bar: KIND: what" on stderr, `what` printable (a control character
  /// or a byte that is not UTF-8 from the user's input is escaped).
  void print_error(const std::string &kind, const std::string &what);

  /// Says in one line on stderr why `failure` ended the run and returns its
  /// exit code. Bad input is said only where `says_input_errors` (rank 0 of
  /// a study: every rank has the same).
  int report_failure(std::exception_ptr failure, bool says_input_errors = true);
} // namespace nsm
