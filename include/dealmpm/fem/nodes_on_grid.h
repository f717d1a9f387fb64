#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <dealmpm/grid/background_grid.h>

#include <string>
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
   * background grid, whatever the two partitions. Each point is placed by
   * one rank, the lowest that owns a cell holding it, with the linear
   * weights of that cell's effective nodes (hanging nodes passed to their
   * masters); what that rank computes for the point goes back to the
   * point's owner.
   *
   * Without a collective per step (an interface spans few ranks): the
   * ranks publish, in one all-gather, the box of their owned cells and
   * the box of their points widened by two of the largest cells; that
   * happens at the first step, after a grid change and when a rank asks
   * for it. Each step a rank sends a point to the ranks whose owned box
   * holds it, receives from the ranks whose published point box meets its
   * own owned box, and the answers go back on the reverse pattern. A point
   * that comes within a cell of its published box's edge asks for a new
   * publication (publication_wanted(), which the step's reduction
   * carries); a point that no rank placed, or that lies in the owned box
   * of a rank it cannot be sent to, is a failure() that the step's
   * reduction turns into a stop.
   */
  template <int dim>
  class NodesOnGrid
  {
  public:
    /** A point placed on this rank: its index among the points this rank
     * holds, the local indices of the grid nodes it touches and their
     * weights. */
    struct Placed
    {
      std::size_t               point;
      std::vector<unsigned int> nodes;
      std::vector<double>       weights;
    };

    /** After the grid changed: its cells' search tree; the boxes are
     * published again at the next gather_and_place(). */
    void
    grid_changed(const BackgroundGrid<dim> &grid);

    /** Send this rank's points (@p mine: per point its position, then
     * n_values - dim values) to the ranks that may place them, receive
     * theirs and place what this rank places. Point to point, except when
     * the boxes are published. All ranks call it together. */
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
      return held[point * n_values + k];
    }

    /** Send @p per_point (n_components per point this rank holds; zeros
     * for the points it did not place) back to the points' owners and
     * return the sums for this rank's own points. With @p all_placed, a
     * point that no rank placed (it left the grid) is a failure(); without,
     * it gets zeros. Point to point. */
    std::vector<double>
    sum_to_owners(const std::vector<double> &per_point,
                  const unsigned int         n_components,
                  const MPI_Comm             comm,
                  const bool                 all_placed = true);

    /** How many points this rank holds (its own and those sent to it). */
    std::size_t
    n_points() const
    {
      return n_values == 0 ? 0 : held.size() / n_values;
    }

    /** Whether one of this rank's points came near its published box's
     * edge (to be combined over the ranks by the step's reduction). */
    bool
    publication_wanted() const
    {
      return wanted;
    }

    /** Some rank asked: publish the boxes at the next step. */
    void
    publish_at_next_step()
    {
      publish_pending = true;
    }

    /** How often the boxes were published so far. */
    unsigned int
    n_publications() const
    {
      return publications;
    }

    /** Why this rank's points could not be coupled this step, or empty. */
    const std::string &
    failure() const
    {
      return failed;
    }

  private:
    /** An axis-aligned box; empty until a point is added. */
    struct Box
    {
      Point<dim> lower, upper;
      bool       empty = true;

      void
      add(const Point<dim> &x);
      void
      widen(const double by);
      bool
      contains(const Point<dim> &x) const;
      bool
      meets(const Box &other) const;
    };

    /** What this rank exchanges with one rank (itself included): the
     * indices of its own points sent there, and where the points received
     * from there lie among those it holds. */
    struct Link
    {
      unsigned int             rank;
      bool                     sends    = false;
      bool                     receives = false;
      std::vector<std::size_t> sent;
      std::size_t              first_received = 0;
      std::size_t              n_received     = 0;
    };

    /** All-gather every rank's owned box, points' box and largest cell
     * size; who sends to whom follows. Collective. */
    void
    publish(const BackgroundGrid<dim> &grid, const std::vector<double> &mine);

    /** The links and boxes from the published @p all (per rank: owned
     * box, points' box, largest cell). */
    void
    read_publication(const std::vector<double> &all);

    /** Sort this rank's points into the links they are sent on; a point
     * near its published box's edge sets wanted, one that escaped it a
     * failure. */
    void
    address_points(const std::vector<double> &mine);

    /** Send the points on their links and receive into held. */
    void
    exchange_points(const std::vector<double> &mine, const MPI_Comm comm);

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

    /** Record the first failure this step: this rank's point at @p x,
     * and @p what happened to it. */
    void
    fail(const Point<dim> &x, const std::string &what);

    RTree<std::pair<BoundingBox<dim>, unsigned int>> tree;
    unsigned int                                     n_values  = 0;
    unsigned int                                     this_rank = 0;

    // What the last publication said.
    bool              publish_pending = true;
    unsigned int      publications    = 0;
    std::vector<Box>  owned_boxes; ///< per rank
    Box               published;   ///< this rank's points' box, widened
    Box               stay_within; ///< beyond it, publish again
    std::vector<Link> links;       ///< by rank

    // This step.
    std::vector<Point<dim>> own_points; ///< this rank's points
    std::vector<double>     held;       ///< the points this rank holds, values
    std::vector<Placed>     on_this_rank;
    bool                    wanted = false;
    std::string             failed;
  };
} // namespace dealmpm
