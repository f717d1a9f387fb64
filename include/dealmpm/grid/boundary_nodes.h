#pragma once

#include <deal.II/base/tensor.h>

#include <dealmpm/grid/background_grid.h>

#include <set>
#include <vector>

namespace dealmpm
{
  /**
   * A locally owned grid node on the boundary faces of one id, facing one
   * way: the outward normal times the node's share of the faces' area
   * (the integral of its shape function over them, exact on flat faces
   * made of parallelograms). A node where faces of the id meet at a corner
   * (more than 30 degrees) appears once per direction; faces that meet at
   * less (a curved wall) share one entry.
   */
  template <int dim>
  struct BoundaryNode
  {
    unsigned int       local_index;
    types::boundary_id id;
    Tensor<1, dim>     area;

    Tensor<1, dim>
    normal() const
    {
      return area / area.norm();
    }
  };

  /** The boundary nodes of the faces with one of @p ids, on this rank's
   * locally owned nodes (hanging nodes left out: they get nothing). Faces
   * of ghost cells count too, so that a node on a partition boundary has
   * its whole area. */
  template <int dim>
  std::vector<BoundaryNode<dim>>
  boundary_nodes(const BackgroundGrid<dim>          &grid,
                 const std::set<types::boundary_id> &ids);
} // namespace dealmpm
