#pragma once

#include <dealmpm/io/vtu_writer.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>

#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * Particle fields as VTU point data, one .vtu per rank and a .pvtu per
   * output step, or as HDF5 datasets of all ranks in one file per output
   * step (Hdf5PointCloud): id (Int64), body and material (Int32), velocity and
   * displacement (3-component vectors, z = 0 in 2D), stress (the full 3 x 3
   * Cauchy tensor, 9 components, with the plane-strain sigma_zz in 2D, so
   * that pressure and von Mises stress computed from it are right), J,
   * volume, mass (Float64) and every further field of the property layout
   * (the materials' internal variables, apic_B, domain_half_length) by its
   * name and component count. A rank without particles writes a piece that
   * declares the same arrays.
   */
  template <int dim>
  class ParticleOutput
  {
  public:
    void
    build_patches(const ParticleSet<dim>                            &particles,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials);

    /** Write <directory>/particles_NNNNN.{rank}.vtu and (rank 0)
     * particles_NNNNN.pvtu, the arrays compressed if @p zlib; return the
     * .pvtu file name (relative to directory). Throws OutputError on this
     * rank's failure only. */
    std::string
    write(const std::string &directory,
          const unsigned int counter,
          const MPI_Comm     comm,
          const bool         zlib = false) const;

    /** Write <directory>/particles_NNNNN.h5 with all ranks (collective);
     * return its XDMF Grid element at @p time. Throws OutputError on every
     * rank. */
    std::string
    write_hdf5(const std::string &directory,
               const unsigned int counter,
               const double       time,
               const MPI_Comm     comm) const;

  private:
    VtuPointCloud cloud;
  };
} // namespace dealmpm
