#pragma once

#include <deal.II/base/types.h>
#include <deal.II/particles/property_pool.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

#include <set>

namespace dealmpm
{
  /**
   * Put back on the wall a particle that crossed one during the step: a
   * wall is a boundary face whose id has a condition that constrains the
   * nodes (slip, no-slip). The particle (@p handle in @p pool) left its
   * cell @p c of the step's order, and @p xi are its unit-cell coordinates
   * there. If they lie beyond faces of @p c that are walls, it is moved
   * onto those faces (its displacement follows) and loses its velocity
   * component out of the domain.
   *
   * Why: kernels with a particle domain (uGIMP, cpGIMP, CPDI) interpolate a
   * velocity at the wall that is not the wall node's, so a particle next to
   * a wall can step through it and would leave the grid; linear shape
   * functions slow it to the wall's velocity on the way.
   * ParticleSet::plan_relocation() calls this for each particle outside its
   * cell before it looks for the particle's new cell.
   *
   * @return whether the particle was put back.
   */
  template <int dim>
  bool
  hold_at_walls(const GridCell<dim>                                &c,
                const std::set<types::boundary_id>                 &walls,
                const CoreFields                                   &f,
                Particles::PropertyPool<dim>                       &pool,
                const typename Particles::PropertyPool<dim>::Handle handle,
                const Point<dim>                                   &xi);
} // namespace dealmpm
