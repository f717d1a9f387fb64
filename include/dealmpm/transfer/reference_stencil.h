#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/kernel.h>
#include <dealmpm/transfer/stencil.h>

#include <utility>

namespace dealmpm
{
  /**
   * Total Lagrangian's stencil: every particle is put in its reference
   * state (position X_p = x_p - u_p in its own cell, F = I, so that the
   * kernels with a particle domain see the undeformed one), the scene's
   * shape function computes the stencil (and APIC's positions, which are
   * then X_p), and the particles get their current state back. Marks the
   * stencil as made in the reference configuration (Stencil::reference).
   * The particles must never have been sorted since they were made: their
   * cells are the reference ones.
   */
  template <int dim>
  void
  compute_reference_stencil(const BackgroundGrid<dim> &grid,
                            const Kernel<dim>         &kernel,
                            ParticleSet<dim>          &particles,
                            const bool                 apic,
                            Stencil<dim>              &stencil);

  /**
   * Two bodies (0-based) that share no grid node through @p stencil, not
   * even through other bodies, or (0, 0) when every body is joined to
   * every other: under total Lagrangian, bodies interact only through the
   * nodes their particles share in the reference configuration, so bodies
   * that start apart would pass through each other. Nodes of zero weight
   * do not join. Collective.
   */
  template <int dim>
  std::pair<unsigned int, unsigned int>
  bodies_apart(const BackgroundGrid<dim> &grid,
               const ParticleSet<dim>    &particles,
               const Stencil<dim>        &stencil,
               const unsigned int         n_bodies);
} // namespace dealmpm
