#pragma once

namespace dealmpm
{
  /**
   * SIGTERM and SIGINT stop a run after its current step instead of killing
   * it: while an object of this class lives, their handlers only record the
   * signal, and the step loop asks stop_signal() (all ranks agree through a
   * reduction), writes a last output and ends; the program exits with
   * 128 + the signal. A second signal of either kind kills the process at
   * once (for a user who does not want to wait). The destructor restores
   * the handlers that were there before.
   */
  class StopSignalHandlers
  {
  public:
    StopSignalHandlers();
    ~StopSignalHandlers();

    StopSignalHandlers(const StopSignalHandlers &) = delete;
    StopSignalHandlers &
    operator=(const StopSignalHandlers &) = delete;
  };

  /** The signal received since the handlers were installed, or 0. */
  int
  stop_signal();

  /** For tests: raise SIGTERM in this process when the step loop is about
   * to take step @p step + 1 and the environment variable
   * DEALMPM_TERM_AT_STEP names @p step, so that a test can stop a run at a
   * step of its choice instead of at a moment a timer picks. */
  void
  test_term_at_step(const unsigned int step);

  /** "SIGTERM", "SIGINT" or "a signal". */
  const char *
  signal_name(const int signal);
} // namespace dealmpm
