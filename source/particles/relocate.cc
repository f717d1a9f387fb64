// ParticleSet::relocate: the particles that left their cells during a step
// are moved into their new cells in the step's order, instead of by
// deal.II's sort of the whole pool (see doc/lean-step.md).
#include <deal.II/base/geometry_info.h>

#include <dealmpm/grid/side_neighbors.h>
#include <dealmpm/particles/hold_at_walls.h>
#include <dealmpm/particles/particle_set.h>

#include <algorithm>
#include <numeric>

namespace dealmpm
{
  namespace
  {
    constexpr unsigned int none = numbers::invalid_unsigned_int;

    /** The index in grid.cells of a locally owned cell that shares a vertex
     * with grid.cells[i] and holds @p x (its unit-cell coordinates go to
     * @p xi), or none: then @p x lies in another rank's cell, beyond the
     * neighbours or outside the grid. On grids of boxes the neighbour on
     * the side the particle left by (@p xi_old) is tried first. */
    template <int dim>
    unsigned int
    owned_neighbor_holding(const BackgroundGrid<dim> &grid,
                           const unsigned int         i,
                           const Point<dim>          &x,
                           const Point<dim>          &xi_old,
                           Point<dim>                &xi)
    {
      // Owned cells only: a ghost cell's particles are another rank's.
      const auto holds = [&](const unsigned int k) {
        if (k == i || k >= grid.cells.size())
          return false;
        xi = grid.cells[k].reference_point(x);
        return GeometryInfo<dim>::is_inside_unit_cell(xi);
      };
      if (grid.has_side_neighbors())
        {
          const GridCell<dim> *guess =
            side_neighbors::owned_at(grid, i, side_neighbors::side_of(xi_old));
          if (guess != nullptr && holds(guess - grid.cells.data()))
            return guess - grid.cells.data();
        }
      for (const unsigned int k : grid.neighbors_of(i))
        if (holds(k))
          return k;
      return none;
    }

    /** Checks particles against their cells (see check()) and collects
     * the moves: each particle that left its cell, by its position in the
     * step's order, its old and new cell and its unit-cell coordinates in
     * the new one. */
    template <int dim>
    struct MoveFinder
    {
      const BackgroundGrid<dim>                    &grid;
      const std::set<types::boundary_id>           &walls;
      const CoreFields                             &fields;
      const ParticleOrder<dim>                     &order;
      Particles::PropertyPool<dim>                 &pool;
      std::vector<typename ParticleSet<dim>::Move> &moves;
      /** What check() changed in the pool, in order; not kept where the
       * plan cannot be cancelled. */
      std::vector<typename ParticleSet<dim>::PoolEdit> &edits;
      const bool                                        keep_edits;
      unsigned int                                      n_held    = 0;
      bool                                              found_all = true;

      typename ParticleSet<dim>::PoolEdit
      before_edit(const typename ParticleOrder<dim>::Handle handle,
                  const bool                                with_properties)
      {
        typename ParticleSet<dim>::PoolEdit edit{handle,
                                                 pool.get_location(handle),
                                                 pool.get_reference_location(
                                                   handle),
                                                 {}};
        if (with_properties)
          {
            const ArrayView<const double> props = pool.get_properties(handle);
            edit.properties.assign(props.begin(), props.end());
          }
        return edit;
      }

      /** hold_at_walls(), and the particle as it was if it held it. */
      bool
      hold(const typename ParticleOrder<dim>::Handle handle,
           const unsigned int                        i,
           const Point<dim>                         &xi)
      {
        if (!keep_edits)
          return hold_at_walls(grid.cells[i], walls, fields, pool, handle, xi);
        auto before = before_edit(handle, true);
        if (!hold_at_walls(grid.cells[i], walls, fields, pool, handle, xi))
          return false;
        edits.push_back(std::move(before));
        return true;
      }

      /** Particle @p k of the order, listed in grid.cells[@p i]: one
       * outside that crossed a wall is put back on it; one (then) inside
       * gets its unit-cell coordinates (as deal.II's sort sets them), one
       * outside a Move. found_all turns false
       * when a particle needs deal.II's sort (the rest are still held). */
      void
      check(const unsigned int k, const unsigned int i)
      {
        const auto        handle = order.handles[k];
        const Point<dim> &x      = pool.get_location(handle);
        Point<dim>        xi     = grid.cells[i].reference_point(x);
        bool              inside = GeometryInfo<dim>::is_inside_unit_cell(xi);
        if (!inside && !walls.empty() &&
            side_neighbors::may_be_beyond_a_wall(grid, i, xi) &&
            hold(handle, i, xi))
          {
            ++n_held; // x (a reference into the pool) is on the wall now
            xi     = grid.cells[i].reference_point(x);
            inside = GeometryInfo<dim>::is_inside_unit_cell(xi);
          }
        if (inside)
          {
            if (keep_edits)
              edits.push_back(before_edit(handle, false));
            pool.set_reference_location(handle, xi);
            return;
          }
        Point<dim>   xi_new;
        unsigned int to_cell = none;
        if (found_all)
          to_cell = owned_neighbor_holding(grid, i, x, xi, xi_new);
        found_all = found_all && to_cell != none;
        if (!found_all)
          return;
        moves.push_back({k, i, to_cell, false, xi_new});
      }
    };

