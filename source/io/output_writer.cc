#include <deal.II/base/mpi.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/io/grid_output.h>
#include <dealmpm/io/output_file.h>
#include <dealmpm/io/output_folder.h>
#include <dealmpm/io/output_writer.h>
#include <dealmpm/io/particle_csv.h>
#include <dealmpm/io/region_output.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace dealmpm
{
  namespace
  {
    /** What an output error adds: how far the folder's output is complete
     * (the files of earlier steps stay usable). */
    std::string
    completeness(const std::string &dir, const OutputRecord &record)
    {
      std::ostringstream context;
      context << "; the output in " << dir << "/ is complete";
      if (record.counter > 0)
        context << " up to t = " << record.last_time;
      else
        context << " but empty";
      return context.str();
    }

    /** Runs writers and keeps the first OutputError's message, so that a
     * rank whose writer failed goes on with the others (each writer does
     * its collective part before it can fail) and all ranks can then throw
     * together. */
    struct Attempts
    {
      std::string problem;

      template <typename Write>
      void
      operator()(const Write &write)
      {
        try
          {
            write();
          }
        catch (const OutputError &e)
          {
            if (problem.empty())
              problem = e.what();
          }
      }
    };

    /** The files one output step wrote that series list (empty: none). */
    struct StepFiles
    {
      std::string              particles, grid;
      std::vector<std::string> regions, bodies;
    };

    /** A series entry of a file in the step_folder, as the series at the
     * folder's top refers to it: a .pvd entry is the file's name, which
     * gets the folder; an XDMF Grid element names its "file.h5:/dataset"s
     * from the top already (the writers know the step_folder). */
    std::string
    from_series_folder(const std::string &entry)
    {
      if (entry.find("<Grid") != std::string::npos)
        return entry;
      return step_folder + "/" + entry;
    }

    /** Adds the step's files at @p time to the @p record's series and
     * rewrites those (rank 0). */
    void
    add_to_series(OutputRecord         &record,
                  const StepFiles      &files,
                  const double          time,
                  const OutputSettings &settings)
    {
      const std::string dir = settings.directory + "/";
      const std::string ext = settings.series_extension();
      if (!files.particles.empty())
        record.particle_series.add_and_write(
          time, from_series_folder(files.particles), dir + "particles" + ext);
      if (!files.grid.empty())
        record.grid_series.add_and_write(time,
                                         from_series_folder(files.grid),
                                         dir + "grid" + ext);
      record.region_series.resize(files.regions.size());
      for (unsigned int r = 0; r < files.regions.size(); ++r)
        if (!files.regions[r].empty())
          record.region_series[r].add_and_write(
            time,
            from_series_folder(files.regions[r]),
            dir + "fem_region_" + std::to_string(r + 1) + ext);
      record.body_series.resize(files.bodies.size());
      for (unsigned int b = 0; b < files.bodies.size(); ++b)
        record.body_series[b].add_and_write(time,
                                            from_series_folder(files.bodies[b]),
                                            dir + "rigid_body_" +
                                              std::to_string(b + 1) + ext);
    }

    /** Writes the files of output @p counter that the @p settings ask for,
     * on every rank, each writer in an @p attempt. */
    template <int dim>
    StepFiles
    write_files(const OutputSettings                    &settings,
                const typename OutputWriter<dim>::Scene &scene,
                ParticleOutput<dim>                     &particle_output,
                const unsigned int                       counter,
                const double                             time,
                const MPI_Comm                           comm,
                Attempts                                &attempt)
    {
      const std::string  dir    = settings.directory + "/" + step_folder;
      const OutputFormat format = settings.format;
      StepFiles          files;
      if (settings.write_particles)
        attempt([&] {
          particle_output.build_patches(scene.particles, scene.materials);
          files.particles =
            format == OutputFormat::hdf5 ?
              particle_output.write_hdf5(dir, counter, time, comm) :
              particle_output.write(dir,
                                    counter,
                                    comm,
                                    settings.compress_particles);
        });
      if (settings.write_grid)
        attempt([&] {
          files.grid = write_grid_output(
            scene.grid, scene.fields, dir, counter, format, time);
        });
      files.regions.resize(scene.regions.size());
      for (unsigned int r = 0; r < scene.regions.size(); ++r)
        attempt([&] {
          files.regions[r] =
            write_region_output(*scene.regions[r].solid,
                                dir,
                                "fem_region_" + std::to_string(r + 1) + "_" +
                                  Utilities::int_to_string(counter, 5),
                                format,
                                time);
        });
      files.bodies.resize(scene.bodies.size());
      for (unsigned int b = 0; b < scene.bodies.size(); ++b)
        attempt([&] {
          files.bodies[b] =
            write_drawn_body(scene.bodies[b],
                             dir,
                             "rigid_body_" + std::to_string(b + 1) + "_" +
                               Utilities::int_to_string(counter, 5),
                             format,
                             time,
                             comm);
        });
      if (settings.write_particle_csv)
        attempt([&] {
          std::ostringstream name;
          name << dir << "/particles_" << std::setw(5) << std::setfill('0')
               << counter << ".csv";
          write_particle_csv(scene.particles, name.str(), comm);
        });
      return files;
    }
  } // namespace

  template <int dim>
  OutputWriter<dim>::OutputWriter(const OutputSettings &settings,
                                  const MPI_Comm        comm)
    : settings(settings)
    , comm(comm)
  {}

  namespace
  {
    /** A resumed run goes on with its series, so it must write them as the
     * saved run did: throws InputError naming @p scene_file's entry when
     * the @p resumed record's series are of the other format. */
    void
    check_resumed_format(const OutputRecord   &resumed,
                         const OutputSettings &settings,
                         const std::string    &scene_file)
    {
      std::vector<const OutputSeries *> series = {&resumed.particle_series,
                                                  &resumed.grid_series};
      for (const OutputSeries &s : resumed.region_series)
        series.push_back(&s);
      for (const OutputSeries &s : resumed.body_series)
        series.push_back(&s);
      const bool hdf5 = settings.format == OutputFormat::hdf5;
      for (const OutputSeries *s : series)
        if (!s->empty() && s->holds_xdmf() != hdf5)
          throw InputError(
            scene_file + ": entry 'Output/Format' = '" +
            (hdf5 ? "hdf5" : "vtu") + "': the saved run wrote " +
            (hdf5 ? "vtu (.pvd series)" : "hdf5 (.xdmf series)") +
            "; resume it with Format = " + (hdf5 ? "vtu" : "hdf5"));
    }
  } // namespace

  template <int dim>
  unsigned int
  OutputWriter<dim>::open(const std::string  &scene_file,
                          const Statistics   &first,
                          const OutputRecord *resumed)
  {
    // Every rank learns whether rank 0 could make the folder: a rank that
    // throws alone would leave the others waiting. The broadcast also keeps
    // the others from writing before rank 0 has removed the earlier run's
    // files.
    if (resumed != nullptr)
      check_resumed_format(*resumed, settings, scene_file);
    const std::string &dir = settings.directory;
    std::string        problem, output_problem;
    unsigned int       n_removed = 0;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          std::filesystem::create_directories(dir + "/" + step_folder);
          try
            {
              // An earlier run's series beside the new one (its later
              // steps, its grid files) would mislead whoever opens the
              // folder.
              if (resumed == nullptr)
                {
                  n_removed = remove_earlier_output(dir);
                  statistics_file =
                    std::make_unique<StatisticsFile>(dir + "/statistics.csv",
                                                     dim,
                                                     first);
                }
              else
                {
                  // The series first: none may list a removed file.
                  const std::string ext = settings.series_extension();
                  if (!resumed->particle_series.empty())
                    resumed->particle_series.write(dir + "/particles" + ext);
                  if (!resumed->grid_series.empty())
                    resumed->grid_series.write(dir + "/grid" + ext);
                  for (unsigned int r = 0; r < resumed->region_series.size();
                       ++r)
                    if (!resumed->region_series[r].empty())
                      resumed->region_series[r].write(
                        dir + "/fem_region_" + std::to_string(r + 1) + ext);
                  for (unsigned int b = 0; b < resumed->body_series.size(); ++b)
                    if (!resumed->body_series[b].empty())
                      resumed->body_series[b].write(
                        dir + "/rigid_body_" + std::to_string(b + 1) + ext);
                  n_removed       = remove_later_output(dir, resumed->counter);
                  statistics_file = std::make_unique<StatisticsFile>(
                    dir + "/statistics.csv", dim, first, resumed->last_step);
                }
            }
          catch (const OutputError &e)
            {
              output_problem = e.what();
            }
        }
      catch (const std::exception &e)
        {
          problem = e.what();
        }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw InputError(scene_file + ": entry 'Output/Directory' = '" + dir +
                       "': expected a folder that can be created and "
                       "written (" +
                       problem + ")");
    agree_on_output_error(output_problem, "", comm);
    return n_removed;
  }

  template <int dim>
  void
  OutputWriter<dim>::write(
    const Scene                                 &scene,
    const double                                 time,
    const unsigned int                           step,
    OutputRecord                                &record,
    const std::function<void(StatisticsFile &)> &write_row)
  {
    const std::string &dir     = settings.directory;
    const std::string  context = completeness(dir, record);

    // The files a series entry points to come first, on every rank; the
    // statistics row and the entries follow once all ranks have them, so
    // that a run stopped at any moment (or by a full disk) leaves no entry
    // without its files and row.
    Attempts        attempt;
    const StepFiles files = write_files<dim>(
      settings, scene, particle_output, record.counter, time, comm, attempt);
    agree_on_output_error(attempt.problem, context, comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      attempt([&] {
        write_row(*statistics_file);
        add_to_series(record, files, time, settings);
      });
    agree_on_output_error(attempt.problem, context, comm);
    ++record.counter;
    record.last_time = time;
    record.last_step = step;
  }

  template class OutputWriter<2>;
  template class OutputWriter<3>;
} // namespace dealmpm
