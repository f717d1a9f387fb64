#include <deal.II/base/mpi.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/fem/bonded_coupling.h>

#include <limits>
#include <sstream>

#include "../transfer/node_accumulator.h"

namespace dealmpm
{
  namespace
  {
    /** x, m, m v, f per node. */
    template <int dim>
    constexpr unsigned int values_per_node = 3 * dim + 1;

    /** The weights of the effective nodes of @p c at unit point @p xi:
     * Q1 values, hanging nodes passed to their masters. */
    template <int dim>
    void
    linear_weights(const BackgroundGrid<dim> &grid,
                   const GridCell<dim>       &c,
                   const Point<dim>          &xi,
                   std::vector<unsigned int> &nodes,
                   std::vector<double>       &weights)
    {
      constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
      double                 N[n_vertices];
      q1_values<dim>(xi, N, nullptr);
      nodes.assign(&grid.cell_nodes[c.first_node],
                   &grid.cell_nodes[c.first_node] + c.n_nodes);
      weights.assign(c.n_nodes, 0.);
      for (unsigned int n = 0; n < c.n_nodes; ++n)
        if (c.first_weight == numbers::invalid_unsigned_int)
          weights[n] = N[n];
        else
          for (unsigned int v = 0; v < n_vertices; ++v)
            weights[n] +=
              grid.cell_node_weights[c.first_weight + n * n_vertices + v] *
              N[v];
    }
  } // namespace

  template <int dim>
  BondedCoupling<dim>::BondedCoupling(SolidRegion<dim>  &region,
                                      const unsigned int body)
    : region(region)
    , body(body)
  {
    for (unsigned int k = 0; k < region.nodes.size(); ++k)
      if (region.nodes[k].kind == SolidRegion<dim>::Node::Kind::bonded)
        local.push_back(k);
    n_global = Utilities::MPI::sum(local.size(), region.comm);
  }