    /** Before the check of leaver @p j: ask the cache for the location of
     * leaver j + 16 and for the cell leaver j + 8 likely enters. The
     * leavers' locations are spread over the pool (see
     * prefetch_particles()) and the cells they enter over the grid's
     * cells: in the flowing column, check() stalled on that cell half its
     * time. */
    template <int dim>
    void
    prefetch_for_check(const MoveFinder<dim>                    &finder,
                       const typename ParticleSet<dim>::Leavers &leavers,
                       const std::size_t                         j)
    {
      const auto       &pool    = finder.pool;
      const auto       &grid    = finder.grid;
      const auto       &handles = finder.order.handles;
      const std::size_t n       = leavers.position.size();
      if (j + 16 < n)
        __builtin_prefetch(
          &pool.get_location(handles[leavers.position[j + 16]]));
      if (j + 8 >= n || !grid.has_side_neighbors())
        return;
      const unsigned int i = leavers.cell[j + 8];
      side_neighbors::prefetch_cell(grid.side_neighbor(
        i,
        side_neighbors::side_of(grid.cells[i].reference_point(
          pool.get_location(handles[leavers.position[j + 8]])))));
    }

    /** The moves, by position in the step's order: those G2P found itself
     * (already in @p finder.moves) and those of the other particles it saw
     * leave (@p leavers, when it
     * recorded them; every other particle is inside its cell at the
     * reference location G2P set), else of every particle. */
    template <int dim>
    void
    find_moves(MoveFinder<dim>                          &finder,
               const typename ParticleSet<dim>::Leavers &leavers)
    {
      const ParticleOrder<dim> &order = finder.order;
      auto                     &moves = finder.moves;
      if (!leavers.recorded)
        {
          for (unsigned int i = 0; i < finder.grid.cells.size(); ++i)
            for (unsigned int k = order.cell_begin[i];
                 k < order.cell_begin[i + 1];
                 ++k)
              finder.check(k, i);
          return;
        }
      const std::size_t by_g2p = moves.size();
      for (std::size_t j = 0; j < leavers.position.size(); ++j)
        {
          prefetch_for_check(finder, leavers, j);
          finder.check(leavers.position[j], leavers.cell[j]);
        }
      // Both G2P's and these are in the step's order: G2P's sweep and the
      // leavers it records visit the particles in it.
      const auto by_position = [](const auto &a, const auto &b) {
        return a.position < b.position;
      };
      std::inplace_merge(moves.begin(),
                         moves.begin() + by_g2p,
                         moves.end(),
                         by_position);
      Assert(std::is_sorted(moves.begin(), moves.end(), by_position),
             ExcMessage("The moves G2P found are not in the step's order."));
    }

    /** The step's order after @p moves (by position in it), in
     * @p spare's arrays (which then get the old ones): each cell's
     * particles that stayed, in their order (by id), and those that
     * entered it put among them by id (as order_by_id() would order the
     * cell). A particle that stayed is copied, and its id is read only
     * where one enters its cell after it. */
    template <int dim, typename Spare>
    void
    regroup(ParticleOrder<dim>                                 &order,
            const Particles::PropertyPool<dim>                 &pool,
            const std::vector<typename ParticleSet<dim>::Move> &moves,
            Spare                                              &spare)
    {
      const std::vector<unsigned int> &old_begin = order.cell_begin;
      const auto                      &old       = order.handles;
      const std::size_t                n_cells   = old_begin.size() - 1;
      // Each cell's new size: the old one, less those that left, plus
      // those that entered; then the new cell_begin.
      auto &begin = spare.cell_begin;
      begin.resize(n_cells + 1);
      begin[0] = 0;
      for (std::size_t i = 0; i < n_cells; ++i)
        begin[i + 1] = old_begin[i + 1] - old_begin[i];
      for (const auto &move : moves)
        {
          --begin[move.from + 1];
          ++begin[move.to + 1];
        }
      std::partial_sum(begin.begin(), begin.end(), begin.begin());
      // Those that stayed, in their order; filled[i]: where grid.cells[i]'s
      // arrivals go.
      auto &grouped = spare.handles;
      auto &filled  = spare.filled;
      grouped.resize(old.size());
      filled.resize(n_cells);
      auto next_move = moves.begin();
      for (std::size_t i = 0; i < n_cells; ++i)
        {
          unsigned int out = begin[i];
          for (unsigned int k = old_begin[i]; k < old_begin[i + 1]; ++k)
            if (next_move != moves.end() && next_move->position == k)
              ++next_move;
            else
              grouped[out++] = old[k];
          filled[i] = out;
        }
      // Each that entered put among its cell's particles by id as it is
      // added, its id read once: those before it are in id order already,
      // and it is compared only with those it passes and one more.
      for (const auto &move : moves)
        {
          const auto   handle = old[move.position];
          const auto   id     = pool.get_id(handle);
          unsigned int k      = filled[move.to]++;
          for (; k > begin[move.to] && id < pool.get_id(grouped[k - 1]); --k)
            grouped[k] = grouped[k - 1];
          grouped[k] = handle;
        }
      order.adopt(grouped, begin);
    }

