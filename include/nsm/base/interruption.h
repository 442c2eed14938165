// A stop asked for by SIGINT (Ctrl-C) or SIGTERM, honoured at the next
// boundary where the work done so far can be kept whole (a study's row).
#pragma once

namespace nsm
{
  /// From now on SIGINT and SIGTERM only record that a stop was asked for;
  /// system calls they interrupt are restarted.
  void catch_stop_signals();

  /// The signal that asked for a stop; 0 if none did.
  int stop_signal();

  /// The exit code of a run stopped by `signal`: 128 + signal, as a shell
  /// reports a process the signal ended.
  int stop_exit_code(int signal);

  /// "SIGINT", "SIGTERM", or "signal N".
  const char *stop_signal_name(int signal);
} // namespace nsm
