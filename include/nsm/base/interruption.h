// A stop asked for by SIGINT (Ctrl-C), SIGTERM or SIGHUP, honoured at the next
// boundary where the work done so far can be kept whole: a study's row, or,
// in a single run, a point of the continuation.
#pragma once

namespace nsm
{
  /// From now on SIGINT, SIGTERM and SIGHUP only record that a stop was
  /// asked for; system calls they interrupt are restarted.
  void catch_stop_signals();

  /// The signal that asked for a stop; 0 if none did.
  int stop_signal();

  /// How many stop signals arrived so far: work that must answer a new one
  /// (the plots, drawn also after a stop) compares it with its start's.
  int stop_signals_received();

  /// Whether the continuation stops at its next point when a stop is asked
  /// for: a single run's does (it then writes what it has); a study's does
  /// not (its rows stop at row boundaries, whole).
  void stop_at_points(bool enabled);

  /// What a stop signal answers at once, on stderr: `first` on the first
  /// signal, `again` on each later one (nullptr: nothing); both must live to
  /// the end of the program. With `points_on_second_signal`, a second
  /// signal turns stop_at_points on (a study's current row stops at its next
  /// point).
  void acknowledge_stops(const char *first, const char *again, bool points_on_second_signal);

  /// The signal to stop at this point for; 0 if none, or if stop_at_points
  /// is off.
  int point_stop_signal();

  /// Within its lifetime, point_stop_signal() is 0: work nested in a
  /// continuation point (the branch with half the harmonics a leap asks
  /// for) runs whole, so that the point it serves is the one an
  /// uninterrupted run computes.
  class PointStopsDeferred
  {
  public:
    PointStopsDeferred();
    ~PointStopsDeferred();
    PointStopsDeferred(const PointStopsDeferred &) = delete;
    PointStopsDeferred &operator=(const PointStopsDeferred &) = delete;

  private:
    bool was_enabled_;
  };

  /// The exit code of a run stopped by `signal`: 128 + signal, as a shell
  /// reports a process the signal ended.
  int stop_exit_code(int signal);

  /// "SIGINT", "SIGTERM", "SIGHUP", or "a signal".
  const char *stop_signal_name(int signal);
} // namespace nsm
