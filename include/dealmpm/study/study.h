#pragma once

#include <deal.II/base/parameter_handler.h>

#include <limits>
#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /** One run of a study: its settings, then what it gave. */
  struct StudyRun
  {
    unsigned int index      = 0;
    unsigned int refinement = 0;
    double       h          = 0; ///< cell size (relative when not known)
    unsigned int particles_per_cell = 0;
    std::string  formulation, shape_function, stress_update, velocity_update;
    double       cfl_number = 0;
    /** Adaptivity on: cells with particles one level finer than the
     * run's refinement, the others at it. */
    bool        adaptive = false;
    std::string folder;

    std::string status = "not run"; ///< ok | stopped | failed
    std::string reason;
    /** NaN until known (a run that failed early has none of them). */
    static constexpr double unknown = std::numeric_limits<double>::quiet_NaN();
    double error_L2 = unknown, error_max = unknown, wall_time = unknown,
           steps = unknown, particles = unknown,
           particle_steps_per_second = unknown, peak_memory = unknown,
           energy_drift = unknown, momentum_drift = unknown, min_J = unknown,
           max_cfl      = unknown;
    bool pareto_optimal = false;
  };

  /** The entries of a study file (subsection "Study"). */
  void
  declare_study_parameters(ParameterHandler &prm);

  /**
   * dealmpm --study: run every combination of the study's axes on its base
   * scene as separate dealmpm processes (@p program, up to @p jobs at once;
   * 0 takes the file's value), each in its own folder, and write study.csv,
   * study.md and, with @p plot_script (python3 and matplotlib), the plots.
   * Runs that fail or stop are rows with their reason. Returns the exit code
   * (0 once the study is written, even with failed runs; 2 for bad input).
   */
  int
  run_study(const std::string &study_file,
            const unsigned int jobs,
            const std::string &program,
            const std::string &plot_script);

  /** study.csv and study.md for finished runs (Pareto marks set here). */
  void
  write_study_tables(std::vector<StudyRun> &runs,
                     const std::string     &folder,
                     const std::string     &title);
} // namespace dealmpm
