// The kinds of failure a run reports, each with its own exit code
// (app/exit_codes.h): bad input (2), a numerical failure (3), an output
// error (5), a bug in nsm-bar itself (6).
#pragma once

#include <stdexcept>
#include <string>

namespace dealii
{
  class ExceptionBase;
} // namespace dealii

namespace nsm
{
  /// Bad input: the message names the parameter and the allowed range.
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Bad input of one kind: the Omega range holds none of the backbone's
  /// branch (it leaves grazing beyond the range's far end). A forced scene
  /// says that its curves need no backbone (app/pipeline.cc).
  class RangeOutsideBranch : public InputError
  {
  public:
    using InputError::InputError;
  };

  /// A file could not be written whole (disk full, file size limit, ...).
  class OutputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// A numerical failure that the run cannot recover from.
  class NumericalError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// A stop signal that arrived in a stage before the first point of the
  /// continuation (the search for the band's cells): nothing is computed yet
  /// that could be kept, so the run ends with no output (exit 128 + signal).
  class StopRequested : public std::runtime_error
  {
  public:
    StopRequested(const int signal, const std::string &stage)
      : std::runtime_error(stage)
      , signal(signal)
    {}
    int signal;
  };

  /// A broken invariant of nsm-bar's own logic: a bug, not the scene's or
  /// the numerics' fault (base/assertions.h).
  class LogicError : public std::logic_error
  {
  public:
    using std::logic_error::logic_error;
  };

  /// A deal.II exception's own message (without its banner) on one line.
  std::string one_line_message(const dealii::ExceptionBase &e);
} // namespace nsm
