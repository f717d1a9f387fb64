#include <deal.II/base/mpi.h>

#include <dealmpm/transfer/quadratic_bspline.h>
#include <dealmpm/transfer/stencil_order.h>

#include <cmath>

#include "lattice_products.h"

namespace dealmpm
{
  template <int dim>
  std::string
  QuadraticBSplineGrid<dim>::check(const BackgroundGrid<dim> &grid)
  {
    const MPI_Comm comm        = grid.comm;
    bool           has_hanging = false;
    Tensor<1, dim> h_min, h_max;
    for (unsigned int d = 0; d < dim; ++d)
      {
        h_min[d] = std::numeric_limits<double>::max();
        h_max[d] = 0;
      }
    for (const GridCell<dim> &c : grid.cells)
      {
        has_hanging =
          has_hanging || c.first_weight != numbers::invalid_unsigned_int;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double length = c.far_corner[d] - c.origin[d];
            h_min[d]            = std::min(h_min[d], length);
            h_max[d]            = std::max(h_max[d], length);
          }
      }
    if (!grid.cartesian)
      return "cells that are axis-aligned boxes";
    if (Utilities::MPI::logical_or(has_hanging, comm))
      return "a grid without hanging nodes (no local refinement)";
    double n_boxes = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double lo = Utilities::MPI::min(h_min[d], comm);
        const double hi = Utilities::MPI::max(h_max[d], comm);
        if (hi - lo > 1e-10 * hi)
          return "cells of equal size";
        n_boxes *=
          std::round((grid.bounding_box.get_boundary_points().second[d] -
                      grid.bounding_box.get_boundary_points().first[d]) /
                     hi);
      }
    if (n_boxes != double(grid.triangulation.n_global_active_cells()))
      return "a grid that fills its bounding box (a rectangle or box)";
    return "";
  }

  template <int dim>
  void
  QuadraticBSplineGrid<dim>::setup(const BackgroundGrid<dim> &grid)
  {
    const auto &[lower, upper] = grid.bounding_box.get_boundary_points();
    origin                     = lower;
    const GridCell<dim> &any =
      grid.cells.empty() ? grid.ghost_cells.front() : grid.cells.front();
    for (unsigned int d = 0; d < dim; ++d)
      {
        h[d]         = any.far_corner[d] - any.origin[d];
        inverse_h[d] = 1. / h[d];
        n_cells[d]   = int(std::round((upper[d] - lower[d]) / h[d]));
      }
    const auto index_of = [&](const Point<dim> &x) {
      std::array<int, dim> index;
      for (unsigned int d = 0; d < dim; ++d)
        index[d] = int(std::round((x[d] - origin[d]) / h[d]));
      return index;
    };

    lower_index.resize(grid.cells.size());
    block_nodes.assign(grid.cells.size() * block_size,
                       numbers::invalid_unsigned_int);
    for (unsigned int i = 0; i < grid.cells.size(); ++i)
      {
        lower_index[i] = index_of(grid.cells[i].origin);
        for (const unsigned int k : grid.neighbors_of(i))
          for (unsigned int v = 0; v < GridCell<dim>::n_vertices; ++v)
            {
              const GridCell<dim>       *c        = &grid.local_cell(k);
              const std::array<int, dim> index    = index_of(c->vertex(v));
              unsigned int               position = 0, stride = 1;
              for (unsigned int d = 0; d < dim; ++d, stride *= 4)
                position += (index[d] - lower_index[i][d] + 1) * stride;
              block_nodes[i * block_size + position] =
                grid.cell_nodes[c->first_node + v];
            }
      }
  }

  template <int dim>
  void
  compute_bspline_stencil(const BackgroundGrid<dim>       &grid,
                          const QuadraticBSplineGrid<dim> &spline,
                          const ParticleSet<dim>          &particles,
                          Stencil<dim>                    &stencil)
  {
    constexpr unsigned int max_entries = Utilities::pow(3, dim);
    const std::size_t n_local = particles.handler.n_locally_owned_particles();
    stencil.begin.resize(n_local + 1);
    if (stencil.node.size() < n_local * max_entries)
      {
        stencil.node.resize(n_local * max_entries);
        stencil.N.resize(n_local * max_entries);
        stencil.grad_N.resize(n_local * max_entries);
      }
    std::size_t       e         = 0;
    const std::size_t n_visited = for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t k, const auto &p, const GridCell<dim> &c)
        DEAL_II_ALWAYS_INLINE {
          const unsigned int i = index_in_grid(grid, c);
          LatticeWeights1D   w[dim];
          spline.weights_at(i, p.get_reference_location(), w);
          append_products(
            &spline.block_nodes[i * QuadraticBSplineGrid<dim>::block_size],
            w,
            k,
            e,
            stencil);
        });
    stencil.begin[n_visited] = e;
    AssertThrow(n_visited == n_local, ExcInternalError());
  }

  template struct QuadraticBSplineGrid<2>;
  template struct QuadraticBSplineGrid<3>;
#define DEALMPM_INSTANTIATE(dim)                                           \
  template void compute_bspline_stencil(const BackgroundGrid<dim> &,       \
                                        const QuadraticBSplineGrid<dim> &, \
                                        const ParticleSet<dim> &,          \
                                        Stencil<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
