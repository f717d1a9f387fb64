#pragma once

#include <dealmpm/adaptivity/load_balance.h>
#include <dealmpm/effects/effect.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>

#include <array>
#include <limits>
#include <memory>
#include <string>
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
    /** Work dissipated by the materials (plastic work, a fluid's viscous
     * work); only counted when a material of the scene dissipates. */
    bool   has_dissipated_work = false;
    double dissipated_work     = 0;
    /** Mass and momentum that effects took out of the run on purpose
     * (erosion), so far: the conservation checks count them as kept. */
    double                removed_mass = 0;
    std::array<double, 3> removed_momentum{{0, 0, 0}};
    /** Displacement error against an effect's exact solution, if any:
     * volume-weighted RMS and max over the particles. */
    bool   has_error = false;
    double error_L2  = 0;
    double error_max = 0;
    /** The listed effects' own columns (Effect::statistics_columns()),
     * summed over the ranks: names and values. */
    std::vector<std::string> effect_columns;
    std::vector<double>      effect_values;
    /** Particles per rank: the fewest, the most and the mean (the load
     * balance; the only numbers that depend on the rank count). */
    double particles_per_rank_min  = 0;
    double particles_per_rank_max  = 0;
    double particles_per_rank_mean = 0;

    double
    total_energy() const
    {
      return kinetic_energy + strain_energy + gravitational_energy +
             dissipated_work;
    }

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &n_particles &mass &momentum[0] & momentum[1] & momentum[2];
      archive &kinetic_energy &strain_energy &gravitational_energy;
      archive &has_dissipated_work           &dissipated_work;
      archive &has_error &error_L2           &error_max;
      archive &removed_mass &removed_momentum[0] & removed_momentum[1] &
        removed_momentum[2];
      // Needs <boost/serialization/{vector,string}.hpp>.
      archive &effect_columns         &effect_values;
      archive &particles_per_rank_min &particles_per_rank_max;
      archive                         &particles_per_rank_mean;
    }
  };

  /** A particle and how much its energy grew since the start. */
  template <int dim>
  struct EnergyGain
  {
    double                gain     = -std::numeric_limits<double>::max();
    types::particle_index particle = 0;
    Point<dim>            location;
  };

  /**
   * The particle of this rank whose energy grew most since the start: its
   * kinetic, strain and potential energy now, minus its kinetic energy at
   * its body's initial velocity (@p initial_velocity, per body) and its
   * potential energy where it started (x - u). For the message of a run
   * stopped by energy growth; a sweep over the particles, not for every
   * step.
   */
  template <int dim>
  EnergyGain<dim>
  largest_energy_gain(
    const ParticleSet<dim>                            &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const std::vector<std::unique_ptr<Effect<dim>>>   &effects,
    const std::vector<Tensor<1, dim>>                 &initial_velocity);

  /** The totals over this run's particles, summed in the step's order of
   * each rank's particles over @p grid (so that they do not depend on how
   * deal.II's lists hold them). */
  template <int dim>
  Statistics
  compute_statistics(
    const BackgroundGrid<dim>                         &grid,
    const ParticleSet<dim>                            &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const std::vector<std::unique_ptr<Effect<dim>>>   &effects,
    const double                                       time,
    const MPI_Comm                                     comm);
} // namespace dealmpm
