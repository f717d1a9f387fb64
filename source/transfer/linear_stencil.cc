#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stencil_order.h>

#include "node_accumulator.h"

namespace dealmpm
{
  template <int dim>
  void
  compute_linear_stencil(const BackgroundGrid<dim> &grid,
                         const ParticleSet<dim>    &particles,
                         Stencil<dim>              &stencil)
  {
    constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
    const std::size_t n_local = particles.handler.n_locally_owned_particles();
    stencil.begin.resize(n_local + 1);
    // Unconstrained cells need n_vertices entries per particle; cells with
    // hanging nodes a few more, so grow on demand.
    const auto ensure = [&](const std::size_t size) {
      if (size > stencil.node.size())
        {
          const std::size_t capacity =
            std::max(size, n_local * n_vertices) * 5 / 4;
          stencil.node.resize(capacity);
          stencil.N.resize(capacity);
          stencil.grad_N.resize(capacity);
        }
    };
    ensure(n_local * n_vertices);

    std::size_t       e = 0;
    double            N[n_vertices];
    Tensor<1, dim>    grad_xi[n_vertices];
    const std::size_t n_visited = for_each_particle_in_stencil_order(
      grid,
      particles.handler,
      [&](const std::size_t k, const auto &p, const GridCell<dim> &c)
        DEAL_II_ALWAYS_INLINE {
          const unsigned int *nodes = &grid.cell_nodes[c.first_node];
          const Point<dim>    xi    = p.get_reference_location();
          q1_values<dim>(xi, N, grad_xi);
          const Tensor<2, dim> K =
            c.affine ? c.inverse_jacobian : c.inverse_jacobian_at(xi);
          stencil.begin[k] = e;
          ensure(e + c.n_nodes);
          if (c.first_weight == numbers::invalid_unsigned_int)
            for (unsigned int v = 0; v < n_vertices; ++v, ++e)
              {
                stencil.node[e]   = nodes[v];
                stencil.N[e]      = N[v];
                stencil.grad_N[e] = grad_xi[v] * K; // K^T grad_xi
              }
          else
            {
              const double *W = &grid.cell_node_weights[c.first_weight];
              for (unsigned int n = 0; n < c.n_nodes; ++n, ++e)
                {
                  double         value = 0;
                  Tensor<1, dim> grad;
                  for (unsigned int v = 0; v < n_vertices; ++v)
                    {
                      value += W[n * n_vertices + v] * N[v];
                      grad += W[n * n_vertices + v] * grad_xi[v];
                    }
                  stencil.node[e]   = nodes[n];
                  stencil.N[e]      = value;
                  stencil.grad_N[e] = grad * K;
                }
            }
        });
    stencil.begin[n_visited] = e;
    AssertThrow(n_visited == n_local, ExcInternalError());
  }

  template <int dim>
  void
  record_positions(const BackgroundGrid<dim> &grid,
                   const ParticleSet<dim>    &particles,
                   Stencil<dim>              &stencil)
  {
    stencil.position.resize(particles.handler.n_locally_owned_particles());
    const auto record =
      [&](const std::size_t k, const auto &p, const GridCell<dim> &)
        DEAL_II_ALWAYS_INLINE { stencil.position[k] = p.get_location(); };
    for_each_particle_in_stencil_order(grid, particles.handler, record);
  }

#define DEALMPM_INSTANTIATE(dim)                                    \
  template void record_positions(const BackgroundGrid<dim> &,       \
                                 const ParticleSet<dim> &,          \
                                 Stencil<dim> &);                   \
  template void compute_linear_stencil(const BackgroundGrid<dim> &, \
                                       const ParticleSet<dim> &,    \
                                       Stencil<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
