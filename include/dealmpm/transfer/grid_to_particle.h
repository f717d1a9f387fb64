#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/stencil.h>

#include <vector>

namespace dealmpm
{
  /**
   * G2P: particle velocity (FLIP fraction alpha: alpha (v_p + sum N dv) +
   * (1 - alpha) sum N v*), position and displacement (x += dt sum N v*),
   * velocity gradient L = sum v* (x) grad N (kept per particle for the stress
   * update), F <- (I + dt L) F, and the new reference location in the old
   * cell.
   *
   * @return true if some local particle left its cell (a sort is needed).
   */
  template <int dim>
  bool
  grid_to_particle(const BackgroundGrid<dim> &   grid,
                   const Stencil<dim> &          stencil,
                   const NodalFields<dim> &      fields,
                   const double                  dt,
                   const double                  flip_fraction,
                   ParticleSet<dim> &            particles,
                   std::vector<Tensor<2, dim>> & velocity_gradient);
} // namespace dealmpm
