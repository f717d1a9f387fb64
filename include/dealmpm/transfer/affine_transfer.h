#pragma once

#include <deal.II/base/config.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/grid/background_grid.h>

#include <cmath>

namespace dealmpm
{
  /**
   * APIC's affine transfer (Jiang et al. 2015). G2P keeps
   * B = sum_i N_i v_i (x) (x_i - x_p); P2G brings each node the momentum
   * m N_i (v + C (x_i - x_p)) with C = B D^-1 and
   * D = sum_i N_i (x_i - x_p) (x) (x_i - x_p). With this D the round trip
   * conserves angular momentum for any shape functions.
   *
   * For multilinear weights in an axis-aligned box cell of edges h_b both
   * sums have a closed form at unit-cell point xi, because
   * sum_i N_i (xi_i,b - xi_b) = 0 and sum_i N_i (xi_i,b - xi_b)^2 =
   * xi_b (1 - xi_b):
   * - D is diagonal, D_bb = h_b^2 xi_b (1 - xi_b);
   * - B = L_v D, L_v the gradient of the interpolated velocity
   *   (sum_i N_i v_i (xi_i,b - xi_b) = xi_b (1 - xi_b) dv/dxi_b).
   * The sweeps then need no node positions and no second pass over the
   * weights (doc/lean-step.md, "APIC where used").
   */

  /** Whether D (determinant @p det, trace @p trace) is far enough from
   * singular to invert: a particle on a node line has a D of rank less
   * than dim, and C = 0 there. */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline bool
  affine_inertia_is_regular(const double det, const double trace)
  {
    return std::abs(det) > 1e-12 * Utilities::fixed_power<dim>(trace);
  }

  /** C = @p B D^-1, D summed over @p weights (any cell, any kernel) about
   * @p x_p; zero where D is singular. */
  template <int dim, typename Weights, typename Particle>
  DEAL_II_ALWAYS_INLINE inline Tensor<2, dim>
  affine_velocity_gradient(const BackgroundGrid<dim> &grid,
                           const Weights             &weights,
                           const std::size_t          k,
                           const Particle            &p,
                           const GridCell<dim>       &c,
                           const Point<dim>          &x_p,
                           const Tensor<2, dim>      &B)
  {
    Tensor<2, dim> D;
    weights(k,
            p,
            c,
            [&](const unsigned int n, const double N, const Tensor<1, dim> &)
              DEAL_II_ALWAYS_INLINE {
                const Tensor<1, dim> r = grid.node_positions[n] - x_p;
                D += N * outer_product(r, r);
              });
    if (affine_inertia_is_regular<dim>(determinant(D), trace(D)))
      return B * invert(D);
    return Tensor<2, dim>();
  }

  /** The point sum_i N_i x_i of @p weights: the particle's position for
   * weights that reproduce linear fields (linear ones computed from the
   * reference location: also after the particle moved, in MUSL's
   * re-map). */
  template <int dim, typename Weights, typename Particle>
  DEAL_II_ALWAYS_INLINE inline Point<dim>
  weights_centroid(const BackgroundGrid<dim> &grid,
                   const Weights             &weights,
                   const std::size_t          k,
                   const Particle            &p,
                   const GridCell<dim>       &c)
  {
    Point<dim> x;
    weights(k,
            p,
            c,
            [&](const unsigned int n, const double N, const Tensor<1, dim> &)
              DEAL_II_ALWAYS_INLINE { x += N * grid.node_positions[n]; });
    return x;
  }

  /** In a box cell (d xi / d x = @p K, diagonal) at @p xi: D's diagonal
   * xi_b (1 - xi_b) / K_bb^2. */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline Tensor<1, dim>
  box_inertia(const Point<dim> &xi, const Tensor<2, dim> &K)
  {
    Tensor<1, dim> D;
    for (unsigned int b = 0; b < dim; ++b)
      D[b] = xi[b] * (1. - xi[b]) / (K[b][b] * K[b][b]);
    return D;
  }

  /** B = L_v D in a box cell at @p xi, from the velocity gradient @p L_v
   * (real coordinates). */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline Tensor<2, dim>
  box_affine_moment(const Tensor<2, dim> &L_v,
                    const Point<dim>     &xi,
                    const Tensor<2, dim> &K)
  {
    const Tensor<1, dim> D = box_inertia(xi, K);
    Tensor<2, dim>       B;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        B[a][b] = L_v[a][b] * D[b];
    return B;
  }

  /** C h in a box cell at @p xi: g[a][b] = C[a][b] h_b with C = @p B D^-1,
   * the change of the affine velocity per unit-cell coordinate, so that
   * vertex i gets v + g (xi_i - xi). Zero where D is singular. */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline void
  box_affine_unit_gradient(const Tensor<2, dim> &B,
                           const Point<dim>     &xi,
                           const Tensor<2, dim> &K,
                           double (&g)[dim][dim])
  {
    const Tensor<1, dim> D     = box_inertia(xi, K);
    double               det   = D[0];
    double               trace = D[0];
    for (unsigned int b = 1; b < dim; ++b)
      {
        det *= D[b];
        trace += D[b];
      }
    const bool regular = affine_inertia_is_regular<dim>(det, trace);
    for (unsigned int b = 0; b < dim; ++b)
      {
        // C[a][b] h_b = B[a][b] / D_bb / K_bb
        const double scale = regular ? 1. / (D[b] * K[b][b]) : 0.;
        for (unsigned int a = 0; a < dim; ++a)
          g[a][b] = B[a][b] * scale;
      }
  }
} // namespace dealmpm
