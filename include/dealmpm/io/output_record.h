#pragma once

#include <dealmpm/io/output_series.h>

#include <vector>

namespace dealmpm
{
  /**
   * What a run has written so far: the number of outputs (the next file's
   * counter), the last output's time and step, and the .pvd series. Part of
   * the run's state (core/run_state.h), so that a resumed run continues the
   * numbering and the series.
   */
  struct OutputRecord
  {
    unsigned int counter   = 0;
    double       last_time = 0;
    unsigned int last_step = 0;
    OutputSeries particle_series;
    OutputSeries grid_series;
    /** One per FEM region. */
    std::vector<OutputSeries> region_series;
    /** One per solid the effects draw (rigid_body_N). */
    std::vector<OutputSeries> body_series;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      // Needs <boost/serialization/vector.hpp>.
      archive &counter &last_time &last_step &particle_series &grid_series;
      archive &region_series                                  &body_series;
    }
  };
} // namespace dealmpm
