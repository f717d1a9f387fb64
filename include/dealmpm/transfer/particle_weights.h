#pragma once

#include <deal.II/base/config.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/transfer/gimp_windows.h>
#include <dealmpm/transfer/quadratic_bspline.h>
#include <dealmpm/transfer/stencil.h>

#include <cstddef>
#include <limits>
#include <type_traits>

namespace dealmpm
{
  /** Q1 values and reference-coordinate gradients at unit-cell point xi
   * (@p grad_xi may be nullptr): N_v = prod_d f_d, with f_d = xi_d on the
   * vertex's upper side of direction d and 1 - xi_d on its lower side, and
   * d N_v / d xi_d = +-prod_(b != d) f_b, the products taken in increasing
   * d. Written out per dimension: the loop over directions did not unroll,
   * and P2G's box cells (for N), cells that are not boxes and CPDI's
   * corners call this once per particle. */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline void
  q1_values(const Point<dim> &xi, double *N, Tensor<1, dim> *grad_xi)
  {
    static_assert(dim == 2 || dim == 3, "Q1 values in 2D and 3D");
    double f[dim][2];
    for (unsigned int d = 0; d < dim; ++d)
      {
        f[d][0] = 1. - xi[d];
        f[d][1] = xi[d];
      }
    for (unsigned int v = 0; v < GridCell<dim>::n_vertices; ++v)
      {
        const unsigned int a = v & 1u, b = (v >> 1) & 1u;
        if constexpr (dim == 2)
          {
            N[v] = f[0][a] * f[1][b];
            if (grad_xi != nullptr)
              {
                grad_xi[v][0] = a ? f[1][b] : -f[1][b];
                grad_xi[v][1] = b ? f[0][a] : -f[0][a];
              }
          }
        else
          {
            const unsigned int c = (v >> 2) & 1u;
            N[v]                 = f[0][a] * f[1][b] * f[2][c];
            if (grad_xi != nullptr)
              {
                const double p12 = f[1][b] * f[2][c];
                const double p02 = f[0][a] * f[2][c];
                const double p01 = f[0][a] * f[1][b];
                grad_xi[v][0]    = a ? p12 : -p12;
                grad_xi[v][1]    = b ? p02 : -p02;
                grad_xi[v][2]    = c ? p01 : -p01;
              }
          }
      }
  }

  /** K^T g (g * K): a gradient in unit-cell coordinates @p g to real
   * ones, K = d xi / d x; summed in deal.II's order for Tensor * Tensor. */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline Tensor<1, dim>
  to_real_gradient(const Tensor<1, dim> &g, const Tensor<2, dim> &K)
  {
    Tensor<1, dim> r;
    for (unsigned int j = 0; j < dim; ++j)
      {
        double sum = g[0] * K[0][j];
        for (unsigned int i = 1; i < dim; ++i)
          sum += g[i] * K[i][j];
        r[j] = sum;
      }
    return r;
  }

  /**
   * Where a P2G or G2P sweep finds a particle's weights: @p weights(k, p,
   * cell, f) calls f(node, N, grad N) for each node of particle k (its
   * place in the stencil order, for_each_particle_in_stencil_order()).
   * This one reads them from the stored stencil.
   */
  template <int dim>
  struct StoredWeights
  {
    const Stencil<dim> &stencil;

    template <typename Particle, typename Function>
    DEAL_II_ALWAYS_INLINE void
    operator()(const std::size_t k,
               const Particle &,
               const GridCell<dim> &,
               Function &&f) const
    {
      for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
        f(stencil.node[e], stencil.N[e], stencil.grad_N[e]);
    }
  };

  /**
   * Linear (Q1) weights computed where they are used, from the particle's
   * reference location in its listed cell, with hanging nodes resolved
   * into their masters. Computing them twice a step costs fewer
   * instructions and far less memory traffic than storing them once and
   * reading them back (Stencil::where_used); compute_linear_stencil()
   * stores the same numbers, computed here.
   */
  template <int dim>
  struct LinearWeights
  {
    const BackgroundGrid<dim> &grid;

