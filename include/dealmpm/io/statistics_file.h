#pragma once

#include <dealmpm/core/accuracy_report.h>
#include <dealmpm/core/statistics.h>

#include <fstream>
#include <string>

namespace dealmpm
{
  /** statistics.csv: one row per output step, named columns, flushed at
   * every row so that it is complete when a run stops. Rank 0 writes. */
  class StatisticsFile
  {
  public:
    /** @p errors: add error_L2,error_max (scenes with an exact solution). */
    StatisticsFile(const std::string &path,
                   const unsigned int dim,
                   const bool         errors,
                   const bool         writer);

    void
    write_row(const unsigned int    step,
              const double          time,
              const double          dt,
              const Statistics     &s,
              const double          external_work,
              const AccuracyReport &accuracy,
              const double          n_lost_particles,
              const double          wall_time);

  private:
    std::ofstream out;
    unsigned int  dim;
    bool          errors;
  };
} // namespace dealmpm
