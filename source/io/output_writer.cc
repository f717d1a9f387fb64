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
  template <int dim>
  OutputWriter<dim>::OutputWriter(const OutputSettings &settings,
                                  const MPI_Comm        comm)
    : settings(settings)
    , comm(comm)
  {}

  template <int dim>
  unsigned int
  OutputWriter<dim>::open(const std::string  &scene_file,
                          const Statistics   &first,
                          const OutputRecord *resumed,
                          const unsigned int  step)
  {
    // Every rank learns whether rank 0 could make the folder: a rank that
    // throws alone would leave the others waiting. The broadcast also keeps
    // the others from writing before rank 0 has removed the earlier run's
    // files.
    const std::string &dir = settings.directory;
    std::string        problem, output_problem;
    unsigned int       n_removed = 0;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          std::filesystem::create_directories(dir);
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
                  if (!resumed->particle_series.empty())
                    resumed->particle_series.write(dir + "/particles.pvd");
                  if (!resumed->grid_series.empty())
                    resumed->grid_series.write(dir + "/grid.pvd");
                  for (unsigned int r = 0; r < resumed->region_series.size();
                       ++r)
                    if (!resumed->region_series[r].empty())
                      resumed->region_series[r].write(
                        dir + "/fem_region_" + std::to_string(r + 1) + ".pvd");
                  n_removed       = remove_later_output(dir, resumed->counter);
                  statistics_file = std::make_unique<StatisticsFile>(
                    dir + "/statistics.csv", dim, first, step);
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
    const std::string &dir = settings.directory;
    std::ostringstream context;
    context << "; the output in " << dir << "/ is complete";
    if (record.counter > 0)
      context << " up to t = " << record.last_time;
    else
      context << " but empty";

    // The files a series entry points to come first, on every rank; the
    // statistics row and the entries follow once all ranks have them, so
    // that a run stopped at any moment (or by a full disk) leaves no entry
    // without its files and row. Each writer does its collective part
    // before it can fail, so a rank that failed still takes part in the
    // rest, and all ranks throw together.
    std::string problem;
    const auto  attempt = [&problem](const auto &write_files) {
      try
        {
          write_files();
        }
      catch (const OutputError &e)
        {
          if (problem.empty())
            problem = e.what();
        }
    };
    std::string particle_file, grid_file;
    if (settings.write_particles)
      attempt([&] {
        particle_output.build_patches(scene.particles, scene.materials);
        particle_file = particle_output.write(dir, record.counter, comm);
      });
    if (settings.write_grid)
      attempt([&] {
        grid_file =
          write_grid_output(scene.grid, scene.fields, dir, record.counter);
      });
    std::vector<std::string> region_files(scene.regions.size());
    for (unsigned int r = 0; r < scene.regions.size(); ++r)
      attempt([&] {
        region_files[r] =
          write_region_output(*scene.regions[r].solid,
                              dir,
                              "fem_region_" + std::to_string(r + 1) + "_" +
                                Utilities::int_to_string(record.counter, 5));
      });
    if (settings.write_particle_csv)
      attempt([&] {
        std::ostringstream name;
        name << dir << "/particles_" << std::setw(5) << std::setfill('0')
             << record.counter << ".csv";
        write_particle_csv(scene.particles, name.str(), comm);
      });
    agree_on_output_error(problem, context.str(), comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      attempt([&] {
        write_row(*statistics_file);
        if (!particle_file.empty())
          record.particle_series.add_and_write(time,
                                               particle_file,
                                               dir + "/particles.pvd");
        if (!grid_file.empty())
          record.grid_series.add_and_write(time, grid_file, dir + "/grid.pvd");
        record.region_series.resize(region_files.size());
        for (unsigned int r = 0; r < region_files.size(); ++r)
          if (!region_files[r].empty())
            record.region_series[r].add_and_write(time,
                                                  region_files[r],
                                                  dir + "/fem_region_" +
                                                    std::to_string(r + 1) +
                                                    ".pvd");
      });
    agree_on_output_error(problem, context.str(), comm);
    ++record.counter;
    record.last_time = time;
    record.last_step = step;
  }

  template class OutputWriter<2>;
  template class OutputWriter<3>;
} // namespace dealmpm
