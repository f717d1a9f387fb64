#include <dealmpm/transfer/gimp_windows.h>
#include <dealmpm/transfer/lattice_blocks.h>
#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <limits>

#include "lattice_products.h"
#include "node_accumulator.h"

namespace dealmpm
{
  namespace
  {
    /** Integrals over [a, b] of the 1D hats of a cell [x0, x1]: the one
     * that is 1 at x0 (lower) and the one that is 1 at x1 (upper). */
    DEAL_II_ALWAYS_INLINE inline void
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
      const Point<dim>      &x0         = c.origin;
      const Point<dim>      &x1         = c.far_corner;
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

    /** The 1D weights of [x - l, x + l] on the lattice of the cell
     * [x0, x1]; false when the domain reaches past the three cells. */
    DEAL_II_ALWAYS_INLINE inline bool
    lattice_weights_1d(const double      x,
                       const double      l,
                       const double      x0,
                       const double      x1,
                       LatticeWeights1D &w)
    {
      const double h         = x1 - x0;
      const double bounds[4] = {x0 - h, x0, x1, x1 + h};
      if (x - l < bounds[0] || x + l > bounds[3])
        return false;
      double length = 0;
      w.count       = 0;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const double a = std::max(x - l, bounds[k]);
          const double b = std::min(x + l, bounds[k + 1]);
          if (!(b > a))
            continue;
          if (w.count == 0)
            {
              w.first    = k;
              w.count    = 1;
              w.value[k] = 0;
              w.slope[k] = 0;
            }
          double lower, upper;
          hat_integrals(a, b, bounds[k], bounds[k + 1], lower, upper);
          w.value[k] += lower;
          w.slope[k] -= (b - a) / h;
          w.value[k + 1] = upper;
          w.slope[k + 1] = (b - a) / h;
          length += b - a;
          ++w.count;
        }
      for (unsigned int n = w.first; n < w.first + w.count; ++n)
        {
          w.value[n] /= length;
          w.slope[n] /= length;
        }
      return true;
    }

    /** Particle k's entries on the lattice @p block of its cell @p c, or
     * false (nothing appended) when its domain reaches past the cells of its
     * patch. The same numbers as the general path to round-off: that one sums
     * per-cell products of the 1D integrals, this one their 1D sums. */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline bool
    append_on_lattice(const unsigned int   *block,
                      const std::uint32_t   present,
                      const GridCell<dim>  &c,
                      const Point<dim>     &x,
                      const Tensor<1, dim> &l,
                      const std::size_t     k,
                      std::size_t          &e,
                      Stencil<dim>         &stencil)
    {
      LatticeWeights1D w[dim];
      for (unsigned int d = 0; d < dim; ++d)
        if (!lattice_weights_1d(x[d], l[d], c.origin[d], c.far_corner[d], w[d]))
          return false;
      if (!spans_present_cells<dim>(w, present))
        return false;
      append_products(block, w, k, e, stencil);
      return true;
    }
  } // namespace

  template <int dim>
  void
  compute_gimp_stencil(const BackgroundGrid<dim> &grid,
                       const ParticleSet<dim>    &particles,
                       const bool                 follow_deformation,
                       Stencil<dim>              &stencil,
                       const LatticeBlocks<dim>  *lattice)
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
          const unsigned int  i     = index_in_grid(grid, own);
          const unsigned int *block = lattice ? lattice->of(i) : nullptr;
          if (block != nullptr &&
              append_on_lattice(
                block, lattice->cells_present(i), own, x, l, k, e, stencil))
            return;
          gathered.clear();
          double covered = 0;
          for (const unsigned int k : grid.neighbors_of(i))
            {
              const GridCell<dim> &c = grid.local_cell(k);
              double               volume;
              if (!overlap_integrals(c, x, l, S, G, volume))
                continue;
              covered += volume;
              gathered.add_cell(grid, c, S, G);
            }
          // Normalise by the covered volume: the partition of unity holds
          // even where a domain reaches past the grid.
          gathered.append_to(stencil, k, e, 1. / covered);
        });
    stencil.begin[n_visited] = e;
    AssertThrow(n_visited == n_local, ExcInternalError());
  }

  namespace
  {
    // Half a cell, as the bodies make it for one particle a cell, may come
    // out a few ulps above: the window then misses a few ulps of weight.
    constexpr double most_in_cells = 0.5 * (1. + 1e-12);
  } // namespace

  template <int dim>
  bool
  domains_fit_windows(const BackgroundGrid<dim> &grid,
                      const ParticleSet<dim>    &particles,
                      const bool                 follows_deformation)
  {
    const GimpWindows<dim> windows{nullptr,
                                   particles.fields.domain_half_length,
                                   follows_deformation};
    AssertThrow(windows.half_length != numbers::invalid_unsigned_int,
                ExcInternalError());
    bool fit = true;
    for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t, const auto &p, const GridCell<dim> &own) {
        const auto props = p.get_properties();
        for (unsigned int d = 0; d < dim; ++d)
          fit = fit &&
                windows.half_length_of(props, d) * own.inverse_jacobian[d][d] <=
                  most_in_cells;
      });
    return Utilities::MPI::min(fit ? 1 : 0, grid.comm) == 1;
  }

  template <int dim>
  Tensor<1, dim>
  gimp_stretch_limit(const BackgroundGrid<dim> &grid)
  {
    Tensor<1, dim> limit;
    for (unsigned int d = 0; d < dim; ++d)
      {
        double shortest = std::numeric_limits<double>::max();
        for (const GridCell<dim> &c : grid.cells)
          shortest = std::min(shortest, 1. / c.inverse_jacobian[d][d]);
        limit[d] = most_in_cells * Utilities::MPI::min(shortest, grid.comm);
      }
    return limit;
  }

#define DEALMPM_INSTANTIATE(dim)                                            \
  template void           compute_gimp_stencil(const BackgroundGrid<dim> &, \
                                               const ParticleSet<dim> &,    \
                                               bool,                        \
                                               Stencil<dim> &,              \
                                               const LatticeBlocks<dim> *); \
  template bool           domains_fit_windows(const BackgroundGrid<dim> &,  \
                                              const ParticleSet<dim> &,     \
                                              bool);                        \
  template Tensor<1, dim> gimp_stretch_limit(const BackgroundGrid<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
