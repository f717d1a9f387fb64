#include <dealmpm/base/errors.h>
#include <dealmpm/diagnostics/memory_estimate.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

namespace dealmpm
{
  namespace
  {
    // Measured with dealmpm's peak resident memory (1 rank, Release):
    // 2D 0.7-1.0 KB per cell (refined - coarse), 3D 1.8-2.2 KB; particles
    // 600 B (2D) and 950 B (3D) in the step, more while output is written.
    constexpr double bytes_per_cell[]     = {0, 0, 1.0e3, 2.2e3};
    constexpr double bytes_per_particle[] = {0, 0, 0.8e3, 1.2e3};
    constexpr double program_bytes        = 150e6;
  } // namespace

  template <int dim>
  MemoryEstimate
  estimate_memory(const GridSize<dim>          &grid,
                  const std::vector<Body<dim>> &bodies,
                  const StartRefinement        &refinement)
  {
    // Cells per cell of the grid's Cells at each level.
    const double everywhere     = std::pow(2., dim * refinement.everywhere);
    const double with_particles = std::pow(
      2., dim * std::max(refinement.everywhere, refinement.with_particles));
    MemoryEstimate estimate;
    estimate.n_cells         = grid.n_cells * everywhere;
    const double cell_volume = grid.box.volume() / grid.n_cells;
    double       body_cells  = 0; // of the grid's Cells, holding particles
    for (const Body<dim> &body : bodies)
      {
        const BoundingBox<dim> box    = body.shape->bounding_box();
        double                 volume = 1;
        for (unsigned int d = 0; d < dim; ++d)
          volume *=
            std::max(0.,
                     std::min(box.upper_bound(d), grid.box.upper_bound(d)) -
                       std::max(box.lower_bound(d), grid.box.lower_bound(d)));
        body_cells += volume / cell_volume;
        estimate.n_particles += volume / cell_volume * with_particles *
                                std::pow(body.particles_per_direction, dim);
      }
    // The bodies' cells refined further (overlaps counted twice: an
    // estimate errs on the large side).
    estimate.n_cells +=
      std::min(body_cells, grid.n_cells) * (with_particles - everywhere);
    if (refinement.most_cells > 0)
      estimate.n_cells =
        std::min(estimate.n_cells,
                 std::max(refinement.most_cells, grid.n_cells * everywhere));
    estimate.bytes = program_bytes + estimate.n_cells * bytes_per_cell[dim] +
                     estimate.n_particles * bytes_per_particle[dim];
    return estimate;
  }

  double
  available_memory(const MPI_Comm comm)
  {
    // One rank per machine adds its machine's memory.
    MPI_Comm machine;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &machine);
    double here = 0;
    if (Utilities::MPI::this_mpi_process(machine) == 0)
      {
        std::ifstream meminfo("/proc/meminfo");
        std::string   line;
        while (std::getline(meminfo, line))
          if (line.rfind("MemAvailable:", 0) == 0)
            {
              std::istringstream in(line.substr(13));
              double             kilobytes = 0;
              in >> kilobytes;
              here = kilobytes * 1024;
            }
      }
    MPI_Comm_free(&machine);
    return Utilities::MPI::sum(here, comm);
  }

  MemoryEstimate
  check_memory(const std::string    &scene_file,
               const MemoryEstimate &estimate,
               const double          limit,
               const MPI_Comm        comm)
  {
    const double available = limit > 0 ? limit : available_memory(comm);
    if (available > 0 && estimate.bytes > available)
      {
        std::ostringstream message;
        message << std::setprecision(3) << scene_file
                << ": the scene needs about " << estimate.bytes / 1e9 << " GB ("
                << estimate.n_cells << " cells, " << estimate.n_particles
                << " particles), more than the " << available / 1e9
                << (limit > 0 ? " GB of 'Checks/Memory limit'" :
                                " GB available on the machine(s) of the run")
                << ": expected fewer cells or particles per cell, or more "
                   "machines";
        throw InputError(message.str());
      }
    return estimate;
  }

#define DEALMPM_INSTANTIATE(dim)                                          \
  template MemoryEstimate estimate_memory(const GridSize<dim> &,          \
                                          const std::vector<Body<dim>> &, \
                                          const StartRefinement &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
