#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <dealmpm/grid/background_grid.h>

#include <utility>
#include <vector>

namespace dealmpm
{
  /** Append the components of @p v to @p values (a point's values for
   * NodesOnGrid). */
  template <int dim>
  void
  append_components(std::vector<double> &values, const Tensor<1, dim> &v)
  {
    for (unsigned int d = 0; d < dim; ++d)
      values.push_back(v[d]);
  }

  /**
   * A set of moving points (an FEM region's coupling nodes) on the
   * background grid, whatever the two partitions: each rank gives its own
   * points' positions and values, all are gathered on every rank (an
   * interface has few nodes against the particles), and each point is
   * placed by one rank, the lowest that owns a cell holding it, with the
   * linear weights of that cell's effective nodes (hanging nodes passed to
   * their masters). What the ranks compute for the placed points comes
   * back to the points' owners by a sum over the ranks.
   */
  template <int dim>
  class NodesOnGrid
  {
  public:
    /** A point placed on this rank: its index among all points, the
     * local indices of the grid nodes it touches and their weights. */
    struct Placed
    {
      std::size_t               point;
      std::vector<unsigned int> nodes;
      std::vector<double>       weights;
    };

    /** After the grid changed: its cells' search tree. */
    void
    grid_changed(const BackgroundGrid<dim> &grid);

    /** Gather every rank's points (@p mine: per point its position, then
     * n_values - dim values) and place them. Collective. */
    void
    gather_and_place(const BackgroundGrid<dim> &grid,
                     const std::vector<double> &mine,
                     const unsigned int         n_values);

    /** The points placed on this rank. */
    const std::vector<Placed> &
    placed() const
    {
      return on_this_rank;
    }

    /** Value @p k of point @p point (k < n_values; the position first). */
    double
    value(const std::size_t point, const unsigned int k) const
    {
      return all[point * n_values + k];
    }

    /** Sum @p per_point (n_components per point, over all points) over the
     * ranks and return this rank's own points' part. With @p all_placed, a
     * point that no rank placed (it left the grid) stops the run
     * (RunError) with its position; without, it gets zeros. Collective. */
    std::vector<double>
    sum_to_owners(std::vector<double> &per_point,
                  const unsigned int   n_components,
                  const MPI_Comm       comm,
                  const bool           all_placed = true) const;

    std::size_t
    n_points() const
    {
      return n_global;
    }

  private:
    /** Every rank's @p mine into all (by plain MPI: deal.II's all_gather
     * of vectors serializes and compresses them, 0.9 M instructions a
     * call for 49 points); this rank's first point. Collective. */
    void
    gather(const std::vector<double> &mine, const MPI_Comm comm);

    /** The owned cell of @p grid that places @p x, if this rank
     * (@p this_rank) is the lowest that owns a cell holding it (else
     * nullptr); @p xi its reference point there. @p hits is scratch
     * space for the tree's answer. */
    const GridCell<dim> *
    placing_cell(const BackgroundGrid<dim> &grid,
                 const Point<dim>          &x,
                 const unsigned int         this_rank,
                 std::vector<std::pair<BoundingBox<dim>, unsigned int>> &hits,
                 Point<dim> &xi) const;

    /** Point @p point placed in cell @p c at reference point @p xi: the
     * cell's effective nodes and their linear weights. */
    Placed
    place(const BackgroundGrid<dim> &grid,
          const std::size_t          point,
          const GridCell<dim>       &c,
          Point<dim>                 xi) const;

    RTree<std::pair<BoundingBox<dim>, unsigned int>> tree;
    std::vector<double>                              all;
    unsigned int                                     n_values = 0;
    std::size_t                                      n_global = 0;
    std::size_t         first  = 0; ///< this rank's first point among all
    std::size_t         n_mine = 0;
    std::vector<Placed> on_this_rank;
  };
} // namespace dealmpm