  template <int dim>
  void
  BondedCoupling<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
    const auto add = [&](const GridCell<dim> &c) {
      boxes.emplace_back(BoundingBox<dim>(std::vector<Point<dim>>(
                           c.vertices.begin(), c.vertices.end())),
                         static_cast<unsigned int>(boxes.size()));
      // A node on a face must be found by both cells.
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
  BondedCoupling<dim>::deposit(const BackgroundGrid<dim> &grid,
                               NodalFieldSet<dim>        &set)
  {
    constexpr unsigned int n_values = values_per_node<dim>;
    std::vector<double>    mine;
    mine.reserve(local.size() * n_values);
    for (const unsigned int k : local)
      {
        const auto          &node = region.nodes[k];
        const Point<dim>     x    = region.position(node);
        const double         m    = region.mass.local_element(node.dof[0]);
        const Tensor<1, dim> v    = region.node_vector(region.velocity, node);
        const Tensor<1, dim> f    = region.node_vector(region.force, node);
        for (unsigned int d = 0; d < dim; ++d)
          mine.push_back(x[d]);
        mine.push_back(m);
        for (unsigned int d = 0; d < dim; ++d)
          mine.push_back(m * v[d]);
        for (unsigned int d = 0; d < dim; ++d)
          mine.push_back(f[d]);
      }
    const std::vector<std::vector<double>> all =
      Utilities::MPI::all_gather(grid.comm, mine);

    const unsigned int this_rank = Utilities::MPI::this_mpi_process(grid.comm);
    const std::size_t  n_owned   = grid.cells.size();
    std::vector<NodalFields<dim> *> targets{&set.core};
    if (set.has_body_fields())
      targets.push_back(&set.body[body]);
    for (NodalFields<dim> *fields : targets)
      {
        fields->mass.zero_out_ghost_values();
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields->momentum[d].zero_out_ghost_values();
            fields->force[d].zero_out_ghost_values();
          }
      }

    placed.clear();
    std::size_t                                            index = 0;
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
    std::vector<unsigned int>                              nodes;
    std::vector<double>                                    weights;
    for (const std::vector<double> &from_rank : all)
      for (std::size_t j = 0; j < from_rank.size(); j += n_values, ++index)
        {
          const double *value = &from_rank[j];
          Point<dim>    x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = value[d];
          hits.clear();
          tree.query(boost::geometry::index::intersects(x),
                     std::back_inserter(hits));
          // The lowest rank that owns a cell holding x deposits it, from
          // an owned cell of its own.
          unsigned int lowest = std::numeric_limits<unsigned int>::max();
          const GridCell<dim> *owned_cell = nullptr;
          Point<dim>           owned_xi;
          for (const auto &hit : hits)
            {
              const bool           is_owned  = hit.second < n_owned;
              const GridCell<dim> &c         = is_owned ?
                                                 grid.cells[hit.second] :
                                                 grid.ghost_cells[hit.second - n_owned];
              const Point<dim>     xi        = c.reference_point(x);
              bool                 contained = true;
              for (unsigned int d = 0; d < dim; ++d)
                contained = contained && xi[d] > -1e-10 && xi[d] < 1 + 1e-10;
              if (!contained)
                continue;
              const unsigned int owner =
                is_owned ? this_rank : c.cell->subdomain_id();
              lowest = std::min(lowest, owner);
              if (is_owned && owned_cell == nullptr)
                {
                  owned_cell = &c;
                  owned_xi   = xi;
                }
            }
          if (lowest != this_rank || owned_cell == nullptr)
            continue;
          Point<dim> xi = owned_xi;
          for (unsigned int d = 0; d < dim; ++d)
            xi[d] = std::min(1., std::max(0., xi[d]));
          placed.push_back({index, owned_cell, xi});
          linear_weights(grid, *owned_cell, xi, nodes, weights);
          for (NodalFields<dim> *fields : targets)
            for (unsigned int n = 0; n < nodes.size(); ++n)
              {
                fields->mass.local_element(nodes[n]) += weights[n] * value[dim];
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    fields->momentum[d].local_element(nodes[n]) +=
                      weights[n] * value[dim + 1 + d];
                    fields->force[d].local_element(nodes[n]) +=
                      weights[n] * value[2 * dim + 1 + d];
                  }
              }
        }
    for (NodalFields<dim> *fields : targets)
      {
        fields->mass.compress(VectorOperation::add);
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields->momentum[d].compress(VectorOperation::add);
            fields->force[d].compress(VectorOperation::add);
          }
      }
  }

  template <int dim>
  void
  BondedCoupling<dim>::read_back(const BackgroundGrid<dim> &grid,
                                 const NodalFieldSet<dim>  &set)
  {
    // v per node and a count of the ranks that placed it, summed.
    std::vector<double>     v((dim + 1) * n_global, 0.);
    const NodalFields<dim> &fields =
      set.has_body_fields() ? set.body[body] : set.core;
    std::vector<unsigned int> nodes;
    std::vector<double>       weights;
    for (const Placed &p : placed)
      {
        linear_weights(grid, *p.cell, p.xi, nodes, weights);
        for (unsigned int n = 0; n < nodes.size(); ++n)
          for (unsigned int d = 0; d < dim; ++d)
            v[(dim + 1) * p.node + d] +=
              weights[n] * fields.velocity[d].local_element(nodes[n]);
        v[(dim + 1) * p.node + dim] += 1;
      }
    Utilities::MPI::sum(v, grid.comm, v);

    // This rank's nodes are at its offset among all.
    const std::vector<std::size_t> counts =
      Utilities::MPI::all_gather(grid.comm, local.size());
    std::size_t first = 0;
    for (unsigned int r = 0; r < Utilities::MPI::this_mpi_process(grid.comm);
         ++r)
      first += counts[r];
    for (std::size_t n = 0; n < n_global; ++n)
      if (v[(dim + 1) * n + dim] != 1.)
        {
          // Which node: its owner says where it is.
          const bool         mine = n >= first && n < first + local.size();
          std::ostringstream message;
          if (mine)
            message << "a bonded node of an FEM region at ("
                    << region.position(region.nodes[local[n - first]])
                    << ") left the background grid; a larger grid or a "
                       "wall that holds the region may help";
          const std::string text = Utilities::MPI::broadcast(
            grid.comm,
            message.str(),
            Utilities::MPI::max(mine ?
                                  Utilities::MPI::this_mpi_process(grid.comm) :
                                  0u,
                                grid.comm));
          throw RunError(text);
        }
    region.velocity.zero_out_ghost_values();
    for (std::size_t j = 0; j < local.size(); ++j)
      {
        const auto &node = region.nodes[local[j]];
        for (unsigned int d = 0; d < dim; ++d)
          region.velocity.local_element(node.dof[d]) =
            v[(dim + 1) * (first + j) + d];
      }
  }

  template class BondedCoupling<2>;
  template class BondedCoupling<3>;
} // namespace dealmpm
