#pragma once

#include <deal.II/base/mpi.h>

#include <dealmpm/fem/fem_regions.h>

#include <string>

namespace dealmpm
{
  /** Each rank's part of each region's state into the checkpoint
   * @p folder (fem_region_N.<rank>.txt). Collective; OutputError. */
  template <int dim>
  void
  save_fem_regions(const FemRegions<dim> &regions,
                   const std::string     &folder,
                   const MPI_Comm         comm);

  /** The regions' state from the checkpoint @p folder, written on
   * @p n_saved_ranks ranks (any number of ranks reads it); InputError when
   * a file is missing. */
  template <int dim>
  void
  restore_fem_regions(FemRegions<dim>   &regions,
                      const std::string &folder,
                      const unsigned int n_saved_ranks,
                      const MPI_Comm     comm);
} // namespace dealmpm
