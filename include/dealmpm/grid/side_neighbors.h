#pragma once

// Which neighbour of a box cell a particle went to: the shared steps of
// relocation (source/particles/relocate.cc) and of G2P, which puts the
// particles that crossed one face into their new cell itself
// (g2p_sweep::enter_side_neighbor()). Both must choose alike, or the
// answers would depend on who moved a particle.
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/grid/background_grid.h>

#include <cstddef>
#include <functional>

namespace dealmpm
{
  namespace side_neighbors
  {
    /** The side of a cell, as BackgroundGrid::side_neighbor() numbers
     * them, that a point at unit-cell coordinates @p xi lies on: below
     * (0), within (1) or above (2) [0, 1] along each axis. */
    template <int dim>
    inline unsigned int
    side_of(const Point<dim> &xi)
    {
      unsigned int side = 0;
      for (unsigned int d = 0, stride = 1; d < dim; ++d, stride *= 3)
        side += stride * (xi[d] < 0 ? 0 : (xi[d] > 1 ? 2 : 1));
      return side;
    }

    /** The neighbour of owned cell @p i at @p side if it is an owned cell,
     * else nullptr (there is none, or it is a ghost cell, whose particles
     * are another rank's). */
    template <int dim>
    inline const GridCell<dim> *
    owned_at(const BackgroundGrid<dim> &grid,
             const unsigned int         i,
             const unsigned int         side)
    {
      const GridCell<dim> *const             c = grid.side_neighbor(i, side);
      const GridCell<dim> *const             begin = grid.cells.data();
      const std::less<const GridCell<dim> *> before;
      return c == nullptr || before(c, begin) ||
                 !before(c, begin + grid.cells.size()) ?
               nullptr :
               c;
    }

    /** The side (as side_of()) by which a point at unit-cell coordinates
     * @p xi left owned cell @p i of a grid of boxes
     * (grid.has_side_neighbors()), or numbers::invalid_unsigned_int if it
     * is out along some axis by no more than @p tolerance of the unit cell
     * (move()'s slack: relocation decides) or beyond a face with no cell
     * behind it (the walls decide). A face neighbour is at the centre
     * side sum_d 3^d, less or plus 3^d along the face's axis. G2P asks
     * this for every particle that leaves: one pass over the axes, out at
     * the first that rules the side out. */
    template <int dim>
    inline unsigned int
    clean_exit_side(const BackgroundGrid<dim> &grid,
                    const unsigned int         i,
                    const Point<dim>          &xi,
                    const double               tolerance = 1e-12)
    {
      constexpr unsigned int none   = numbers::invalid_unsigned_int;
      constexpr unsigned int centre = (Utilities::pow(3, dim) - 1) / 2;
      unsigned int           side   = 0;
      for (unsigned int d = 0, stride = 1; d < dim; ++d, stride *= 3)
        if (xi[d] < -tolerance)
          {
            if (grid.side_neighbor(i, centre - stride) == nullptr)
              return none;
          }
        else if (xi[d] > 1. + tolerance)
          {
            if (grid.side_neighbor(i, centre + stride) == nullptr)
              return none;
            side += 2 * stride;
          }
        else if (xi[d] < 0. || xi[d] > 1.)
          return none;
        else
          side += stride;
      return side;
    }

    /** Whether @p xi, outside owned cell @p i, may lie beyond a boundary
     * face of it (where the walls have to be asked): on grids of boxes
     * only if no cell lies across a face it is beyond (a face neighbour
     * as in clean_exit_side()); elsewhere always. Most particles that
     * leave a cell enter a neighbour, and this costs less than the walls'
     * look. */
    template <int dim>
    inline bool
    may_be_beyond_a_wall(const BackgroundGrid<dim> &grid,
                         const unsigned int         i,
                         const Point<dim>          &xi)
    {
      if (!grid.has_side_neighbors())
        return true;
      constexpr unsigned int centre = (Utilities::pow(3, dim) - 1) / 2;
      for (unsigned int d = 0, stride = 1; d < dim; ++d, stride *= 3)
        if ((xi[d] < 0 && grid.side_neighbor(i, centre - stride) == nullptr) ||
            (xi[d] > 1 && grid.side_neighbor(i, centre + stride) == nullptr))
          return true;
      return false;
    }

    /** Ask the cache for the whole of @p cell (every 64-byte line, and
     * the last byte in case it straddles one more), if there is one: the
     * flowing column's G2P and relocation stalled on reading the cell a
     * leaver enters. */
    template <int dim>
    inline void
    prefetch_cell(const GridCell<dim> *const cell)
    {
      if (cell == nullptr)
        return;
      const char *const bytes = reinterpret_cast<const char *>(cell);
      for (std::size_t b = 0; b < sizeof(GridCell<dim>); b += 64)
        __builtin_prefetch(bytes + b);
      __builtin_prefetch(bytes + sizeof(GridCell<dim>) - 1);
    }
  } // namespace side_neighbors
} // namespace dealmpm
