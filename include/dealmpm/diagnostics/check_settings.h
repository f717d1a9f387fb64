#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/scene_reader.h>

#include <string>

namespace dealmpm
{
  using namespace dealii;

  /** The "Checks" section: when a run stops or warns rather than go on
   * with an answer that cannot be trusted. */
  struct CheckSettings
  {
    double energy_growth_limit = 0.1; ///< fraction of the energy put in; 0: off
    double cfl_warning  = 0.5; ///< fixed step: particle CFL number that warns
    double memory_limit = 0;   ///< bytes; 0: what the machines have
    double mass_loss_limit = 0.01; ///< fraction of the mass; 0: off

    /** Declare the section's entries. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check the section (the reader at the top level). */
    static CheckSettings
    read(SceneReader &reader);
  };
} // namespace dealmpm
