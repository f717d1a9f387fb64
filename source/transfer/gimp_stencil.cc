#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>

#include "node_accumulator.h"

namespace dealmpm
{
  namespace
  {
    /** Integrals over [a, b] of the 1D hats of a cell [x0, x1]: the one
     * that is 1 at x0 (lower) and the one that is 1 at x1 (upper). */
    inline void
    hat_integrals(const double a,
                  const double b,
                  const double x0,
                  const double x1,
                  double      &lower,
                  double      &upper)
    {
      const double h = x1 - x0;
      upper          = ((b - x0) * (b - x0) - (a - x0) * (a - x0)) / (2. * h);
      lower          = ((x1 - a) * (x1 - a) - (x1 - b) * (x1 - b)) / (2. * h);
    }

    /**
     * Integrals of the Q1 functions N_v of box cell @p c (S[v]) and of their
     * gradients (G[v]) over the cell's overlap with the particle domain of
     * centre @p x and half-lengths @p l, and the overlap's @p volume; false
     * (S, G and volume unset) when they do not overlap.
     */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline bool
    overlap_integrals(const GridCell<dim>  &c,
                      const Point<dim>     &x,
                      const Tensor<1, dim> &l,
                      double               *S,
                      Tensor<1, dim>       *G,
                      double               &volume)
    {
      constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
      const Point<dim>      &x0         = c.vertices[0];
      const Point<dim>      &x1         = c.vertices[n_vertices - 1];
      double                 lower[dim], upper[dim], length[dim];
      volume = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double a = std::max(x[d] - l[d], x0[d]);
          const double b = std::min(x[d] + l[d], x1[d]);
          if (!(b > a))
            return false;
          hat_integrals(a, b, x0[d], x1[d], lower[d], upper[d]);
          length[d] = b - a;
          volume *= length[d];
        }
      // A product of 1D integrals per direction: N_v is a product of hats.
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          S[v] = 1;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const bool up = (v >> d) & 1u;
              S[v] *= up ? upper[d] : lower[d];
              double g = (up ? 1. : -1.) / (x1[d] - x0[d]) * length[d];
              for (unsigned int b = 0; b < dim; ++b)
                if (b != d)
                  g *= ((v >> b) & 1u) ? upper[b] : lower[b];
              G[v][d] = g;
            }
        }
      return true;
    }
  } // namespace

  template <int dim>
  void
  compute_gimp_stencil(const BackgroundGrid<dim> &grid,
                       const ParticleSet<dim>    &particles,
                       const bool                 follow_deformation,
                       Stencil<dim>              &stencil)
  {
    constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
    const CoreFields      &f          = particles.fields;
    const std::size_t n_local = particles.handler.n_locally_owned_particles();
    stencil.begin.resize(n_local + 1);
    std::size_t e = 0;

    NodeAccumulator<dim> gathered;
    double               S[n_vertices];
    Tensor<1, dim>       G[n_vertices];
    const std::size_t    n_visited = for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t k, const auto &p, const GridCell<dim> &own)
        DEAL_II_ALWAYS_INLINE {
          const auto       props = p.get_properties();
          const Point<dim> x     = p.get_location();
          Tensor<1, dim>   l;
          for (unsigned int d = 0; d < dim; ++d)
            {
              l[d] = props[f.domain_half_length + d];
              if (follow_deformation)
                l[d] *=
                  std::max(props[f.deformation_gradient + d * dim + d], 1e-3);
            }
          gathered.clear();
          double covered = 0;
          for (const GridCell<dim> *c :
               grid.neighbors[index_in_grid(grid, own)])
            {
              double volume;
              if (!overlap_integrals(*c, x, l, S, G, volume))
                continue;
              covered += volume;
              gathered.add_cell(grid, *c, S, G);
            }
          // Normalise by the covered volume: the partition of unity holds
          // even where a domain reaches past the grid.
          gathered.append_to(stencil, k, e, 1. / covered);
        });
    stencil.begin[n_visited] = e;
    AssertThrow(n_visited == n_local, ExcInternalError());
  }

#define DEALMPM_INSTANTIATE(dim)                                  \
  template void compute_gimp_stencil(const BackgroundGrid<dim> &, \
                                     const ParticleSet<dim> &,    \
                                     bool,                        \
                                     Stencil<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
