// The code's checks of its own logic: deal.II's Assert, AssertDimension and
// AssertIndexRange on the kernels' preconditions (compiled in a Debug build,
// ./test.sh --debug; nothing in a Release build), and ExcPrecondition for
// the ones a size or an index does not state. A failed check is a bug in
// nsm-bar, not in the scene or the numerics: is_logic_error() says which
// exceptions are such, and the program exits with exit_codes::internal.
#pragma once

#include <deal.II/base/exceptions.h>

#include <exception>
#include <string>

namespace nsm
{
  /// A kernel's precondition that is not a size or an index.
  DeclException1(ExcPrecondition, std::string, << "precondition violated: " << arg1);

  /// Whether `e` reports a broken invariant of the code: std::logic_error
  /// (nsm::LogicError among them), ExcPrecondition, or the exceptions of
  /// deal.II's Assert family (a dimension, an index range, an internal error).
  bool is_logic_error(const std::exception &e);

  /// Failed Asserts throw instead of aborting the process, so that the
  /// program reports them in one line with its own exit code (Debug builds).
  void throw_on_failed_asserts();
} // namespace nsm
