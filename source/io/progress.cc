#include <dealmpm/io/progress.h>

#include <cmath>
#include <cstdio>

namespace dealmpm
{
  Progress::Progress(std::ostream &out,
                     const double  interval_seconds,
                     const bool    active)
    : out(out)
    , interval(interval_seconds)
    , active(active)
    , start(std::chrono::steady_clock::now())
  {}

  double
  Progress::elapsed_seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
      .count();
  }

  void
  Progress::update(const unsigned int step,
                   const double       time,
                   const double       dt,
                   const double       end_time,
                   const double       n_particles)
  {
    if (!active || interval <= 0)
      return;
    const double now = elapsed_seconds();
    if (now - last_print < interval)
      return;
    last_print            = now;
    const double fraction = end_time > 0 ? std::min(1., time / end_time) : 1.;
    const double remaining =
      fraction > 0 ? now * (1. - fraction) / fraction : 0.;
    const long eta = std::lround(remaining);
    char       line[200];
    std::snprintf(
      line,
      sizeof(line),
      "step %7u  t = %.4e / %.4e  dt = %.3e  %5.1f%%  ETA %ld:%02ld:%02ld  "
      "particles %.0f",
      step,
      time,
      end_time,
      dt,
      100. * fraction,
      eta / 3600,
      (eta / 60) % 60,
      eta % 60,
      n_particles);
    out << line << std::endl;
  }
} // namespace dealmpm
