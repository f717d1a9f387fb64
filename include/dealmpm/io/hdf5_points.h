#pragma once

#include <deal.II/base/mpi.h>

#include <dealmpm/io/vtu_writer.h>

#include <string>

namespace dealmpm
{
  /**
   * A point cloud of all ranks in one HDF5 file, written together through
   * MPI-IO (parallel HDF5), and the XDMF element that shows it in ParaView.
   *
   * The file holds /points (n x 3, Float64: x, y, z, z = 0 in 2D) and one
   * dataset per array of the cloud (n x components, the array's type: ids
   * stay Int64), each rank's points at its offset in rank order. A rank
   * without points takes part with an empty selection. The file is written
   * beside its target and renamed over it once complete, so that an output
   * on disk is whole (as OutputFile does for one rank's files). A cloud
   * with cells (VtuPointCloud::connectivity) adds /cells (cells x points
   * per cell, Int64, indices among all ranks' points) and is shown as
   * those cells; one without, as vertices.
   */
  class Hdf5PointCloud
  {
  public:
    /** Collective. Write @p cloud's pieces of all ranks to @p path; returns
     * the XDMF Grid element (time @p time) that points at it by its name
     * relative to the XDMF file's folder, @p name, and is called
     * @p grid_name. Throws OutputError on
     * every rank when the file cannot be written. */
    static std::string
    write(const VtuPointCloud &cloud,
          const std::string   &path,
          const std::string   &name,
          const double         time,
          const MPI_Comm       comm,
          const std::string   &grid_name = "particles");
  };

} // namespace dealmpm
