#pragma once

#include <deal.II/base/mpi.h>

#include <dealmpm/base/scene_reader.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/body.h>
#include <dealmpm/particles/particle_set.h>

#include <memory>
#include <vector>

namespace dealmpm
{
  /**
   * Bodies with 'Initial stress = geostatic' start at rest under the
   * uniform acceleration @p g (gravity): each particle of such a body takes
   * the stress of its depth (Shape::depth(): below the top of the body's
   * bounding box, or a polygon's surface above it) (vertical rho g depth,
   * horizontal K0 times it) with the deformation
   * gradient its material needs for it, and the volume (and, for cpGIMP
   * and CPDI, the domain) it fills at that stretch. Fails through
   * @p reader ('Body N/K0') when a material cannot carry its stress at
   * rest. Collective. The scene's rules (a non-zero @p g, the updated
   * Lagrangian formulation) are check_compatibility()'s.
   */
  template <int dim>
  void
  start_geostatic_bodies(
    SceneReader                                       &reader,
    const std::vector<Body<dim>>                      &bodies,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const Tensor<1, dim>                              &g,
    ParticleSet<dim>                                  &particles,
    const MPI_Comm                                     comm);
} // namespace dealmpm
