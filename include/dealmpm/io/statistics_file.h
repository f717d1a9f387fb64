#pragma once

#include <dealmpm/diagnostics/accuracy_report.h>
#include <dealmpm/diagnostics/statistics.h>

#include <string>

namespace dealmpm
{
  /**
   * statistics.csv: one row per output step, named columns. Each row is
   * appended with one write and so is on disk when a run stops; a row that
   * cannot be written whole (a full disk) is cut off again, so that the
   * file never ends in half a row. Rank 0 writes; failures throw
   * OutputError naming the file and the reason.
   */
  class StatisticsFile
  {
  public:
    /** Create the file with its header. The columns that not every scene
     * has come with the first statistics: dissipated_work (a material
     * dissipates), error_L2,error_max (an exact solution). With
     * @p keep_up_to_step >= 0 (a resumed run) an existing file with the
     * same header keeps its rows up to that step and is appended to. */
    StatisticsFile(const std::string &path,
                   const unsigned int dim,
                   const Statistics  &first,
                   const long long    keep_up_to_step = -1);

    ~StatisticsFile();

    StatisticsFile(const StatisticsFile &) = delete;
    StatisticsFile &
    operator=(const StatisticsFile &) = delete;

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
    void
    append(const std::string &text);

    std::string  path;
    int          fd   = -1;
    std::size_t  size = 0; ///< bytes of complete rows so far
    unsigned int dim;
    bool         errors;
    bool         dissipated_work;
  };
} // namespace dealmpm
