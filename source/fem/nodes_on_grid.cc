#include <deal.II/base/mpi.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/fem/nodes_on_grid.h>

#include <algorithm>
#include <limits>
#include <sstream>

#include "../transfer/node_accumulator.h"

namespace dealmpm
{
  namespace
  {
    // Tags of the points and of the answers (NodalExchange uses 7301-2).
    constexpr int points_tag  = 7303;
    constexpr int answers_tag = 7304;

    /** Send @p values to @p rank (its request into @p requests). */
    void
    send(const std::vector<double> &values,
         const unsigned int         rank,
         const int                  tag,
         const MPI_Comm             comm,
         std::vector<MPI_Request>  &requests)
    {
      requests.emplace_back();
      const int ierr = MPI_Isend(values.data(),
                                 static_cast<int>(values.size()),
                                 MPI_DOUBLE,
                                 rank,
                                 tag,
                                 comm,
                                 &requests.back());
      AssertThrowMPI(ierr);
    }

    /** Receive @p rank's message, of the size it has, into @p to from
     * position @p at; returns that size. */
    std::size_t
    receive(std::vector<double> &to,
            const std::size_t    at,
            const unsigned int   rank,
            const int            tag,
            const MPI_Comm       comm)
    {
      MPI_Status status;
      int        ierr = MPI_Probe(rank, tag, comm, &status);
      AssertThrowMPI(ierr);
      int size = 0;
      ierr     = MPI_Get_count(&status, MPI_DOUBLE, &size);
      AssertThrowMPI(ierr);
      to.resize(std::max(to.size(), at + size));
      ierr = MPI_Recv(
        to.data() + at, size, MPI_DOUBLE, rank, tag, comm, MPI_STATUS_IGNORE);
      AssertThrowMPI(ierr);
      return size;
    }

    void
    wait_for(std::vector<MPI_Request> &requests)
    {
      const int ierr = MPI_Waitall(static_cast<int>(requests.size()),
                                   requests.data(),
                                   MPI_STATUSES_IGNORE);
      AssertThrowMPI(ierr);
    }

