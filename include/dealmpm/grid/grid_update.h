#pragma once

#include <dealmpm/grid/boundary_conditions.h>
#include <dealmpm/grid/nodal_fields.h>

namespace dealmpm
{
  /**
   * USL's stable nodal mass for a step of Courant number @p courant
   * (c dt / h of the fastest particle) in @p dim dimensions, in particles of
   * @p mean_particle_mass: dim courant^2 mean_particle_mass.
   *
   * Used with the shape functions whose gradient does not shrink with the
   * weight (ShapeFunction::gradient_shrinks_with_weight()): linear, and
   * cpGIMP, whose domains F can squash to a sliver.
   *
   * Why: USL deforms a particle with v* = v + dt f / m at every node of its
   * stencil, and with linear shape functions a node that a particle has just
   * reached carries only the sliver N of its mass while the particle's
   * gradient there is a full 1/h. That node and the particle then form a
   * spring of stiffness about c^2 m_p |grad N|^2 on a mass N m_p, whose
   * explicit step is stable only if N >= dim courant^2 / 4 (Gershgorin, one
   * particle). Below it the stress round-off of a body in rigid motion grows
   * by about courant^2 / N per step until the body turns inside out (a
   * translating block at CFL 0.5 in 132 steps). update_nodal_velocity() gives
   * such nodes less of their own increment; the factor of four over the
   * one-particle bound covers the particles that feed a node together
   * (dim / 2 still let a 3D block grow at CFL 0.5).
   */
  inline double
  stable_nodal_mass(const unsigned int dim,
                    const double       courant,
                    const double       mean_particle_mass)
  {
    return dim * courant * courant * mean_particle_mass;
  }

  /**
   * fields.increment_weight = min(1, m / @p stable_mass) on the owned nodes
   * (sized on first use), ghosts updated, and fields.has_light_nodes; see
   * update_nodal_velocity().
   */
  template <int dim>
  void
  set_increment_weights(NodalFields<dim> &fields, double stable_mass);

  /**
   * The explicit grid update on the locally owned nodes: on active nodes
   * (mass above @p mass_threshold) v = p / m and v* = v + dt f / m; boundary
   * conditions act on v*, and the increment FLIP uses is taken after them,
   * v* - v. Inactive nodes get zero. Ghost values are updated for G2P.
   *
   * With @p stable_mass > 0 (USL, stable_nodal_mass()) the increment
   * weights fields.increment_weight = min(1, m / stable_mass) are set too:
   * G2P's velocity gradient then uses v_i - (1 - w_i) (dv_i - dv_p) at a
   * node, with dv_p the particle's own interpolated increment, so that a
   * light node moves with the particles that give it its mass (MUSL's
   * re-mapped velocity does the same for all nodes). Uniform and rigid
   * velocity fields keep a zero strain rate; motion is unchanged.
   */
  template <int dim>
  void
  update_nodal_velocity(NodalFields<dim>              &fields,
                        const double                   dt,
                        const double                   mass_threshold,
                        const BoundaryConditions<dim> &boundary_conditions,
                        const double                   stable_mass);

  /**
   * The nodal velocity v = p / m of the current momentum on active nodes
   * (zero elsewhere), boundary conditions applied, ghosts updated: the
   * velocity field of USF's and MUSL's stress update.
   */
  template <int dim>
  void
  velocity_from_momentum(NodalFields<dim>              &fields,
                         const double                   mass_threshold,
                         const BoundaryConditions<dim> &boundary_conditions);
} // namespace dealmpm
