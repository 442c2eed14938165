#include <nsm/base/interruption.h>

#include <csignal>

namespace nsm
{
  namespace
  {
    volatile std::sig_atomic_t requested = 0;
    volatile std::sig_atomic_t received  = 0; ///< stop signals so far (only the handler writes it)
    bool                       at_points = false;

    extern "C" void record_stop(const int signal)
    {
      requested = signal;
      received  = received + 1;
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

  int point_stop_signal() { return at_points ? requested : 0; }

  PointStopsDeferred::PointStopsDeferred()
    : was_enabled_(at_points)
  {
    at_points = false;
  }

  PointStopsDeferred::~PointStopsDeferred() { at_points = was_enabled_; }

  int stop_exit_code(const int signal) { return 128 + signal; }

  const char *stop_signal_name(const int signal)
  {
    return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : signal == SIGHUP ? "SIGHUP" : "a signal";
  }
} // namespace nsm
