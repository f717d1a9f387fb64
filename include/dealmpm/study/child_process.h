#pragma once

#include <string>
#include <sys/types.h>
#include <vector>

namespace dealmpm
{
  /** How a child process ended. */
  struct ChildResult
  {
    int    exit_code   = -1; ///< -1 when killed by a signal
    int    signal      = 0;
    double peak_memory = 0; ///< resident set, MB
  };

  /** Start @p program with @p arguments, stdout and stderr into the files
   * given; returns the process id. Throws when it cannot be started. */
  pid_t
  start_child(const std::string              &program,
              const std::vector<std::string> &arguments,
              const std::string              &stdout_file,
              const std::string              &stderr_file);

  /** Wait for any child, at most @p timeout seconds (negative: no limit);
   * its pid and how it ended, or 0 when none ended in time. */
  pid_t
  wait_for_child(ChildResult &result, const double timeout = -1);
} // namespace dealmpm
