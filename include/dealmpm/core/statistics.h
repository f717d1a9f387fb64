#pragma once

#include <dealmpm/effects/effect.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>

#include <array>
#include <memory>
#include <vector>

namespace dealmpm
{
  /** Global sums over all particles (all ranks). */
  struct Statistics
  {
    double                n_particles = 0;
    double                mass        = 0;
    std::array<double, 3> momentum{{0, 0, 0}};
    double                kinetic_energy       = 0;
    double                strain_energy        = 0;
    double                gravitational_energy = 0;
    /** Displacement error against an effect's exact solution, if any:
     * volume-weighted RMS and max over the particles. */
    bool   has_error = false;
    double error_L2  = 0;
    double error_max = 0;

    double
    total_energy() const
    {
      return kinetic_energy + strain_energy + gravitational_energy;
    }
  };

  template <int dim>
  Statistics
  compute_statistics(
    const ParticleSet<dim>                            &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const std::vector<std::unique_ptr<Effect<dim>>>   &effects,
    const double                                       time,
    const MPI_Comm                                     comm);
} // namespace dealmpm
