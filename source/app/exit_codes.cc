#include <nsm/app/exit_codes.h>
#include <nsm/base/assertions.h>
#include <nsm/base/errors.h>
#include <nsm/base/interruption.h>
#include <nsm/base/text.h>

#include <iostream>
#include <new>

namespace nsm
{
  void print_error(const std::string &kind, const std::string &what)
  {
    std::cerr << "nsm-bar: " << kind << printable(what) << '\n';
  }

  namespace
  {
    int internal_error(const std::string &what)
    {
      print_error("internal error (a bug in nsm-bar, not in the scene: please report it with the scene): ", what);
      return exit_codes::internal;
    }
  } // namespace

  int report_failure(const std::exception_ptr failure, const bool says_input_errors)
  {
    try
      {
        std::rethrow_exception(failure);
      }
    catch (const InputError &e)
      {
        if (says_input_errors)
          print_error("input error: ", e.what());
        return exit_codes::input;
      }
    catch (const StopRequested &e)
      {
        std::cerr << "nsm-bar: stopped by " << stop_signal_name(e.signal) << " in " << e.what()
                  << ", before any point was computed: no output written\n";
        return stop_exit_code(e.signal);
      }
    catch (const OutputError &e)
      {
        print_error("output error: ", e.what());
        return exit_codes::output;
      }
    catch (const NumericalError &e)
      {
        print_error("numerical failure: ", e.what());
        return exit_codes::numerical;
      }
    catch (const std::bad_alloc &)
      {
        print_error("output error: ", "out of memory (the machine's, or a limit on the process): reduce "
                                      "Discretisation/Cells or Degree, Harmonic balance/Harmonics, or the outputs");
        return exit_codes::output;
      }
    catch (const dealii::ExceptionBase &e)
      {
        if (is_logic_error(e))
          return internal_error(one_line_message(e));
        print_error("error: ", one_line_message(e));
        return exit_codes::other;
      }
    catch (const std::exception &e)
      {
        if (is_logic_error(e))
          return internal_error(e.what());
        print_error("error: ", e.what());
        return exit_codes::other;
      }
    catch (const char *message) // NOX throws these
      {
        print_error("numerical failure: ", message);
        return exit_codes::numerical;
      }
    catch (...)
      {
        print_error("error: ", "an exception of unknown type");
        return exit_codes::other;
      }
  }
} // namespace nsm
