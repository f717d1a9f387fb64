#pragma once

#include <deal.II/base/tensor.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>

#include <map>
#include <vector>

namespace dealmpm
{
  enum class BoundaryKind
  {
    free,
    no_slip, ///< all velocity components zero
    slip     ///< normal velocity zero, tangential free
  };

  /**
   * Velocity conditions on grid nodes by boundary id, applied to the nodal
   * velocity v* of each step. A node on two slip faces that meet at a corner
   * (more than 30 degrees) loses both normal components, on a curved wall
   * only the averaged normal one; a node on any no-slip face is fixed.
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read "Grid/Boundary conditions"; every id must be one of @p grid_ids. */
    static std::map<types::boundary_id, BoundaryKind>
    read(SceneReader &reader, const std::vector<types::boundary_id> &grid_ids);

    void
    setup(const BackgroundGrid<dim>                        &grid,
          const std::map<types::boundary_id, BoundaryKind> &kinds);

    /** Remove the constrained components of a nodal vector field on the
     * locally owned nodes. */
    void
    project(std::array<NodalVector, dim> &vector) const;

    /**
     * Project v* and change the increment by as much, so that the increment
     * stays v* - p / m with v* after the condition: the wall's reaction then
     * reaches FLIP particles as it reaches PIC ones (a particle moving into a
     * fixed node is stopped by it; projecting the increment as well would
     * leave it moving for ever).
     */
    void
    project_with_increment(std::array<NodalVector, dim> &velocity,
                           std::array<NodalVector, dim> &increment) const;

  private:
    struct Node
    {
      unsigned int                    local_index;
      unsigned int                    n_normals = 0;
      std::array<Tensor<1, dim>, dim> normals; ///< orthonormal
    };
    std::vector<Node> nodes;
  };
} // namespace dealmpm