    /** f(vertex, N, grad N) at unit-cell point @p xi of @p c, an
     * axis-aligned box without hanging nodes (is_box()): the gradient is
     * the unit cell's scaled by the diagonal of d xi / d x. The same
     * numbers as q1_values() followed by that scaling ((-a) K = -(a K)
     * exactly), but each product shared by the vertices that use it is
     * taken once: d N / d x_0 depends only on the vertex's sides in the
     * other directions (4 products in 2D instead of 8, 24 in 3D instead
     * of 48). */
    template <typename Function>
    static DEAL_II_ALWAYS_INLINE void
    at_in_box(const Point<dim> &xi, const GridCell<dim> &c, Function &&f)
    {
      static_assert(dim == 2 || dim == 3, "Q1 values in 2D and 3D");
      double side[dim][2]; // 1 - xi_d on a vertex's lower side, xi_d upper
      for (unsigned int d = 0; d < dim; ++d)
        {
          side[d][0] = 1. - xi[d];
          side[d][1] = xi[d];
        }
      // Filled first, in a loop the compiler unrolls, then handed out: a
      // loop that also calls f (a sweep's whole body) is not unrolled.
      constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
      double                 N[n_vertices];
      Tensor<1, dim>         grad[n_vertices];
      if constexpr (dim == 2)
        {
          double g0[2], g1[2]; // |d N / d x_0| by b, |d N / d x_1| by a
          for (unsigned int s = 0; s < 2; ++s)
            {
              g0[s] = side[1][s] * c.inverse_jacobian[0][0];
              g1[s] = side[0][s] * c.inverse_jacobian[1][1];
            }
          for (unsigned int b = 0; b < 2; ++b)
            for (unsigned int a = 0; a < 2; ++a)
              {
                const unsigned int v = a + 2 * b;
                N[v]                 = side[0][a] * side[1][b];
                grad[v][0]           = a ? g0[b] : -g0[b];
                grad[v][1]           = b ? g1[a] : -g1[a];
              }
        }
      else
        {
          double g0[2][2], g1[2][2], g2[2][2], p01[2][2];
          for (unsigned int s = 0; s < 2; ++s)
            for (unsigned int t = 0; t < 2; ++t)
              {
                g0[s][t]  = side[1][s] * side[2][t] * c.inverse_jacobian[0][0];
                g1[s][t]  = side[0][s] * side[2][t] * c.inverse_jacobian[1][1];
                p01[s][t] = side[0][s] * side[1][t];
                g2[s][t]  = p01[s][t] * c.inverse_jacobian[2][2];
              }
          for (unsigned int e = 0; e < 2; ++e)
            for (unsigned int b = 0; b < 2; ++b)
              for (unsigned int a = 0; a < 2; ++a)
                {
                  const unsigned int v = a + 2 * b + 4 * e;
                  N[v]                 = p01[a][b] * side[2][e];
                  grad[v][0]           = a ? g0[b][e] : -g0[b][e];
                  grad[v][1]           = b ? g1[a][e] : -g1[a][e];
                  grad[v][2]           = e ? g2[a][b] : -g2[a][b];
                }
        }
      for (unsigned int v = 0; v < n_vertices; ++v)
        f(v, N[v], grad[v]);
    }

    /** f(node, N, grad N) at unit-cell point @p xi of cell @p c. */
    template <typename Function>
    DEAL_II_ALWAYS_INLINE void
    at(const Point<dim> &xi, const GridCell<dim> &c, Function &&f) const
    {
      constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
      const unsigned int    *nodes      = &grid.cell_nodes[c.first_node];
      if (c.first_weight == numbers::invalid_unsigned_int &&
          is_box(c)) // most cells: d xi / d x is diagonal
        {
          at_in_box(xi,
                    c,
                    [&](const unsigned int    v,
                        const double          N,
                        const Tensor<1, dim> &grad)
                      DEAL_II_ALWAYS_INLINE { f(nodes[v], N, grad); });
          return;
        }
      double         N[n_vertices];
      Tensor<1, dim> grad_xi[n_vertices];
      q1_values<dim>(xi, N, grad_xi);
      if (c.first_weight == numbers::invalid_unsigned_int)
        {
          const Tensor<2, dim> K =
            c.affine ? c.inverse_jacobian : c.inverse_jacobian_at(xi);
          for (unsigned int v = 0; v < n_vertices; ++v)
            f(nodes[v], N[v], to_real_gradient(grad_xi[v], K));
        }
      else
        {
          const Tensor<2, dim> K =
            c.affine ? c.inverse_jacobian : c.inverse_jacobian_at(xi);
          const double *W = &grid.cell_node_weights[c.first_weight];
          for (unsigned int n = 0; n < c.n_nodes; ++n)
            {
              double         value = 0;
              Tensor<1, dim> grad;
              for (unsigned int v = 0; v < n_vertices; ++v)
                {
                  value += W[n * n_vertices + v] * N[v];
                  grad += W[n * n_vertices + v] * grad_xi[v];
                }
              f(nodes[n], value, to_real_gradient(grad, K));
            }
        }
    }