    /** The plan's moves are done with: their memory goes back to G2P's
     * list (@p g2p), which fills it in the next step, and only one such
     * list is kept (32-40 B a move). */
    template <typename Move>
    void
    hand_back(std::vector<Move> &planned, std::vector<Move> &g2p)
    {
      planned.clear();
      g2p.clear();
      if (planned.capacity() > g2p.capacity())
        g2p.swap(planned);
      std::vector<Move>().swap(planned);
    }
  } // namespace

  template <int dim>
  int
  ParticleSet<dim>::plan_relocation(BackgroundGrid<dim>                &grid,
                                    const std::set<types::boundary_id> &walls,
                                    unsigned int                       &n_held,
                                    const bool may_cancel)
  {
    grid.find_neighbors();
    const ParticleOrder<dim> &now = order_over(grid);
    planned_edits.clear();
    planned_moves.clear();
    if (leavers.recorded)
      planned_moves.swap(leavers.moves);
    planned_may_cancel = may_cancel;
    MoveFinder<dim> finder{grid,
                           walls,
                           fields,
                           now,
                           handler.get_property_pool(),
                           planned_moves,
                           planned_edits,
                           may_cancel};
    find_moves(finder, leavers);
    n_held = finder.n_held;
    return finder.found_all ? (planned_moves.empty() ? 0 : 1) : 2;
  }

  template <int dim>
  void
  ParticleSet<dim>::cancel_relocation()
  {
    // A plan made without records (a particle here surely relocates)
    // cannot be undone.
    AssertThrow(planned_may_cancel, ExcInternalError());
    auto &pool = handler.get_property_pool();
    for (auto edit = planned_edits.rbegin(); edit != planned_edits.rend();
         ++edit)
      {
        pool.set_location(edit->handle, edit->location);
        pool.set_reference_location(edit->handle, edit->reference);
        if (!edit->properties.empty())
          std::copy(edit->properties.begin(),
                    edit->properties.end(),
                    pool.get_properties(edit->handle).begin());
      }
    planned_edits.clear();
    hand_back(planned_moves, leavers.moves);
  }

  template <int dim>
  bool
  ParticleSet<dim>::finish_relocation(const BackgroundGrid<dim> &grid,
                                      const int                  everywhere)
  {
    leavers.recorded = false;
    planned_edits.clear();
    const std::vector<Move> &moves = planned_moves;
    if (everywhere == 2)
      {
        hand_back(planned_moves, leavers.moves);
        sort();
        return false;
      }
    // The order is rebuilt from deal.II's lists, so before they may lag
    // (on a rank that planned nothing, the order may be out of date).
    const ParticleOrder<dim> &now = order_over(grid);
    handler_lags                  = handler_lags || everywhere == 1;
    if (moves.empty())
      {
        hand_back(planned_moves, leavers.moves);
        return true;
      }
    auto &pool = handler.get_property_pool();
    for (std::size_t j = 0; j < moves.size(); ++j)
      {
        if (j + 8 < moves.size() && !moves[j + 8].placed)
          __builtin_prefetch(&pool.get_reference_location(
                               now.handles[moves[j + 8].position]),
                             1);
        if (!moves[j].placed)
          pool.set_reference_location(now.handles[moves[j].position],
                                      moves[j].reference);
      }
    regroup(order, pool, moves, spare);
    hand_back(planned_moves, leavers.moves);
    return true;
  }

  template int
  ParticleSet<2>::plan_relocation(BackgroundGrid<2> &,
                                  const std::set<types::boundary_id> &,
                                  unsigned int &,
                                  bool);
  template int
  ParticleSet<3>::plan_relocation(BackgroundGrid<3> &,
                                  const std::set<types::boundary_id> &,
                                  unsigned int &,
                                  bool);
  template void
  ParticleSet<2>::cancel_relocation();
  template void
  ParticleSet<3>::cancel_relocation();
  template bool
  ParticleSet<2>::finish_relocation(const BackgroundGrid<2> &, const int);
  template bool
  ParticleSet<3>::finish_relocation(const BackgroundGrid<3> &, const int);
} // namespace dealmpm
