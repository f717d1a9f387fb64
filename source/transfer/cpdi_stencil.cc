#include <dealmpm/transfer/stencil.h>

#include <algorithm>
#include <limits>

#include "node_accumulator.h"

namespace dealmpm
{
  namespace
  {
    /** How far unit-cell point xi lies outside [0,1]^dim (0 inside). */
    template <int dim>
    double
    distance_outside(const Point<dim> &xi)
    {
      double outside = 0;
      for (unsigned int d = 0; d < dim; ++d)
        outside = std::max({outside, -xi[d], xi[d] - 1.});
      return outside;
    }

    /**
     * The cell among the particle's cell and its neighbours that holds x
     * (the particle's own cell first: most corners are there), or, when
     * none does, the one x is least outside of. Returns x's unit-cell
     * coordinates there and how far outside they are.
     */
    template <int dim>
    const GridCell<dim> *
    locate(const GridCell<dim>                      &own,
           const std::vector<const GridCell<dim> *> &neighbors,
           const Point<dim>                         &x,
           Point<dim>                               &xi,
           double                                   &outside)
    {
      constexpr double tolerance = 1e-12;
      xi                         = own.reference_point(x);
      outside                    = distance_outside(xi);
      if (outside <= tolerance)
        return &own;
      const GridCell<dim> *best = &own;
      for (const GridCell<dim> *c : neighbors)
        {
          if (c == &own)
            continue;
          const Point<dim> candidate = c->reference_point(x);
          const double     d         = distance_outside(candidate);
          if (d < outside)
            {
              best    = c;
              xi      = candidate;
              outside = d;
              if (d <= tolerance)
                break;
            }
        }
      return best;
    }
  } // namespace

  template <int dim>
  void
  compute_cpdi_stencil(const BackgroundGrid<dim> &grid,
                       const ParticleSet<dim>    &particles,
                       Stencil<dim>              &stencil)
  {
    constexpr unsigned int n_corners = GridCell<dim>::n_vertices;
    // A corner further than this (in unit-cell lengths) from every cell next
    // to the particle's: the domain has outgrown its neighbourhood.
    constexpr double  max_extrapolation = 0.5;
    const CoreFields &f                 = particles.fields;
    const std::size_t n_local = particles.handler.n_locally_owned_particles();
    stencil.begin.resize(n_local + 1);
    stencil.failed = false;
    std::size_t k = 0, e = 0;

    NodeAccumulator<dim> gathered;
    double               N[n_corners];
    Tensor<1, dim>       G[n_corners];
    for (unsigned int i = 0; i < grid.cells.size(); ++i)
      for (const auto &p :
           particles.handler.particles_in_cell(grid.cells[i].cell))
        {
          const auto       props = p.get_properties();
          const Point<dim> x     = p.get_location();
          // R's columns are the domain's half-edge vectors r_d = F e_d l_d.
          const Tensor<2, dim> F =
            read_tensor<dim>(&props[f.deformation_gradient]);
          Tensor<2, dim> R;
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int d = 0; d < dim; ++d)
              R[a][d] = F[a][d] * props[f.domain_half_length + d];
          const double         det = determinant(R);
          const Tensor<2, dim> R_inverse_transpose =
            det > 0 ? transpose(invert(R)) : Tensor<2, dim>();

          gathered.clear();
          for (unsigned int corner = 0; corner < n_corners; ++corner)
            {
              Tensor<1, dim> sign;
              for (unsigned int d = 0; d < dim; ++d)
                sign[d] = ((corner >> d) & 1u) ? 1. : -1.;
              const Point<dim>     x_c = x + R * sign;
              Point<dim>           xi;
              double               outside;
              const GridCell<dim> *c =
                locate(grid.cells[i], grid.neighbors[i], x_c, xi, outside);
              if (!(outside <= max_extrapolation) && !stencil.failed)
                {
                  stencil.failed          = true;
                  stencil.failed_particle = p.get_id();
                  stencil.failed_location = x;
                  stencil.failure =
                    "its CPDI domain reaches past the cells next to its own "
                    "(stretched to more than a cell, or far past the grid's "
                    "boundary); use more particles per cell or cpGIMP";
                }
              // N_i(x_c) / 2^dim, and N_i(x_c) R^{-T} s_c / 2^dim.
              q1_values<dim>(xi, N, nullptr);
              const Tensor<1, dim> g =
                R_inverse_transpose * sign / double(n_corners);
              for (unsigned int v = 0; v < n_corners; ++v)
                {
                  G[v] = N[v] * g;
                  N[v] /= n_corners;
                }
              gathered.add_cell(grid, *c, N, G);
            }
          gathered.append_to(stencil, k, e);
          ++k;
        }
    stencil.begin[k] = e;
    AssertThrow(k == n_local, ExcInternalError());
  }

  template void
  compute_cpdi_stencil(const BackgroundGrid<2> &,
                       const ParticleSet<2> &,
                       Stencil<2> &);
  template void
  compute_cpdi_stencil(const BackgroundGrid<3> &,
                       const ParticleSet<3> &,
                       Stencil<3> &);
} // namespace dealmpm
