#pragma once

#include <deal.II/numerics/data_out.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/io/output_settings.h>

#include <string>

namespace dealmpm
{
  /** Write the grid with nodal mass and velocity v* (hanging nodes
   * interpolated), refinement level and MPI rank, as output @p counter at
   * @p time in @p format; returns the series entry (write_pieces()). */
  template <int dim>
  std::string
  write_grid_output(const BackgroundGrid<dim> &grid,
                    const NodalFields<dim>    &fields,
                    const std::string         &directory,
                    const unsigned int         counter,
                    const OutputFormat         format,
                    const double               time);

  /** Write @p data_out's patches of all ranks in @p directory, each file
   * whole or not at all, and return the series entry (OutputSeries):
   * - vtu: this rank's piece <base>.<rank>.vtu and, on rank 0, the record
   *   <base>.pvtu that lists every rank's piece; the entry is the record's
   *   name;
   * - hdf5: <base>.h5 written by all ranks together; the entry is its XDMF
   *   Grid element at @p time.
   * Collective for hdf5 (which throws OutputError on every rank). */
  template <int dim>
  std::string
  write_pieces(DataOut<dim>      &data_out,
               const std::string &directory,
               const std::string &base,
               const MPI_Comm     comm,
               const OutputFormat format,
               const double       time);
} // namespace dealmpm
