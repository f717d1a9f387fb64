#pragma once

#include <dealmpm/effects/drawn_body.h>
#include <dealmpm/fem/fem_region.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/io/output_record.h>
#include <dealmpm/io/output_settings.h>
#include <dealmpm/io/particle_output.h>
#include <dealmpm/io/statistics_file.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * The run's output folder: made (and cleared of an earlier run's files)
   * by open(), then one write() per output step: particle and grid files on
   * every rank, then the statistics row and the series entries on rank 0,
   * so that no entry and no row is on disk before the files they stand for.
   */
  template <int dim>
  class OutputWriter
  {
  public:
    OutputWriter(const OutputSettings &settings, const MPI_Comm comm);

    /** Make the folder, remove an earlier run's files and start
     * statistics.csv (its columns from the @p first statistics). Collective;
     * throws InputError naming @p scene_file when the folder cannot be
     * made, OutputError on every rank when a file cannot be written.
     * Returns the number of files removed (rank 0).
     *
     * A resumed run gives the @p resumed record of its checkpoint instead:
     * the folder keeps the outputs that record lists (statistics.csv its
     * rows up to the record's last step, the series their entries, rewritten
     * at once), and the files the interrupted run wrote after them (after
     * the checkpoint, or at the stop that saved it) are removed. */
    unsigned int
    open(const std::string  &scene_file,
         const Statistics   &first,
         const OutputRecord *resumed = nullptr);

    /** The parts of a run an output shows. */
    struct Scene
    {
      const ParticleSet<dim>                            &particles;
      const std::vector<std::unique_ptr<Material<dim>>> &materials;
      const BackgroundGrid<dim>                         &grid;
      const NodalFields<dim>                            &fields;
      const std::vector<FemRegion<dim>>                 &regions;
      /** The solids the effects draw (Effect::drawn_bodies()). */
      const std::vector<DrawnBody<dim>> &bodies;
    };

    /** Write the output of the state at @p time, step @p step, counted in
     * @p record; @p write_row writes its statistics row (rank 0).
     * Collective; throws OutputError on every rank when any rank failed. */
    void
    write(const Scene                                 &scene,
          const double                                 time,
          const unsigned int                           step,
          OutputRecord                                &record,
          const std::function<void(StatisticsFile &)> &write_row);

  private:
    const OutputSettings           &settings;
    MPI_Comm                        comm;
    ParticleOutput<dim>             particle_output;
    std::unique_ptr<StatisticsFile> statistics_file;
  };
} // namespace dealmpm
