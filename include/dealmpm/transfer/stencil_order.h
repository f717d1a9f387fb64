#pragma once

#include <deal.II/base/config.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>

namespace dealmpm
{
  /**
   * Ask the cache for the pool's data of the particles 8 places after
   * those from @p first to @p last - 1 in the step's order (one cell's).
   * After particles changed cells without deal.II's sort
   * (ParticleSet::finish_relocation()), the order jumps about in the pool,
   * which the hardware's prefetcher does not follow: the flowing column's
   * P2G and G2P ran at about half the speed they run at rest, stalled on
   * each particle's first property. The sweeps ask only then
   * (ParticleOrder::follows_pool), once a cell: asked for each particle,
   * the test cost the column at rest 5 instructions a particle-step.
   * A read-only sweep (@p read_only) does not ask for the location.
   */
  template <bool read_only, int dim>
  inline void
  prefetch_particles(const PoolArrays<dim>    &pool,
                     const ParticleOrder<dim> &order,
                     const std::size_t         first,
                     const std::size_t         last)
  {
    // 4 ahead left the flowing column's P2G a quarter slower than 8; 16
    // and 32 gained nothing more.
    constexpr std::size_t ahead = 8;
    const std::size_t     end   = std::min(last + ahead, order.handles.size());
    const std::size_t     bytes = pool.n_properties * sizeof(double);
    for (std::size_t k = first + ahead; k < end; ++k)
      {
        const std::size_t handle = order.handles[k];
        const char *const props  = reinterpret_cast<const char *>(
          pool.properties + handle * pool.n_properties);
        for (std::size_t b = 0; b < bytes; b += 64)
          __builtin_prefetch(props + b);
        __builtin_prefetch(props + bytes - 1);
        __builtin_prefetch(pool.reference_locations + handle);
        if constexpr (!read_only)
          __builtin_prefetch(pool.locations + handle);
        // A loop of prefetches alone has no effect GCC must keep: without
        // this (it emits nothing), the loop was deleted.
        asm volatile("");
      }
  }

  /**
   * Visit this rank's particles in the stencil's order: grid.cells, then the
   * particles of each cell. Calls @p f(k, particle, cell) with k the
   * particle's place in that order, so that its stencil entries are
   * stencil.begin[k] to stencil.begin[k + 1]. Every sweep that builds or
   * reads a stencil visits through here, so that they cannot disagree on
   * the order. @p particles is the particle set, const for sweeps that only
   * read the particles (then @p f gets read-only views). Returns the number
   * of particles visited.
   *
   * The particle is a PooledParticle (the particle set's order of handles
   * into deal.II's property pool), not deal.II's accessor: the handler is
   * not asked for each cell's particles in each sweep.
   *
   * The step's hot loops go through here. Mark @p f DEAL_II_ALWAYS_INLINE
   * (after its parameter list), as this function is, and so the helpers it
   * calls per particle: then all are inlined before the optimiser works on
   * the sweep, which compiles as if the loops were written out. Left to the
   * compiler's own inlining (later, or not at all), P2G took 8 % and the
   * linear stencil 25 % more instructions (callgrind): the nodal pointers
   * were reloaded from the stack in the innermost loop.
   */
  template <int dim, typename ParticleSetType, typename Function>
  DEAL_II_ALWAYS_INLINE inline std::size_t
  for_each_particle_in_stencil_order(const BackgroundGrid<dim> &grid,
                                     ParticleSetType           &particles,
                                     Function                 &&f)
  {
    constexpr bool            read_only = std::is_const_v<ParticleSetType>;
    const ParticleOrder<dim> &order     = particles.order_over(grid);
    const PoolArrays<dim>     pool(particles.handler.get_property_pool());
    const bool                prefetch = !order.follows_pool;
    std::size_t               k        = 0;
    const std::size_t         n_cells  = grid.cells.size();
    for (std::size_t i = 0; i < n_cells; ++i)
      {
        const GridCell<dim> &c   = grid.cells[i];
        const std::size_t    end = order.cell_begin[i + 1];
        if (prefetch)
          prefetch_particles<read_only>(pool, order, k, end);
        for (; k < end; ++k)
          {
            const PooledParticle<dim, read_only> p(pool, order.handles[k]);
            f(k, p, c);
          }
      }
    return k;
  }

  /**
   * The particles of a sweep that works a cell at a time: the step's order
   * and deal.II's property pool, fetched once a sweep (both are calls into
   * compiled code, about 40 instructions together, which once a cell cost
   * the 2D column 25 instructions a particle-step). @p ParticleSetType is
   * const for sweeps that only read the particles.
   */
  template <int dim, typename ParticleSetType>
  class ParticlesByCell
  {
  public:
    static constexpr bool read_only = std::is_const_v<ParticleSetType>;

    ParticlesByCell(const BackgroundGrid<dim> &grid, ParticleSetType &particles)
      : order(particles.order_over(grid))
      , pool(particles.handler.get_property_pool())
      , prefetch(!order.follows_pool)
    {}

    /** Whether grid.cells[@p i] has no particles. */
    DEAL_II_ALWAYS_INLINE bool
    empty(const std::size_t i) const
    {
      return order.cell_begin[i] == order.cell_begin[i + 1];
    }

    /** Visit the particles of grid.cells[@p i] with @p f(particle), in the
     * stencil's order. */
    template <typename Function>
    DEAL_II_ALWAYS_INLINE void
    for_each(const std::size_t i, Function &&f) const
    {
      const std::size_t begin = order.cell_begin[i];
      const std::size_t end   = order.cell_begin[i + 1];
      if (prefetch)
        prefetch_particles<read_only>(pool, order, begin, end);
      for (std::size_t k = begin; k < end; ++k)
        {
          const PooledParticle<dim, read_only> p(pool, order.handles[k]);
          f(p);
        }
    }

  private:
    const ParticleOrder<dim> &order;
    const PoolArrays<dim>     pool;
    const bool                prefetch;
  };

  /** Visit the particles of grid.cells[@p i] with @p f(particle), in the
   * stencil's order (one cell; a sweep over every cell makes a
   * ParticlesByCell once instead). */
  template <int dim, typename ParticleSetType, typename Function>
  inline void
  for_each_particle_in_cell(const BackgroundGrid<dim> &grid,
                            ParticleSetType           &particles,
                            const std::size_t          i,
                            Function                 &&f)
  {
    ParticlesByCell<dim, ParticleSetType>(grid, particles).for_each(i, f);
  }

  /** The index of @p cell in grid.cells, for the per-cell data kept beside
   * it (grid.neighbors_of(), the B-spline's node blocks). */
  template <int dim>
  inline unsigned int
  index_in_grid(const BackgroundGrid<dim> &grid, const GridCell<dim> &cell)
  {
    return static_cast<unsigned int>(&cell - grid.cells.data());
  }
} // namespace dealmpm
