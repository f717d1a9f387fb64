#pragma once

#include <deal.II/base/types.h>

#include <dealmpm/particles/particle_set.h>

#include <set>

namespace dealmpm
{
  /**
   * Put back on the wall every particle that crossed one during the step: a
   * wall is a boundary face whose id has a condition that constrains the
   * nodes (slip, no-slip). A particle whose reference location in its old
   * cell lies beyond such a face is moved onto the face (its displacement
   * follows) and loses its velocity component out of the domain.
   *
   * Why: kernels with a particle domain (uGIMP, cpGIMP, CPDI) interpolate a
   * velocity at the wall that is not the wall node's, so a particle next to
   * a wall can step through it and would leave the grid; linear shape
   * functions slow it to the wall's velocity on the way. Call before the
   * particles are relocated into cells (the old cell of the step's order
   * is still theirs).
   *
   * @return the number of particles put back on this rank.
   */
  template <int dim>
  unsigned int
  hold_particles_at_walls(const BackgroundGrid<dim>          &grid,
                          ParticleSet<dim>                   &particles,
                          const std::set<types::boundary_id> &walls);
} // namespace dealmpm
