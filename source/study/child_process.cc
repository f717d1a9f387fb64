#include <dealmpm/study/child_process.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>

extern char **environ;

namespace dealmpm
{
  pid_t
  start_child(const std::string              &program,
              const std::vector<std::string> &arguments,
              const std::string              &stdout_file,
              const std::string              &stderr_file)
  {
    std::vector<char *> argv;
    argv.push_back(const_cast<char *>(program.c_str()));
    for (const auto &a : arguments)
      argv.push_back(const_cast<char *>(a.c_str()));
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions,
                                     STDOUT_FILENO,
                                     stdout_file.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(&actions,
                                     STDERR_FILENO,
                                     stderr_file.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    pid_t     pid;
    const int status = posix_spawn(
      &pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (status != 0)
      throw std::runtime_error("cannot start " + program + ": " +
                               std::strerror(status));
    return pid;
  }

  pid_t
  wait_for_child(ChildResult &result, const double timeout)
  {
    int           status = 0;
    struct rusage usage;
    pid_t         pid;
    const auto    deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration<double>(std::max(timeout, 0.));
    while (true)
      {
        pid = wait4(-1, &status, timeout < 0 ? 0 : WNOHANG, &usage);
        if (pid < 0 && errno == EINTR)
          continue;
        if (pid != 0)
          break;
        if (std::chrono::steady_clock::now() >= deadline)
          return 0;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    if (pid < 0)
      throw std::runtime_error(std::string("waiting for a run: ") +
                               std::strerror(errno));
    result             = ChildResult();
    result.peak_memory = usage.ru_maxrss / 1024.; // kB on Linux
    if (WIFEXITED(status))
      result.exit_code = WEXITSTATUS(status);
    else if (WIFSIGNALED(status))
      result.signal = WTERMSIG(status);
    return pid;
  }
} // namespace dealmpm
