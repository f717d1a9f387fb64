#pragma once

#include <dealmpm/base/scene_reader.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/body.h>
#include <dealmpm/particles/particle_set.h>

#include <vector>

namespace dealmpm
{
  /**
   * Fill @p particles with the particles of every body of the scene: each
   * body must lie inside the grid and cover at least one particle position,
   * and bodies may not overlap unless the later one replaces the earlier
   * one's particles ('Allow overlap'). Per material index: its density and
   * the initial values of its internal variables. Collective; bad bodies are
   * an InputError naming the "Body N" section (the reader at the top level).
   */
  template <int dim>
  void
  fill_bodies(SceneReader                            &reader,
              const std::vector<Body<dim>>           &bodies,
              const std::vector<double>              &densities,
              const std::vector<std::vector<double>> &initial,
              const BackgroundGrid<dim>              &grid,
              ParticleSet<dim>                       &particles);
} // namespace dealmpm
