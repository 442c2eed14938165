#include <nsm/base/interruption.h>

#include <csignal>
#include <cstring>

#include <unistd.h>

namespace nsm
{
  namespace
  {
    volatile std::sig_atomic_t requested = 0;
    volatile std::sig_atomic_t received  = 0; ///< stop signals so far (only the handler writes it)
    volatile std::sig_atomic_t at_points = 0;
    bool                       points_on_second = false;
    const char                *first_message = nullptr, *again_message = nullptr;
    std::size_t                first_length = 0, again_length = 0;

    extern "C" void record_stop(const int signal)
    {
      requested = signal;
      received  = received + 1;
      if (received > 1 && points_on_second)
        at_points = 1;
      // write() is async-signal-safe; the messages were measured beforehand.
      const char       *message = received == 1 ? first_message : again_message;
      const std::size_t length  = received == 1 ? first_length : again_length;
      if (message != nullptr && write(STDERR_FILENO, message, length) < 0)
        return; // stderr is gone: nothing to say it on
    }
  } // namespace

  void catch_stop_signals()
  {
    struct sigaction action = {};
    action.sa_handler       = record_stop;
    action.sa_flags         = SA_RESTART;
    sigemptyset(&action.sa_mask);
    // A closed terminal or a dropped SSH session (SIGHUP) stops a run like
    // Ctrl-C: what was computed is kept.
    for (const int signal : {SIGINT, SIGTERM, SIGHUP})
      sigaction(signal, &action, nullptr);
  }

  int stop_signal() { return requested; }

  int stop_signals_received() { return received; }

  void stop_at_points(const bool enabled) { at_points = enabled; }

  void acknowledge_stops(const char *first, const char *again, const bool points_on_second_signal)
  {
    first_message    = first;
    again_message    = again;
    first_length     = first ? std::strlen(first) : 0;
    again_length     = again ? std::strlen(again) : 0;
    points_on_second = points_on_second_signal;
  }

  int point_stop_signal() { return at_points ? requested : 0; }

  PointStopsDeferred::PointStopsDeferred()
    : was_enabled_(at_points != 0)
  {
    at_points = 0;
  }

  PointStopsDeferred::~PointStopsDeferred() { at_points = was_enabled_; }

  int stop_exit_code(const int signal) { return 128 + signal; }

  const char *stop_signal_name(const int signal)
  {
    return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : signal == SIGHUP ? "SIGHUP" : "a signal";
  }
} // namespace nsm