    template <int dim>
    Point<dim>
    point_at(const double *x)
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = x[d];
      return p;
    }
  } // namespace

  template <int dim>
  void
  NodesOnGrid<dim>::Box::add(const Point<dim> &x)
  {
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = empty ? x[d] : std::min(lower[d], x[d]);
        upper[d] = empty ? x[d] : std::max(upper[d], x[d]);
      }
    empty = false;
  }

  template <int dim>
  void
  NodesOnGrid<dim>::Box::widen(const double by)
  {
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] -= by;
        upper[d] += by;
      }
  }

  template <int dim>
  bool
  NodesOnGrid<dim>::Box::contains(const Point<dim> &x) const
  {
    bool inside = !empty;
    for (unsigned int d = 0; d < dim; ++d)
      inside = inside && x[d] >= lower[d] && x[d] <= upper[d];
    return inside;
  }

  template <int dim>
  bool
  NodesOnGrid<dim>::Box::meets(const Box &other) const
  {
    bool meet = !empty && !other.empty;
    for (unsigned int d = 0; d < dim; ++d)
      meet = meet && lower[d] <= other.upper[d] && other.lower[d] <= upper[d];
    return meet;
  }

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
    tree            = pack_rtree(boxes);
    publish_pending = true;
  }

  template <int dim>
  void
  NodesOnGrid<dim>::publish(const BackgroundGrid<dim> &grid,
                            const std::vector<double> &mine)
  {
    Box    owned, points;
    double largest = 0;
    for (const GridCell<dim> &c : grid.cells)
      {
        for (const Point<dim> &v : c.vertices())
          owned.add(v);
        largest = std::max(largest, c.h);
      }
    for (std::size_t j = 0; j < mine.size() / n_values; ++j)
      points.add(point_at<dim>(&mine[j * n_values]));
    std::vector<double> local;
    for (const Box *box : {&owned, &points})
      {
        local.push_back(box->empty ? 1. : 0.);
        for (const Point<dim> &corner : {box->lower, box->upper})
          for (unsigned int d = 0; d < dim; ++d)
            local.push_back(corner[d]);
      }
    local.push_back(largest);
    const int           width   = static_cast<int>(local.size());
    const unsigned int  n_ranks = Utilities::MPI::n_mpi_processes(grid.comm);
    std::vector<double> all(width * n_ranks);
    const int           ierr = MPI_Allgather(local.data(),
                                   width,
                                   MPI_DOUBLE,
                                   all.data(),
                                   width,
                                   MPI_DOUBLE,
                                   grid.comm);
    AssertThrowMPI(ierr);
    read_publication(all);
    publish_pending = false;
    ++publications;
  }

  template <int dim>
  void
  NodesOnGrid<dim>::read_publication(const std::vector<double> &all)
  {
    constexpr unsigned int box_width = 2 * dim + 1;
    constexpr unsigned int width     = 2 * box_width + 1;
    const unsigned int     n_ranks   = all.size() / width;
    const auto             read_box  = [&](const double *at) {
      Box box;
      box.empty = at[0] != 0.;
      box.lower = point_at<dim>(at + 1);
      box.upper = point_at<dim>(at + 1 + dim);
      return box;
    };
    double reach = 0; // the largest cell
    for (unsigned int r = 0; r < n_ranks; ++r)
      reach = std::max(reach, all[r * width + width - 1]);
    std::vector<Box> point_boxes(n_ranks);
    owned_boxes.resize(n_ranks);
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        owned_boxes[r] = read_box(&all[r * width]);
        owned_boxes[r].widen(1e-8 * reach); // round-off on its faces
        point_boxes[r] = read_box(&all[r * width + box_width]);
        point_boxes[r].widen(3 * reach);
      }
    published   = point_boxes[this_rank];
    stay_within = published;
    stay_within.widen(-reach);
    links.clear();
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        Link link;
        link.rank     = r;
        link.sends    = owned_boxes[r].meets(published);
        link.receives = point_boxes[r].meets(owned_boxes[this_rank]);
        if (link.sends || link.receives)
          links.push_back(link);
      }
  }

  template <int dim>
  void
  NodesOnGrid<dim>::fail(const Point<dim> &x, const std::string &what)
  {
    if (!failed.empty())
      return;
    std::ostringstream where;
    where << "a coupling node of an FEM region at (";
    for (unsigned int d = 0; d < dim; ++d)
      where << (d > 0 ? ", " : "") << x[d];
    where << ") " << what;
    failed = where.str();
  }

  template <int dim>
  void
  NodesOnGrid<dim>::address_points(const std::vector<double> &mine)
  {
    for (Link &link : links)
      link.sent.clear();
    own_points.resize(mine.size() / n_values);
    for (std::size_t j = 0; j < own_points.size(); ++j)
      {
        const Point<dim> x = point_at<dim>(&mine[j * n_values]);
        own_points[j]      = x;
        wanted             = wanted || !stay_within.contains(x);
        for (Link &link : links)
          if (link.sends && owned_boxes[link.rank].contains(x))
            link.sent.push_back(j);
        if (published.contains(x))
          continue;
        // Outside its published box: a rank that holds it but does not
        // expect it would miss it.
        for (unsigned int r = 0; r < owned_boxes.size(); ++r)
          if (owned_boxes[r].contains(x) &&
              std::none_of(links.begin(), links.end(), [&](const Link &l) {
                return l.rank == r && l.sends;
              }))
            fail(x,
                 "moved more than a cell of the background grid in one "
                 "step; a smaller 'Time/CFL number' may help");
      }
  }

  template <int dim>
  void
  NodesOnGrid<dim>::exchange_points(const std::vector<double> &mine,
                                    const MPI_Comm             comm)
  {
    std::vector<std::vector<double>> outgoing;
    outgoing.reserve(links.size());
    std::vector<MPI_Request> requests;
    const auto               pack = [&](const Link &link) {
      std::vector<double> values;
      values.reserve(link.sent.size() * n_values);
      for (const std::size_t j : link.sent)
        values.insert(values.end(),
                      &mine[j * n_values],
                      &mine[j * n_values] + n_values);
      return values;
    };
    for (const Link &link : links)
      if (link.sends && link.rank != this_rank)
        {
          outgoing.push_back(pack(link));
          send(outgoing.back(), link.rank, points_tag, comm, requests);
        }
    held.clear();
    for (Link &link : links)
      {
        link.first_received = held.size() / n_values;
        link.n_received     = 0;
        if (!link.receives)
          continue;
        if (link.rank == this_rank)
          {
            const std::vector<double> own = pack(link);
            held.insert(held.end(), own.begin(), own.end());
            link.n_received = link.sent.size();
          }
        else
          link.n_received =
            receive(held, held.size(), link.rank, points_tag, comm) / n_values;
      }
    wait_for(requests);
  }

  template <int dim>
  void
  NodesOnGrid<dim>::gather_and_place(const BackgroundGrid<dim> &grid,
                                     const std::vector<double> &mine,
                                     const unsigned int         n)
  {
    n_values  = n;
    this_rank = Utilities::MPI::this_mpi_process(grid.comm);
    wanted    = false;
    failed.clear();
    if (publish_pending)
      publish(grid, mine);
    address_points(mine);
    exchange_points(mine, grid.comm);

    on_this_rank.clear();
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
    for (std::size_t point = 0; point < n_points(); ++point)
      {
        const Point<dim>     x = point_at<dim>(&held[point * n_values]);
        Point<dim>           xi;
        const GridCell<dim> *cell = placing_cell(grid, x, this_rank, hits, xi);
        if (cell != nullptr)
          on_this_rank.push_back(place(grid, point, *cell, xi));
      }
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
  NodesOnGrid<dim>::sum_to_owners(const std::vector<double> &per_point,
                                  const unsigned int         n_components,
                                  const MPI_Comm             comm,
                                  const bool                 all_placed)
  {
    // One more component: whether this rank placed the point.
    const unsigned int width = n_components + 1;
    std::vector<char>  placed_here(n_points(), 0);
    for (const Placed &p : on_this_rank)
      placed_here[p.point] = 1;
    const auto answers = [&](const Link &link) {
      std::vector<double> values(width * link.n_received);
      for (std::size_t i = 0; i < link.n_received; ++i)
        {
          const std::size_t point = link.first_received + i;
          for (unsigned int k = 0; k < n_components; ++k)
            values[width * i + k] = per_point[n_components * point + k];
          values[width * i + n_components] = placed_here[point];
        }
      return values;
    };
    std::vector<std::vector<double>> outgoing;
    outgoing.reserve(links.size());
    std::vector<MPI_Request> requests;
    for (const Link &link : links)
      if (link.receives && link.rank != this_rank)
        {
          outgoing.push_back(answers(link));
          send(outgoing.back(), link.rank, answers_tag, comm, requests);
        }
    // The sums for this rank's points, and how many ranks placed each.
    const std::size_t   n_mine = own_points.size();
    std::vector<double> sums(width * n_mine, 0.);
    std::vector<double> incoming;
    for (const Link &link : links)
      {
        if (!link.sends)
          continue;
        if (link.rank == this_rank)
          incoming = answers(link);
        else
          {
            const std::size_t size =
              receive(incoming, 0, link.rank, answers_tag, comm);
            AssertThrow(size == width * link.sent.size(), ExcInternalError());
          }
        for (std::size_t i = 0; i < link.sent.size(); ++i)
          for (unsigned int k = 0; k < width; ++k)
            sums[width * link.sent[i] + k] += incoming[width * i + k];
      }
    wait_for(requests);
    std::vector<double> mine(n_components * n_mine);
    for (std::size_t j = 0; j < n_mine; ++j)
      {
        if (all_placed && sums[width * j + n_components] != 1.)
          fail(own_points[j],
               "left the background grid; a larger grid, or walls that "
               "hold the region, may help");
        for (unsigned int k = 0; k < n_components; ++k)
          mine[n_components * j + k] = sums[width * j + k];
      }
    return mine;
  }

  template class NodesOnGrid<2>;
  template class NodesOnGrid<3>;
} // namespace dealmpm