    /** Whether @p c is an axis-aligned box: then K^T g is g_d K_dd,
     * the same numbers as to_real_gradient() but for the sign of a zero. */
    static DEAL_II_ALWAYS_INLINE bool
    is_box(const GridCell<dim> &c)
    {
      if (!c.affine)
        return false;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          if (i != j && c.inverse_jacobian[i][j] != 0.)
            return false;
      return true;
    }

    template <typename Particle, typename Function>
    DEAL_II_ALWAYS_INLINE void
    operator()(const std::size_t,
               const Particle      &p,
               const GridCell<dim> &c,
               Function           &&f) const
    {
      at(p.get_reference_location(), c, f);
    }
  };

  /**
   * Weights computed where they are used, as LinearWeights are
   * (Stencil::where_used), on fixed windows of three nodes a direction
   * (NodeWindow): the quadratic B-spline's (@p spline, if not nullptr) or
   * GIMP's (@p gimp). A node costs a few products instead of reading back the
   * 36 (2D: 28) bytes of a stored entry, and the stencil's 972 (2D: 252) bytes
   * a particle are not kept.
   */
  template <int dim>
  struct WindowWeights
  {
    const BackgroundGrid<dim>       &grid;
    const QuadraticBSplineGrid<dim> *spline = nullptr;
    GimpWindows<dim>                 gimp;
    /** Whether rows() keeps the windows it computes: MUSL's G2P sweep
     * reads them again for its re-map (g2p_sweep::visit() sets it). */
    mutable bool keep_windows = false;
    /** rows()'s own, with keep_windows: the windows of the particle it saw
     * last (a sweep's index k; none yet) and its cell's lattice block. */
    mutable std::size_t last_particle = std::numeric_limits<std::size_t>::max();
    mutable NodeWindow  last_windows[dim]  = {};
    mutable const unsigned int *last_block = nullptr;

    /** The windows @p stencil stands for (Stencil::on_windows()). */
    static WindowWeights
    of(const BackgroundGrid<dim> &grid, const Stencil<dim> &stencil)
    {
      return WindowWeights{grid,
                           stencil.spline,
                           {stencil.gimp_lattice,
                            stencil.gimp_half_length,
                            stencil.gimp_follows_deformation}};
    }

