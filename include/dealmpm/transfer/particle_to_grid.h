#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_field_set.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/formulation.h>
#include <dealmpm/transfer/stencil.h>

namespace dealmpm
{
  /**
   * P2G: nodal mass and momentum (if @p mass_and_momentum; with APIC's
   * affine part C_p (x_i - x_p) when the particles carry it) and internal
   * force (if @p internal_force)
   * f_int = -sum_p V_p sigma_p grad N (V_p = J_p V_p0), summed over ranks;
   * with @p formulation total Lagrangian, the stencil's gradients are the
   * reference ones and f_int = -sum_p V_p0 P_p Grad N, P = J sigma F^-T.
   * External forces are the effects' business (gravity acts on the nodal
   * mass directly, which is the same sum). A nonzero @p predictor_offset
   * (Newmark, see NewmarkStep) maps the momentum of v_p - offset a_p.
   */
  template <int dim>
  void
  particle_to_grid(
    const BackgroundGrid<dim> &grid,
    const ParticleSet<dim>    &particles,
    const Stencil<dim>        &stencil,
    NodalFields<dim>          &fields,
    const bool                 mass_and_momentum = true,
    const bool                 internal_force    = true,
    const Formulation          formulation = Formulation::updated_lagrangian,
    const double               predictor_offset = 0);

  /**
   * particle_to_grid() with each body's own fields (contact): each particle
   * adds into @p set.body of its body, and its mass times grad N into @p
   * set.mass_gradient of its body (with mass and momentum); the core fields
   * are then the bodies' sums, the centre-of-mass field.
   */
  template <int dim>
  void
  particle_to_body_grids(
    const BackgroundGrid<dim> &grid,
    const ParticleSet<dim>    &particles,
    const Stencil<dim>        &stencil,
    NodalFieldSet<dim>        &set,
    const bool                 mass_and_momentum = true,
    const bool                 internal_force    = true,
    const Formulation          formulation = Formulation::updated_lagrangian,
    const double               predictor_offset = 0);
} // namespace dealmpm
