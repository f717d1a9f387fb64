#include <dealmpm/core/stop_signal.h>

#include <csignal>
#include <cstdlib>

namespace dealmpm
{
  namespace
  {
    // Only lock-free atomic or sig_atomic_t objects may be touched in a
    // handler.
    volatile std::sig_atomic_t received = 0;

    extern "C" void
    record_signal(int signal)
    {
      if (received != 0)
        {
          // The second one: the default action (termination).
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      received = signal;
    }

    struct sigaction previous_term, previous_int;
  } // namespace

  StopSignalHandlers::StopSignalHandlers()
  {
    received                = 0;
    struct sigaction action = {};
    action.sa_handler       = record_signal;
    sigemptyset(&action.sa_mask);
    // Restart interrupted system calls (file writes, MPI's polling).
    action.sa_flags = SA_RESTART;
    sigaction(SIGTERM, &action, &previous_term);
    sigaction(SIGINT, &action, &previous_int);
  }

  StopSignalHandlers::~StopSignalHandlers()
  {
    sigaction(SIGTERM, &previous_term, nullptr);
    sigaction(SIGINT, &previous_int, nullptr);
  }

  int
  stop_signal()
  {
    return received;
  }

  void
  test_term_at_step(const unsigned int step)
  {
    static const char *when = std::getenv("DEALMPM_TERM_AT_STEP");
    if (when != nullptr && std::strtoul(when, nullptr, 10) == step)
      std::raise(SIGTERM);
  }

  const char *
  signal_name(const int signal)
  {
    switch (signal)
      {
        case SIGTERM:
          return "SIGTERM";
        case SIGINT:
          return "SIGINT";
        default:
          return "a signal";
      }
  }
} // namespace dealmpm
