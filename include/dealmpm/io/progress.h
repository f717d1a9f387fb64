#pragma once

#include <chrono>
#include <ostream>

namespace dealmpm
{
  /** A progress line (step, time, dt, percent, ETA) every few seconds of
   * wall time. */
  class Progress
  {
  public:
    Progress(std::ostream &out,
             const double  interval_seconds,
             const bool    active);

    void
    update(const unsigned int step,
           const double       time,
           const double       dt,
           const double       end_time,
           const double       n_particles);

    double
    elapsed_seconds() const;

  private:
    std::ostream                         &out;
    double                                interval;
    bool                                  active;
    std::chrono::steady_clock::time_point start;
    double                                last_print = 0;
  };
} // namespace dealmpm
