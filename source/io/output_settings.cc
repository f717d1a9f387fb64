#include <dealmpm/io/output_settings.h>

namespace dealmpm
{
  void
  OutputSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry(
      "Directory",
      "output",
      Patterns::DirectoryName(),
      "Folder for all output (created; relative to the working directory). "
      "The files of an earlier run in it (particles_*, grid_*, "
      "statistics.csv, *.pvd, *.xdmf) are removed first; other files stay.");
    prm.declare_entry(
      "Interval",
      "0.1",
      Patterns::Double(),
      "Simulated time between outputs (s); 0: only the first and last step.");
    prm.declare_entry(
      "Format",
      "vtu",
      Patterns::Selection("vtu|hdf5"),
      "How particle, grid and FEM region files are written. vtu: a .vtu "
      "piece per rank and a .pvtu per output, listed in .pvd series. hdf5: "
      "one .h5 file per output written by all ranks together (parallel "
      "HDF5), listed in .xdmf series (particles.xdmf, grid.xdmf, "
      "fem_region_N.xdmf) that ParaView opens with its XDMF reader; for "
      "runs on many ranks, where a file per rank and output would be "
      "hundreds of thousands of files.");
    prm.declare_entry(
      "Compression",
      "none",
      Patterns::Selection("none|zlib"),
      "Particle .vtu files (Format = vtu): none, raw binary, the fastest to "
      "write; zlib, smaller files at the cost of compressing them (the 2D "
      "column of 1.2 M particles: 4.8 times smaller, written in 1.9 times "
      "the time; fields that vary more compress less). deal.II always "
      "compresses the grid's and FEM regions' .vtu files.");
    prm.declare_entry("Write particles",
                      "true",
                      Patterns::Bool(),
                      "Particle files (see Format) and their series.");
    prm.declare_entry(
      "Write grid",
      "false",
      Patterns::Bool(),
      "Grid files (nodal mass and velocity, level, rank; see Format) and "
      "their series (under total Lagrangian the grid is the reference one, "
      "while the particles are shown where they are).");
    prm.declare_entry(
      "Particle CSV",
      "false",
      Patterns::Bool(),
      "Also particles_NNNNN.csv (id, position, velocity, displacement, J, body).");
    prm.declare_entry("Progress interval",
                      "5",
                      Patterns::Double(),
                      "Seconds of wall time between progress lines (0: none).");
    prm.leave_subsection();
  }

  OutputSettings
  OutputSettings::read(SceneReader &reader)
  {
    OutputSettings s;
    SectionScope   output(reader, "Output");
    s.directory = reader.get("Directory");
    if (s.directory.empty())
      reader.fail("Directory", "a folder name");
    s.interval = reader.get_nonnegative("Interval");
    s.format =
      reader.get("Format") == "hdf5" ? OutputFormat::hdf5 : OutputFormat::vtu;
    s.compress_particles = reader.get("Compression") == "zlib";
    s.write_particles    = reader.get_bool("Write particles");
    s.write_grid         = reader.get_bool("Write grid");
    s.write_particle_csv = reader.get_bool("Particle CSV");
    s.progress_interval  = reader.get_nonnegative("Progress interval");
    return s;
  }
} // namespace dealmpm
