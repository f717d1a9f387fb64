#pragma once

#include <deal.II/base/timer.h>

#include <dealmpm/effects/effect.h>
#include <dealmpm/fem/fem_regions.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/boundary_conditions.h>
#include <dealmpm/grid/nodal_field_set.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/schemes/method_settings.h>
#include <dealmpm/transfer/kernel.h>
#include <dealmpm/transfer/mixed_cell_split.h>
#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stress_update.h>

#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * Everything one explicit step works on, handed to each stage
   * (schemes/stages.h): the run's parts (grid, particles, shape function and
   * its stencil, nodal fields, boundary conditions, materials, effects), the
   * step's time and size, and what the step learns on the way (the stress
   * update's particle check, whether a particle left its cell). Made by the
   * simulation for every step; the stages know nothing else of the run.
   */
  template <int dim>
  struct StepState
  {
    StepState(const BackgroundGrid<dim>     &grid,
              ParticleSet<dim>              &particles,
              const Kernel<dim>             &kernel,
              Stencil<dim>                  &stencil,
              NodalFieldSet<dim>            &field_set,
              const BoundaryConditions<dim> &boundary_conditions,
              const std::vector<std::unique_ptr<Material<dim>>> &materials,
              std::vector<std::unique_ptr<Effect<dim>>>         &effects,
              const std::vector<std::string>                    &effect_names,
              const MethodSettings                              &method,
              const double                                       mass_threshold,
              const unsigned int                                 step,
              const double                                       time,
              const double                                       dt,
              TimerOutput                                       &timer)
      : grid(grid)
      , particles(particles)
      , kernel(kernel)
      , stencil(stencil)
      , field_set(field_set)
      , fields(field_set.core)
      , boundary_conditions(boundary_conditions)
      , materials(materials)
      , effects(effects)
      , effect_names(effect_names)
      , method(method)
      , mass_threshold(mass_threshold)
      , step(step)
      , time(time)
      , dt(dt)
      , timer(timer)
      , stress_update(materials, particles, dt, method.total_lagrangian())
    {
      if (stencil.gimp_follows_deformation)
        stress_update.watch_domains(stencil.gimp_half_length,
                                    stencil.gimp_stretch_limit);
    }

    const BackgroundGrid<dim>     &grid;
    ParticleSet<dim>              &particles;
    const Kernel<dim>             &kernel;
    Stencil<dim>                  &stencil;
    NodalFieldSet<dim>            &field_set;
    NodalFields<dim>              &fields; ///< the core ones
    const BoundaryConditions<dim> &boundary_conditions;
    const std::vector<std::unique_ptr<Material<dim>>> &materials;
    std::vector<std::unique_ptr<Effect<dim>>>         &effects;
    const std::vector<std::string>                    &effect_names;
    const MethodSettings                              &method;
    /** Nodes lighter than this are inactive. */
    double mass_threshold;
    /** USL: nodes lighter than this lend the velocity gradient only part of
     * their own increment (update_nodal_velocity()); 0: all of it. */
    double stable_mass = 0;
    /** The step's number (from 1) and its start time, for messages. */
    unsigned int step;
    double       time;
    double       dt;
    /** The step before's size, 0 in the first step (Newmark). */
    double       previous_dt = 0;
    TimerOutput &timer;

    /** The stress update and what it learns of the particles. */
    StressUpdate<dim> stress_update;
    /** The strain-rate split of cells shared by materials of different
     * stiffness, or nullptr when the scene has none or turns it off. */
    MixedCellSplit<dim> *mixed_cells = nullptr;
    /** The scene's FEM regions, or nullptr when it has none. */
    FemRegions<dim> *fem_regions = nullptr;
    /** Some particle left its cell in G2P (they are relocated after the
     * step). */
    bool left_cell = false;

    /** What an effect sees of the step. */
    EffectContext<dim>
    effect_context() const
    {
      return {grid,
              particles,
              stencil,
              time,
              dt,
              field_set,
              mass_threshold,
              effects,
              stable_mass};
    }
  };
} // namespace dealmpm
