#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cstdint>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /**
   * A solid that an effect moves and the output draws as its own series
   * (`rigid_body_N.pvd`): its outline now, as cells of one VTK type, and
   * its velocity. The grid's box is given so that shapes without an end
   * (a cylinder along z, a half-space) can be drawn as far as the grid
   * reaches.
   */
  template <int dim>
  struct DrawnBody
  {
    /** VTK's cell types used here. */
    enum CellType : std::uint8_t
    {
      triangle   = 5,
      quad       = 9,
      hexahedron = 12,
      wedge      = 13
    };

    std::vector<Point<dim>> points;
    CellType                cell_type = quad;
    /** Points per cell (4 for a quad, ...), cell after cell. */
    std::vector<unsigned int> connectivity;
    Tensor<1, dim>            velocity;

    unsigned int
    points_per_cell() const
    {
      switch (cell_type)
        {
          case triangle:
            return 3;
          case quad:
            return 4;
          case hexahedron:
            return 8;
          case wedge:
            return 6;
        }
      return 0;
    }
  };
} // namespace dealmpm
