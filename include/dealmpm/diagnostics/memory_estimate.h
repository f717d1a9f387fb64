#pragma once

#include <deal.II/base/mpi.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/body.h>

#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * What a scene will allocate, estimated from the grid's size and the
   * bodies' bounding boxes before any cell or particle exists, so that a
   * scene that cannot fit is refused at once instead of swapping for
   * minutes. Bytes per cell and per particle were measured on the whole
   * program (peak resident memory; benchmarks/README.md).
   */
  struct MemoryEstimate
  {
    double n_cells     = 0;
    double n_particles = 0;
    double bytes       = 0;
  };

  /** How adaptivity refines the grid at the start, before the first step:
   * every cell to @p everywhere levels, those holding particles to
   * @p with_particles (where the bodies are filled), up to @p most_cells. */
  struct StartRefinement
  {
    unsigned int everywhere     = 0;
    unsigned int with_particles = 0;
    double       most_cells     = 0; ///< 0: no limit
  };

  /** The cells, particles and bytes of a scene at its first step, from
   * the grid's size and the bodies' boxes before the grid is made. */
  template <int dim>
  MemoryEstimate
  estimate_memory(const GridSize<dim>          &grid,
                  const std::vector<Body<dim>> &bodies,
                  const StartRefinement        &refinement = {});

  /** @p estimate, or an InputError (about @p scene_file) when it exceeds
   * @p limit (bytes) or, with no limit (0), the available memory.
   * Collective. */
  MemoryEstimate
  check_memory(const std::string    &scene_file,
               const MemoryEstimate &estimate,
               const double          limit,
               const MPI_Comm        comm);

  /** The memory the run may use: the sum, over the machines its ranks run
   * on, of MemAvailable in /proc/meminfo (0 where that is unknown). */
  double
  available_memory(const MPI_Comm comm);
} // namespace dealmpm
