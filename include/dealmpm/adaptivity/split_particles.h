#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

namespace dealmpm
{
  /**
   * Split the particles that are too large for their cells (after a
   * refinement) into 2^dim each: a particle is split when each part would
   * still fill at least half of the cell's measure / @p
   * particles_per_direction^dim. The parts sit at the centres of the
   * particle's 2^dim sub-domains, x +- F (l0 / 4) along each reference axis
   * (l0: the particle's initial size, 2 x its GIMP half-lengths or V0^(1/dim)),
   * and share its mass and initial volume equally (so mass, momentum,
   * volume and the first moment of mass are kept exactly); velocity,
   * stress, F, APIC's B, internal variables and effects' fields are
   * copied, the displacement is the part's own (u + (F - I) offset), GIMP
   * half-lengths are halved. The parts get new ids above every id in use,
   * from their parent's (the same on any number of ranks).
   * Returns the number of particles split on all ranks. Collective; the
   * particles are sorted into their cells afterwards.
   */
  template <int dim>
  double
  split_particles(const BackgroundGrid<dim> &grid,
                  ParticleSet<dim>          &particles,
                  const unsigned int         particles_per_direction);

  /**
   * Merge the particles of cells that hold too many small ones (after a
   * coarsening): where at least 2^dim particles of one body and material
   * lie in the same of a cell's @p particles_per_direction^dim sub-cells
   * (as the parts of a split particle do), they become one. Kept exactly: mass,
   * momentum, the first moment of mass (the merged particle sits at the centre
   * of mass) and the current volume; averaged (volume-weighted): F, stress, and
   * (mass-weighted) displacement, APIC's B, internal variables and effects'
   * fields; GIMP half-lengths scaled with the volume. Lost: the spin of the
   * merged particles about their centre and the spread of their stresses. The
   * merged particle keeps the smallest id of its group. Returns the number
   * of particles removed on all ranks. Collective.
   */
  template <int dim>
  double
  merge_particles(const BackgroundGrid<dim> &grid,
                  ParticleSet<dim>          &particles,
                  const unsigned int         particles_per_direction);
} // namespace dealmpm
