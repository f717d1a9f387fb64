#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>

#include <string>

namespace dealmpm
{
  /** Write the grid with nodal mass and velocity v* (hanging nodes
   * interpolated), refinement level and MPI rank; returns the .pvtu name. */
  template <int dim>
  std::string
  write_grid_output(const BackgroundGrid<dim> &grid,
                    const NodalFields<dim>    &fields,
                    const std::string         &directory,
                    const unsigned int         counter);
} // namespace dealmpm
