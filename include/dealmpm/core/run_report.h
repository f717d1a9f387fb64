#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/run_messages.h>
#include <dealmpm/core/run_state.h>

#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealmpm
{
  /** A timer section of @p timer, or nothing while there is no timer yet
   * (during construction). */
  inline std::unique_ptr<TimerOutput::Scope>
  timed(TimerOutput *timer, const std::string &section)
  {
    return timer != nullptr ?
             std::make_unique<TimerOutput::Scope>(*timer, section) :
             nullptr;
  }

  /** The wall time of each set-up stage on this rank, taken while the
   * stages are built and the step's timer is not. */
  class SetupClock
  {
  public:
    /** Ends the current stage, named @p stage, and starts the next. */
    void
    lap(const std::string &stage)
    {
      const auto now = std::chrono::steady_clock::now();
      stages.emplace_back(stage,
                          std::chrono::duration<double>(now - last).count());
      last = now;
    }

    /** "set-up took 2.4 s: grid 0.6 s, particles 1.2 s, ...": each stage's
     * slowest rank, and their sum (collective). */
    std::string
    report(const MPI_Comm comm) const;

    std::vector<std::pair<std::string, double>> stages;

  private:
    std::chrono::steady_clock::time_point last =
      std::chrono::steady_clock::now();
  };

  /** @p error with where the last good output (at @p last_output_time)
   * is. */
  inline RunError
  with_last_output(const RunError    &error,
                   const double       last_output_time,
                   const std::string &directory)
  {
    return RunError(std::string(error.what()) + ". The last good output (t = " +
                    short_number(last_output_time) + ") is in " + directory +
                    "/");
  }

  /** The timer's table (on several ranks each section's least, mean and
   * most time over the ranks) and the closing line of a run: steps,
   * particle-steps per second per core, peak memory, and the counts of what
   * happened to the grid and the particles on the way (collective). */
  void
  print_run_summary(ConditionalOStream      &out,
                    TimerOutput             &timer,
                    const RunState          &loop,
                    const unsigned long long n_active_cells,
                    const MPI_Comm           comm);
} // namespace dealmpm
