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

    std::size_t              e = 0;
    const LinearWeights<dim> weights{grid};
    const std::size_t        n_visited = for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t k, const auto &p, const GridCell<dim> &c)
        DEAL_II_ALWAYS_INLINE {
          stencil.begin[k] = e;
          ensure(e + c.n_nodes);
          weights(k,
                  p,
                  c,
                  [&](const unsigned int    node,
                      const double          N,
                      const Tensor<1, dim> &grad_N) DEAL_II_ALWAYS_INLINE {
                    stencil.node[e]   = node;
                    stencil.N[e]      = N;
                    stencil.grad_N[e] = grad_N;
                    ++e;
                  });
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
    for_each_particle_in_stencil_order(grid, particles, record);
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
