#pragma once

#include <deal.II/numerics/data_out.h>

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

  /** This rank's piece <base>.<rank>.vtu of @p data_out and, on rank 0,
   * the record <base>.pvtu that lists every rank's piece, in @p directory
   * (each written whole or not at all); returns the record's name. */
  template <int dim>
  std::string
  write_pieces(const DataOut<dim> &data_out,
               const std::string  &directory,
               const std::string  &base,
               const MPI_Comm      comm);
} // namespace dealmpm
