#pragma once

#include <deal.II/base/data_out_base.h>

#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>

#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace dealmpm
{
  /**
   * Particle fields as VTU point data (one .vtu per rank and a .pvtu per
   * output step, through deal.II's writers): id, body, material, velocity,
   * displacement, stress (full tensor), J, volume, mass and the materials'
   * internal variables by name.
   */
  template <int dim>
  class ParticleOutput : public DataOutInterface<0, dim>
  {
  public:
    void
    build_patches(const ParticleSet<dim> &particles);

    /** Write <directory>/particles_NNNNN.{rank}.vtu and .pvtu; return the
     * .pvtu file name (relative to directory). */
    std::string
    write(const std::string &directory,
          const unsigned int counter,
          const MPI_Comm     comm) const;

  private:
    const std::vector<DataOutBase::Patch<0, dim>> &
    get_patches() const override
    {
      return patches;
    }
    std::vector<std::string>
    get_dataset_names() const override
    {
      return names;
    }
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override
    {
      return ranges;
    }

    std::vector<DataOutBase::Patch<0, dim>> patches;
    std::vector<std::string>                names;
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      ranges;
  };

  /** The .pvd time series ParaView opens; rewritten whole at each output so
   * that it is complete whenever a run stops. */
  class PvdSeries
  {
  public:
    void
    add_and_write(const double       time,
                  const std::string &file,
                  const std::string &pvd_path);

  private:
    std::vector<std::pair<double, std::string>> entries;
  };
} // namespace dealmpm