    /** f(n_x, row, w0, v12, s12, s2) for each row of particle @p p's nodes
     * along x (3 or 2 a direction: NodeWindow::rows): row[k] is node k of
     * the row (k < n_x, a std::integral_constant: 2 where a GIMP domain
     * stays in its cell along x, else 3), with weight
     * w0.value[k] v12 and gradient (w0.slope[k] v12, w0.value[k] s12,
     * w0.value[k] s2); v12 is the product of the other directions'
     * values, s12 that of y's slope and z's value, s2 (3D) that of y's
     * value and z's slope. A sweep sums a row with w0 first and scales the
     * sums once (P2G, G2P): its accumulators stay in registers. With
     * keep_windows, the windows of particle @p k are kept for the next
     * call with the same @p k. */
    template <typename Particle, typename Function>
    DEAL_II_ALWAYS_INLINE void
    rows(const std::size_t    k,
         const Particle      &p,
         const GridCell<dim> &c,
         Function           &&f) const
    {
      // Local windows: the sweeps' stores to nodal arrays cannot alias
      // them, so they stay in registers (read from the members, a row
      // reloaded them after each store).
      NodeWindow          w[dim];
      const unsigned int *block;
      if (keep_windows) // one test in the sweeps that do not keep them
        {
          if (k != last_particle)
            {
              last_block    = windows_at(p, c, last_windows);
              last_particle = k;
            }
          for (unsigned int d = 0; d < dim; ++d)
            w[d] = last_windows[d];
          block = last_block;
        }
      else
        block = windows_at(p, c, w);
      // Rows one after the other: unrolled, the 3D G2P's loads of all
      // 27 nodes were hoisted ahead and spilled to the stack.
      const auto each_row = [&](const auto n_x) DEAL_II_ALWAYS_INLINE {
        const unsigned int n2 = dim == 3 ? w[dim - 1].rows : 1;
#pragma GCC unroll 1
        for (unsigned int i2 = 0; i2 < n2; ++i2)
#pragma GCC unroll 1
          for (unsigned int i1 = 0; i1 < w[1].rows; ++i1)
            {
              double       v12 = w[1].value[i1], s12 = w[1].slope[i1];
              double       s2  = 0;
              unsigned int row = 4 * (w[1].first + i1) + w[0].first;
              if constexpr (dim == 3)
                {
                  s12 *= w[2].value[i2];
                  s2 = w[1].value[i1] * w[2].slope[i2];
                  v12 *= w[2].value[i2];
                  row += 16 * (w[2].first + i2);
                }
              f(n_x, block + row, w[0], v12, s12, s2);
            }
      };
      // A row's length fixed at compile time: its loops unroll and keep
      // their sums in registers.
      if (w[0].rows == 2)
        each_row(std::integral_constant<unsigned int, 2>());
      else
        each_row(std::integral_constant<unsigned int, 3>());
    }

    /** Particle @p p's windows @p w in cell @p c; returns the cell's
     * lattice block. */
    template <typename Particle>
    DEAL_II_ALWAYS_INLINE const unsigned int *
    windows_at(const Particle &p, const GridCell<dim> &c, NodeWindow *w) const
    {
      const unsigned int i = index_in_grid(grid, c);
      if (spline == nullptr)
        return gimp.windows_at(i, p, c, w);
      spline->windows_at(i, p.get_reference_location(), w);
      return &spline->block_nodes[i * QuadraticBSplineGrid<dim>::block_size];
    }

    /** f(node, N, grad N) for each of particle @p p's nodes (3^dim, or
     * fewer where NodeWindow::rows says). */
    template <typename Particle, typename Function>
    DEAL_II_ALWAYS_INLINE void
    operator()(const std::size_t    k,
               const Particle      &p,
               const GridCell<dim> &c,
               Function           &&f) const
    {
      rows(k,
           p,
           c,
           [&](const auto          n_x,
               const unsigned int *row,
               const NodeWindow   &w0,
               const double        v12,
               const double        s12,
               const double        s2) DEAL_II_ALWAYS_INLINE {
             for (unsigned int k = 0; k < n_x; ++k)
               {
                 Tensor<1, dim> grad_N;
                 grad_N[0] = w0.slope[k] * v12;
                 grad_N[1] = w0.value[k] * s12;
                 if constexpr (dim == 3)
                   grad_N[dim - 1] = w0.value[k] * s2;
                 f(row[k], w0.value[k] * v12, grad_N);
               }
           });
    }
  };

  /** Whether @p Weights are computed where used (Stencil::where_used),
   * from the particle's reference location in its listed cell. */
  template <int dim, typename Weights>
  constexpr bool computed_where_used =
    std::is_same_v<Weights, LinearWeights<dim>> ||
    std::is_same_v<Weights, WindowWeights<dim>>;

  /** Run @p sweep(weights) with the weights @p stencil stands for: stored,
   * or linear or windowed ones computed where used. */
  template <int dim, typename Sweep>
  DEAL_II_ALWAYS_INLINE inline auto
  with_weights(const BackgroundGrid<dim> &grid,
               const Stencil<dim>        &stencil,
               const Sweep               &sweep)
  {
    if (stencil.on_windows())
      return sweep(WindowWeights<dim>::of(grid, stencil));
    if (stencil.where_used)
      return sweep(LinearWeights<dim>{grid});
    return sweep(StoredWeights<dim>{stencil});
  }
} // namespace dealmpm
