#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/scene_reader.h>

#include <string>

namespace dealmpm
{
  using namespace dealii;

  /** How particle, grid and FEM region files are written. */
  enum class OutputFormat
  {
    vtu, ///< a .vtu piece per rank, a .pvtu per output, .pvd series
    hdf5 ///< one .h5 per output for all ranks, .xdmf series
  };

  /** The "Output" section: where and how often a run writes, and its
   * progress line. */
  struct OutputSettings
  {
    std::string  directory          = "output";
    double       interval           = 0.1;
    bool         write_particles    = true;
    bool         write_grid         = false;
    bool         write_particle_csv = false;
    OutputFormat format             = OutputFormat::vtu;
    bool         compress_particles = false; ///< zlib in particle .vtu files
    double       progress_interval  = 5;
    bool         verbose = true; ///< not from the scene: tests run quietly

    /** The series files' extension: ".pvd" or ".xdmf". */
    std::string
    series_extension() const
    {
      return format == OutputFormat::hdf5 ? ".xdmf" : ".pvd";
    }

    /** Declare the section's entries. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check the section (the reader at the top level). */
    static OutputSettings
    read(SceneReader &reader);
  };
} // namespace dealmpm
