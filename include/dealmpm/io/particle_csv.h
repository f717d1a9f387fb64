#pragma once

#include <dealmpm/particles/particle_set.h>

#include <string>

namespace dealmpm
{
  /** Write id,x,y[,z],vx,vy[,vz],ux,uy[,uz],J,body to one CSV file (gathered
   * on rank 0), sorted by id, for scripting. */
  template <int dim>
  void
  write_particle_csv(const ParticleSet<dim> &particles,
                     const std::string      &path,
                     const MPI_Comm          comm);
} // namespace dealmpm
