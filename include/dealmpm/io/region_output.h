#pragma once

#include <dealmpm/effects/drawn_body.h>
#include <dealmpm/fem/solid_region.h>
#include <dealmpm/io/output_settings.h>
#include <dealmpm/io/vtu_writer.h>

#include <string>

namespace dealmpm
{
  /** This rank's cells of an FEM region on its deformed mesh (a Q2 cell
   * as 2^dim sub-cells through its nodes), its arrays named and typed as
   * the particles' are: `mpi_rank`, nodal `velocity` and `displacement`,
   * and constant in each cell its mean `stress` (one 3 x 3 tensor, in 2D
   * with the plane-strain sigma_zz), `von_mises` and the material's
   * internal variables. Collective (ghost exchanges). */
  template <int dim>
  VtuPointCloud
  region_cloud(const SolidRegion<dim> &region);

  /** Write region_cloud() of all ranks as <base>.pvtu with a .vtu piece
   * per rank, or as one <base>.h5 (@p format), in @p directory at
   * @p time. Returns the series entry. Collective; throws OutputError on
   * every rank when a file cannot be written. */
  template <int dim>
  std::string
  write_region_output(const SolidRegion<dim> &region,
                      const std::string      &directory,
                      const std::string      &base,
                      const OutputFormat      format,
                      const double            time);

  /** Write a solid an effect draws (a rigid body) as <base>.vtu from rank
   * 0 alone, or as <base>.h5 (@p format), in @p directory at @p time,
   * with its `velocity` at every point. Returns the series entry.
   * Collective. */
  template <int dim>
  std::string
  write_drawn_body(const DrawnBody<dim> &body,
                   const std::string    &directory,
                   const std::string    &base,
                   const OutputFormat    format,
                   const double          time,
                   const MPI_Comm        comm);
} // namespace dealmpm
