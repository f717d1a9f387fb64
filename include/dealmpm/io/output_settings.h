#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/scene_reader.h>

#include <string>

namespace dealmpm
{
  using namespace dealii;

  /** The "Output" section: where and how often a run writes, and its
   * progress line. */
  struct OutputSettings
  {
    std::string directory          = "output";
    double      interval           = 0.1;
    bool        write_particles    = true;
    bool        write_grid         = false;
    bool        write_particle_csv = false;
    double      progress_interval  = 5;
    bool        verbose = true; ///< not from the scene: tests run quietly

    /** Declare the section's entries. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check the section (the reader at the top level). */
    static OutputSettings
    read(SceneReader &reader);
  };
} // namespace dealmpm
