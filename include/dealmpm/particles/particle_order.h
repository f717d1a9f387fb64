#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/particles/particle_handler.h>
#include <deal.II/particles/property_pool.h>

#include <dealmpm/grid/background_grid.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /**
   * Where deal.II's property pool keeps its slots' data, fetched once a
   * sweep: a particle's properties, location and reference location are
   * then found from its handle with no call and no check of the handle
   * (the pool's getters test for the invalid handle at each call; the
   * step's order holds valid ones only). The pool must keep its slots
   * (no particle added or removed) while this is in use.
   */
  template <int dim>
  struct PoolArrays
  {
    using Pool = Particles::PropertyPool<dim>;

    Pool        *pool;
    double      *properties          = nullptr;
    Point<dim>  *locations           = nullptr;
    Point<dim>  *reference_locations = nullptr;
    unsigned int n_properties;

    explicit PoolArrays(Pool &pool)
      : pool(&pool)
      , n_properties(pool.n_properties_per_slot())
    {
      if (pool.n_slots() == 0)
        return;
      // Slot 0's addresses are the arrays' starts. The pool's points are
      // not const objects; its getters only hand them out as const.
      properties = pool.get_properties(0).data();
      locations  = const_cast<Point<dim> *>(&pool.get_location(0));
      reference_locations =
        const_cast<Point<dim> *>(&pool.get_reference_location(0));
    }
  };

  /**
   * One particle seen through deal.II's property pool (its arrays,
   * PoolArrays): the same calls as a ParticleAccessor (get_properties,
   * get_location, get_reference_location, their setters, get_id), without
   * the accessor's cell-list iterator. A read-only view (@p read_only)
   * hands out const properties and has no setters.
   */
  template <int dim, bool read_only>
  class PooledParticle
  {
  public:
    using Pool   = Particles::PropertyPool<dim>;
    using Handle = typename Pool::Handle;
    using Properties =
      std::conditional_t<read_only, ArrayView<const double>, ArrayView<double>>;

    DEAL_II_ALWAYS_INLINE
    PooledParticle(const PoolArrays<dim> &arrays, const Handle handle)
      : arrays(&arrays)
      , handle(handle)
    {}

    DEAL_II_ALWAYS_INLINE Properties
    get_properties() const
    {
      return Properties(arrays->properties +
                          std::size_t(handle) * arrays->n_properties,
                        arrays->n_properties);
    }

    DEAL_II_ALWAYS_INLINE const Point<dim>                             &
    get_location() const
    {
      return arrays->locations[handle];
    }

    DEAL_II_ALWAYS_INLINE const Point<dim>                             &
    get_reference_location() const
    {
      return arrays->reference_locations[handle];
    }

    DEAL_II_ALWAYS_INLINE types::particle_index
                          get_id() const
    {
      return arrays->pool->get_id(handle);
    }

    template <bool writable = !read_only>
    DEAL_II_ALWAYS_INLINE void
    set_location(const Point<dim> &x) const
    {
      static_assert(writable, "a read-only particle view cannot move");
      arrays->locations[handle] = x;
    }

    template <bool writable = !read_only>
    DEAL_II_ALWAYS_INLINE void
    set_reference_location(const Point<dim> &xi) const
    {
      static_assert(writable, "a read-only particle view cannot move");
      arrays->reference_locations[handle] = xi;
    }

  private:
    const PoolArrays<dim> *arrays;
    Handle                 handle;
  };

  /**
   * Put the handles of one cell's particles (@p first to @p last) in the
   * order of the particles' ids. The order the step visits particles in
   * decides the order of its sums, so it must not depend on how they got
   * into their cells (deal.II's sort, a restore,
   * ParticleSet::finish_relocation()): a checkpoint, which sorts with deal.II,
   * would otherwise change the last digits of the run it saves, and a resumed
   * run would not repeat an uninterrupted one bit for bit.
   */
  template <int dim, typename Iterator>
  void
  order_by_id(const Particles::PropertyPool<dim> &pool,
              const Iterator                      first,
              const Iterator                      last)
  {
    const auto by_id = [&pool](const auto a, const auto b) {
      return pool.get_id(a) < pool.get_id(b);
    };
    if (last - first > 32)
      {
        std::sort(first, last, by_id);
        return;
      }
    // Insertion sort: a cell's few particles, mostly in order already.
    for (Iterator i = first; i != last; ++i)
      for (Iterator j = i; j != first && by_id(*j, *(j - 1)); --j)
        std::iter_swap(j, j - 1);
  }

  /**
   * This rank's particles in the order the step visits them (grid.cells,
   * then the particles of each cell by id), as handles into deal.II's property
   * pool. Built once after the particles changed (a sort, an insertion or
   * removal, a grid change, a restore) instead of asking the handler for
   * each cell's particles in each sweep: particles_in_cell() costs about
   * 160 instructions a cell and its accessors more per particle, three
   * times a step. 4 B per particle and per cell.
   */
  template <int dim>
  class ParticleOrder
  {
  public:
    using Handle = typename Particles::PropertyPool<dim>::Handle;

    /** Walk @p handler cell by cell in @p grid's order. */
    void
    rebuild(const BackgroundGrid<dim>             &grid,
            const Particles::ParticleHandler<dim> &handler)
    {
      handles.clear();
      handles.reserve(handler.n_locally_owned_particles());
      cell_begin.resize(grid.cells.size() + 1);
      for (std::size_t i = 0; i < grid.cells.size(); ++i)
        {
          cell_begin[i] = handles.size();
          for (const auto &p : handler.particles_in_cell(grid.cells[i].cell))
            handles.push_back(static_cast<Handle>(p.get_local_index()));
          order_by_id(handler.get_property_pool(),
                      handles.begin() + cell_begin[i],
                      handles.end());
        }
      cell_begin.back() = handles.size();
      built_for         = &grid;
      grid_generation   = grid.generation;
      valid             = true;
      follows_pool      = true;
    }

    /** Whether the order describes @p grid's cells as they are now (a grid
     * change is seen here; a change of the particles alone must be said
     * with invalidate()). */
    bool
    is_valid_for(const BackgroundGrid<dim> &grid) const
    {
      return valid && built_for == &grid && grid_generation == grid.generation;
    }

    void
    invalidate()
    {
      valid = false;
    }

    /** Take @p grouped_handles, grouped by cell as handles is, with
     * @p grouped_begin as cell_begin, as the order over the same grid:
     * after particles moved between its cells without deal.II's sort.
     * The arguments get the old handles and cell_begin, for the caller
     * to reuse (a relocation every few steps then allocates nothing). */
    void
    adopt(std::vector<Handle>       &grouped_handles,
          std::vector<unsigned int> &grouped_begin)
    {
      handles.swap(grouped_handles);
      cell_begin.swap(grouped_begin);
      valid        = true;
      follows_pool = false;
    }

    /** The particles of grid.cells[i] are handles[cell_begin[i]] to
     * handles[cell_begin[i + 1] - 1]. */
    std::vector<Handle>       handles;
    std::vector<unsigned int> cell_begin;
    /** Whether the handles run through the pool about in its own order,
     * as after rebuild() (deal.II's sort puts the pool in its cells'
     * order); after adopt() they jump about, and the sweeps prefetch
     * (prefetch_particles()). */
    bool follows_pool = true;

  private:
    const BackgroundGrid<dim> *built_for       = nullptr;
    unsigned int               grid_generation = 0;
    bool                       valid           = false;
  };
} // namespace dealmpm
