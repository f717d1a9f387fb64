#pragma once

#include <deal.II/base/config.h>

#include <dealmpm/grid/background_grid.h>

#include <cstddef>

namespace dealmpm
{
  /**
   * Visit this rank's particles in the stencil's order: grid.cells, then the
   * particles of each cell. Calls @p f(k, particle, cell) with k the
   * particle's place in that order, so that its stencil entries are
   * stencil.begin[k] to stencil.begin[k + 1]. Every sweep that builds or
   * reads a stencil visits through here, so that they cannot disagree on
   * the order. @p handler is the particle set's handler, const for sweeps
   * that only read the particles. Returns the number of particles visited.
   *
   * The step's hot loops go through here. Mark @p f DEAL_II_ALWAYS_INLINE
   * (after its parameter list), as this function is, and so the helpers it
   * calls per particle: then all are inlined before the optimiser works on
   * the sweep, which compiles as if the loops were written out. Left to the
   * compiler's own inlining (later, or not at all), P2G took 8 % and the
   * linear stencil 25 % more instructions (callgrind): the nodal pointers
   * were reloaded from the stack in the innermost loop.
   */
  template <int dim, typename ParticleHandlerType, typename Function>
  DEAL_II_ALWAYS_INLINE inline std::size_t
  for_each_particle_in_stencil_order(const BackgroundGrid<dim> &grid,
                                     ParticleHandlerType       &handler,
                                     Function                 &&f)
  {
    std::size_t k = 0;
    for (const GridCell<dim> &c : grid.cells)
      for (auto &p : handler.particles_in_cell(c.cell))
        {
          f(k, p, c);
          ++k;
        }
    return k;
  }

  /** The index of @p cell in grid.cells, for the per-cell data kept beside
   * it (grid.neighbors, the B-spline's node blocks). */
  template <int dim>
  inline unsigned int
  index_in_grid(const BackgroundGrid<dim> &grid, const GridCell<dim> &cell)
  {
    return static_cast<unsigned int>(&cell - grid.cells.data());
  }
} // namespace dealmpm
