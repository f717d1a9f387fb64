#include <deal.II/base/mpi.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/fem/nodes_on_grid.h>

#include <limits>
#include <sstream>

#include "../transfer/node_accumulator.h"

namespace dealmpm
{
  template <int dim>
  void
  NodesOnGrid<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
    const auto add = [&](const GridCell<dim> &c) {
      const auto vertices = c.vertices();
      boxes.emplace_back(BoundingBox<dim>(std::vector<Point<dim>>(
                           vertices.begin(), vertices.end())),
                         static_cast<unsigned int>(boxes.size()));
      // A point on a face must be found by both cells.
      boxes.back().first.extend(1e-10 * c.h);
    };
    for (const GridCell<dim> &c : grid.cells)
      add(c);
    for (const GridCell<dim> &c : grid.ghost_cells)
      add(c);
    tree = pack_rtree(boxes);
  }

  template <int dim>
  void
  NodesOnGrid<dim>::gather_and_place(const BackgroundGrid<dim> &grid,
                                     const std::vector<double> &mine,
                                     const unsigned int         n)
  {
    n_values = n;
    n_mine   = mine.size() / n;
    gather(mine, grid.comm);

    const unsigned int this_rank = Utilities::MPI::this_mpi_process(grid.comm);
    on_this_rank.clear();
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
    for (std::size_t point = 0; point < n_global; ++point)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = value(point, d);
        Point<dim>           xi;
        const GridCell<dim> *cell = placing_cell(grid, x, this_rank, hits, xi);
        if (cell != nullptr)
          on_this_rank.push_back(place(grid, point, *cell, xi));
      }
  }

  template <int dim>
  void
  NodesOnGrid<dim>::gather(const std::vector<double> &mine, const MPI_Comm comm)
  {
    const unsigned int this_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks   = Utilities::MPI::n_mpi_processes(comm);
    const int          size      = static_cast<int>(mine.size());
    std::vector<int>   sizes(n_ranks), offsets(n_ranks + 1, 0);
    int ierr = MPI_Allgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, comm);
    AssertThrowMPI(ierr);
    for (unsigned int r = 0; r < n_ranks; ++r)
      offsets[r + 1] = offsets[r] + sizes[r];
    all.resize(offsets[n_ranks]);
    ierr = MPI_Allgatherv(mine.data(),
                          size,
                          MPI_DOUBLE,
                          all.data(),
                          sizes.data(),
                          offsets.data(),
                          MPI_DOUBLE,
                          comm);
    AssertThrowMPI(ierr);
    first    = offsets[this_rank] / n_values;
    n_global = all.size() / n_values;
  }

  template <int dim>
  const GridCell<dim> *
  NodesOnGrid<dim>::placing_cell(
    const BackgroundGrid<dim>                              &grid,
    const Point<dim>                                       &x,
    const unsigned int                                      this_rank,
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> &hits,
    Point<dim>                                             &xi) const
  {
    const std::size_t n_owned = grid.cells.size();
    hits.clear();
    tree.query(boost::geometry::index::intersects(x), std::back_inserter(hits));
    // The lowest rank that owns a cell holding x places it, in an
    // owned cell of its own.
    unsigned int         lowest     = std::numeric_limits<unsigned int>::max();
    const GridCell<dim> *owned_cell = nullptr;
    for (const auto &hit : hits)
      {
        const bool           is_owned = hit.second < n_owned;
        const GridCell<dim> &c        = is_owned ?
                                          grid.cells[hit.second] :
                                          grid.ghost_cells[hit.second - n_owned];
        const Point<dim>     unit     = c.reference_point(x);
        bool                 inside   = true;
        for (unsigned int d = 0; d < dim; ++d)
          inside = inside && unit[d] > -1e-10 && unit[d] < 1 + 1e-10;
        if (!inside)
          continue;
        lowest =
          std::min(lowest, is_owned ? this_rank : c.cell->subdomain_id());
        if (is_owned && owned_cell == nullptr)
          {
            owned_cell = &c;
            xi         = unit;
          }
      }
    return lowest == this_rank ? owned_cell : nullptr;
  }

  template <int dim>
  typename NodesOnGrid<dim>::Placed
  NodesOnGrid<dim>::place(const BackgroundGrid<dim> &grid,
                          const std::size_t          point,
                          const GridCell<dim>       &c,
                          Point<dim>                 xi) const
  {
    constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
    for (unsigned int d = 0; d < dim; ++d)
      xi[d] = std::min(1., std::max(0., xi[d]));
    double N[n_vertices];
    q1_values<dim>(xi, N, nullptr);
    Placed p{point, {}, {}};
    p.nodes.assign(&grid.cell_nodes[c.first_node],
                   &grid.cell_nodes[c.first_node] + c.n_nodes);
    p.weights.assign(c.n_nodes, 0.);
    for (unsigned int k = 0; k < c.n_nodes; ++k)
      if (c.first_weight == numbers::invalid_unsigned_int)
        p.weights[k] = N[k];
      else
        for (unsigned int v = 0; v < n_vertices; ++v)
          p.weights[k] +=
            grid.cell_node_weights[c.first_weight + k * n_vertices + v] * N[v];
    return p;
  }

  template <int dim>
  std::vector<double>
  NodesOnGrid<dim>::sum_to_owners(std::vector<double> &per_point,
                                  const unsigned int   n_components,
                                  const MPI_Comm       comm,
                                  const bool           all_placed) const
  {
    // One more component: how many ranks placed the point.
    const unsigned int  width = n_components + 1;
    std::vector<double> sum(width * n_global, 0.);
    for (std::size_t p = 0; p < n_global; ++p)
      for (unsigned int k = 0; k < n_components; ++k)
        sum[width * p + k] = per_point[n_components * p + k];
    for (const Placed &p : on_this_rank)
      sum[width * p.point + n_components] = 1;
    Utilities::MPI::sum(sum, comm, sum);
    for (std::size_t p = 0; p < n_global; ++p)
      if (all_placed && sum[width * p + n_components] != 1.)
        {
          std::ostringstream where;
          where << "a coupling node of an FEM region at (";
          for (unsigned int d = 0; d < dim; ++d)
            where << (d > 0 ? ", " : "") << value(p, d);
          where << ") left the background grid; a larger grid, or walls "
                   "that hold the region, may help";
          throw RunError(where.str());
        }
    std::vector<double> mine(n_components * n_mine);
    for (std::size_t j = 0; j < n_mine; ++j)
      for (unsigned int k = 0; k < n_components; ++k)
        mine[n_components * j + k] = sum[width * (first + j) + k];
    return mine;
  }

  template class NodesOnGrid<2>;
  template class NodesOnGrid<3>;
} // namespace dealmpm
