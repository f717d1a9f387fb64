#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/scene_reader.h>

#include <string>

namespace dealmpm
{
  using namespace dealii;

  /**
   * The "Time" section: how long a run lasts and how its step is chosen
   * (the CFL step dt = C min_p h / (c_p + |v_p|), recomputed every step, or
   * a fixed one).
   */
  struct TimeStepping
  {
    double       end_time        = 1;
    bool         cfl_time_step   = true;
    double       fixed_time_step = 1e-3;
    double       cfl_number      = 0.5;
    unsigned int max_steps       = 0; ///< 0: no limit

    /** Declare the section's entries. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check the section (the reader at the top level). */
    static TimeStepping
    read(SceneReader &reader);

    /** Whether a run at @p time after @p step steps is done. */
    bool
    finished(const double time, const unsigned int step) const
    {
      return !(time < end_time - 1e-9 * end_time) ||
             (max_steps != 0 && step >= max_steps);
    }
  };
} // namespace dealmpm
