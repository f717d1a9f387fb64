#pragma once

#include <dealmpm/grid/boundary_conditions.h>
#include <dealmpm/grid/nodal_fields.h>

namespace dealmpm
{
  /**
   * The explicit grid update on the locally owned nodes: on active nodes
   * (mass above @p mass_threshold) v = p / m and v* = v + dt f / m; boundary
   * conditions act on v*, and the increment FLIP uses is taken after them,
   * v* - v. Inactive nodes get zero. Ghost values are updated for G2P.
   */
  template <int dim>
  void
  update_nodal_velocity(NodalFields<dim>              &fields,
                        const double                   dt,
                        const double                   mass_threshold,
                        const BoundaryConditions<dim> &boundary_conditions);

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
