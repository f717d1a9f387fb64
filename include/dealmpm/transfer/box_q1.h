#pragma once

#include <deal.II/base/config.h>

#include <dealmpm/grid/background_grid.h>

namespace dealmpm
{
  /**
   * One component of a nodal field in an axis-aligned box cell (vertex v =
   * a + 2 b + 4 e), prepared once per cell for the multilinear (Q1)
   * interpolation at many particles: the value by linear interpolation
   * along x, then y (then z), and the gradient from the same partial sums.
   * The same function as sum_v N_v u_v and sum_v grad N_v u_v of
   * LinearWeights::at_in_box(), in a different order of sums (equal to
   * round-off in the field's magnitude), and without forming the weights:
   * 9 to 30 operations a component where the sums over the vertices cost
   * 16 to 60.
   */
  template <int dim>
  struct BoxQ1Component;

  template <>
  struct BoxQ1Component<2>
  {
    double lower, lower_step; ///< edge y = 0: u_0 and u_1 - u_0
    double upper, upper_step; ///< edge y = 1: u_2 and u_3 - u_2
    /** d u / d x at y = 0 and its change to y = 1 (real coordinates). */
    double dx, dx_step;
    double k1; ///< d xi_1 / d x_1

    DEAL_II_ALWAYS_INLINE void
    set(const double *u, const Tensor<2, 2> &K)
    {
      lower      = u[0];
      lower_step = u[1] - u[0];
      upper      = u[2];
      upper_step = u[3] - u[2];
      dx         = lower_step * K[0][0];
      dx_step    = (upper_step - lower_step) * K[0][0];
      k1         = K[1][1];
    }

    DEAL_II_ALWAYS_INLINE double
    value(const Point<2> &xi) const
    {
      const double a = lower + xi[0] * lower_step;
      const double b = upper + xi[0] * upper_step;
      return a + xi[1] * (b - a);
    }

    /** The value; its real gradient into @p grad. */
    DEAL_II_ALWAYS_INLINE double
    value_and_gradient(const Point<2> &xi, double *grad) const
    {
      const double a  = lower + xi[0] * lower_step;
      const double ba = upper + xi[0] * upper_step - a;
      grad[0]         = dx + xi[1] * dx_step;
      grad[1]         = ba * k1;
      return a + xi[1] * ba;
    }
  };

  template <>
  struct BoxQ1Component<3>
  {
    /** The four edges along x, by (y, z) side j + 2 k: u at x = 0 and its
     * step to x = 1. */
    double base[4], step[4];
    /** d u / d x on the edges z = 0 and z = 1 at y = 0, and its change to
     * y = 1 (real coordinates). */
    double dx[2], dx_step[2];
    double k1, k2; ///< d xi_1 / d x_1, d xi_2 / d x_2

    DEAL_II_ALWAYS_INLINE void
    set(const double *u, const Tensor<2, 3> &K)
    {
      for (unsigned int e = 0; e < 4; ++e)
        {
          base[e] = u[2 * e];
          step[e] = u[2 * e + 1] - u[2 * e];
        }
      for (unsigned int k = 0; k < 2; ++k)
        {
          dx[k]      = step[2 * k] * K[0][0];
          dx_step[k] = (step[2 * k + 1] - step[2 * k]) * K[0][0];
        }
      k1 = K[1][1];
      k2 = K[2][2];
    }

    DEAL_II_ALWAYS_INLINE double
    value(const Point<3> &xi) const
    {
      double c[2]; // at (xi_0, xi_1) on the faces z = 0 and z = 1
      for (unsigned int k = 0; k < 2; ++k)
        {
          const double a0 = base[2 * k] + xi[0] * step[2 * k];
          const double a1 = base[2 * k + 1] + xi[0] * step[2 * k + 1];
          c[k]            = a0 + xi[1] * (a1 - a0);
        }
      return c[0] + xi[2] * (c[1] - c[0]);
    }

    DEAL_II_ALWAYS_INLINE double
    value_and_gradient(const Point<3> &xi, double *grad) const
    {
      double c[2], dy[2], gx[2];
      for (unsigned int k = 0; k < 2; ++k)
        {
          const double a0 = base[2 * k] + xi[0] * step[2 * k];
          dy[k]           = base[2 * k + 1] + xi[0] * step[2 * k + 1] - a0;
          c[k]            = a0 + xi[1] * dy[k];
          gx[k]           = dx[k] + xi[1] * dx_step[k];
        }
      const double cc = c[1] - c[0];
      grad[0]         = gx[0] + xi[2] * (gx[1] - gx[0]);
      grad[1]         = (dy[0] + xi[2] * (dy[1] - dy[0])) * k1;
      grad[2]         = cc * k2;
      return c[0] + xi[2] * cc;
    }
  };

  /**
   * P2G's sums over the particles of an axis-aligned box cell without
   * hanging nodes, in SSE2 pairs that stay in registers (2D) while the
   * cell's particles are added: the two vertices of an edge along x are a
   * pair, pair w = b (2D) or b + 2 e (3D). Mass and momentum by vertex,
   * with N_v = prod_d f_d (f_d = 1 - xi_d or xi_d on v's side of d, the
   * products in LinearWeights' order: the same numbers). The internal force
   * by direction: grad_j N_v = +-K_jj prod_(k != j) f_k, so the force on
   * vertex v, sum_p sum_j S_p,dj grad_j N_v with S = -V sigma, is
   * sum_j +-K_jj T_jd[u], T_jd[u] = sum_p S_p,dj prod_(k != j) f_k over
   * the 2^(dim-1) sides u of the other directions: a particle adds
   * dim^2 2^(dim-1) products instead of dim^2 2^dim, and K comes in once a
   * cell. Without @p with_mass the momentum is summed and the mass is not
   * (MUSL's re-map that keeps P2G's mass, RemapInSweep).
   */
  template <int  dim,
            bool mass_and_momentum,
            bool internal_force,
            bool with_mass = mass_and_momentum>
  struct BoxCellSums
  {
    /** Two doubles, added and multiplied as one SSE2 register (GCC's
     * vector extension: Debian's deal.II is built without
     * VectorizedArray's wider types). */
    typedef double                Pair __attribute__((vector_size(16)));
    static constexpr unsigned int n_vertices = 1u << dim;
    static constexpr unsigned int n_pairs    = n_vertices / 2;
    /** Pairs of sides of the directions other than one. */
    static constexpr unsigned int n_side_pairs           = n_vertices / 4;
    Pair                          mass[n_pairs]          = {};
    Pair                          momentum[dim][n_pairs] = {};
    /** T[j][d][q]: sides u = 2 q and 2 q + 1 (u indexes the directions
     * other than j in increasing order, the lowest first). */
    Pair T[dim][dim][n_side_pairs] = {};

    /** Add a particle of mass @p m and velocity @p v, S = -V sigma
     * (S[d][j]), at unit-cell point @p xi. */
    DEAL_II_ALWAYS_INLINE void
    add(const double          m,
        const Tensor<1, dim> &v,
        const double (&S)[dim][dim],
        const Point<dim> &xi)
    {
      Pair f[dim]; // (1 - xi_d, xi_d)
      for (unsigned int d = 0; d < dim; ++d)
        f[d] = Pair{1. - xi[d], xi[d]};
      // f_0 f_1 by b: N of the pair w = b (2D), the product before f_2 (3D)
      const Pair f01[2] = {f[0] * f[1][0], f[0] * f[1][1]};
      if (mass_and_momentum)
        for (unsigned int w = 0; w < n_pairs; ++w)
          {
            const Pair mN =
              m * (dim == 2 ? f01[w] : f01[w & 1] * f[dim - 1][w >> 1]);
            if (with_mass)
              mass[w] += mN;
            for (unsigned int d = 0; d < dim; ++d)
              momentum[d][w] += mN * v[d];
          }
      if (internal_force)
        for (unsigned int q = 0; q < n_side_pairs; ++q)
          {
            // prod_(k != j) f_k for the sides 2 q, 2 q + 1
            Pair others[dim];
            if constexpr (dim == 2)
              {
                others[0] = f[1];
                others[1] = f[0];
              }
            else
              {
                others[0] = f[1] * f[2][q];
                others[1] = f[0] * f[2][q];
                others[2] = f01[q];
              }
            for (unsigned int j = 0; j < dim; ++j)
              for (unsigned int d = 0; d < dim; ++d)
                T[j][d][q] += S[d][j] * others[j];
          }
    }

    /** add() with APIC's affine velocity (affine_transfer.h): vertex i
     * gets the momentum m N_i (v + g (xi_i - xi)), @p g = C h by unit-cell
     * direction (box_affine_unit_gradient()): add()'s m N_i v, then
     * m N_i g (xi_i - xi), so that add() stays as lean without APIC. */
    DEAL_II_ALWAYS_INLINE void
    add_affine(const double          m,
               const Tensor<1, dim> &v,
               const double (&g)[dim][dim],
               const double (&S)[dim][dim],
               const Point<dim> &xi)
    {
      add(m, v, S, xi);
      if (!mass_and_momentum)
        return;
      Pair f[dim]; // (1 - xi_d, xi_d), as in add()
      for (unsigned int d = 0; d < dim; ++d)
        f[d] = Pair{1. - xi[d], xi[d]};
      const Pair f01[2] = {f[0] * f[1][0], f[0] * f[1][1]};
      for (unsigned int w = 0; w < n_pairs; ++w)
        {
          const Pair mN =
            m * (dim == 2 ? f01[w] : f01[w & 1] * f[dim - 1][w >> 1]);
          for (unsigned int d = 0; d < dim; ++d)
            {
              // g (xi_i - xi) at the pair's vertex on the lower x side,
              // then one step along x.
              double lower = 0;
              for (unsigned int b = 0; b < dim; ++b)
                lower -= g[d][b] * xi[b];
              for (unsigned int b = 1; b < dim; ++b)
                if ((w >> (b - 1)) & 1u)
                  lower += g[d][b];
              momentum[d][w] += mN * Pair{lower, lower + g[d][0]};
            }
        }
    }

    /** Add the sums into the nodal vectors @p to (.mass, .momentum[d],
     * .force[d]: raw arrays) at the cell's @p nodes: the force from the
     * cell's d xi / d x @p K (diagonal), each vertex's summed over j in
     * increasing order in locals first, then added. Mass and momentum go
     * straight from the pairs: no vertex arrays zeroed and copied in
     * between (the 2D column, USL: 480 -> 472 instructions per
     * particle-step, the same numbers). */
    template <typename To>
    DEAL_II_ALWAYS_INLINE void
    scatter(const Tensor<2, dim>     &K,
            const unsigned int *const nodes,
            const To                 &to) const
    {
      double vertex_force[n_vertices][dim];
      if (internal_force)
        {
          for (unsigned int v = 0; v < n_vertices; ++v)
            for (unsigned int d = 0; d < dim; ++d)
              vertex_force[v][d] = 0;
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int u = 0; u < n_vertices / 2; ++u)
                {
                  const double t = K[j][j] * T[j][d][u / 2][u % 2];
                  // The vertices on side u of the other directions: bit j
                  // inserted into u, 0 (N falls along j) and 1.
                  const unsigned int low =
                    (u & ((1u << j) - 1)) | ((u >> j) << (j + 1));
                  vertex_force[low][d] -= t;
                  vertex_force[low | (1u << j)][d] += t;
                }
        }
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          const unsigned int n = nodes[v];
          if (mass_and_momentum && with_mass)
            to.mass[n] += mass[v / 2][v % 2];
          for (unsigned int d = 0; d < dim; ++d)
            {
              if (mass_and_momentum)
                to.momentum[d][n] += momentum[d][v / 2][v % 2];
              if constexpr (internal_force) // @p to may have no force
                to.force[d][n] += vertex_force[v][d];
            }
        }
    }
  };
} // namespace dealmpm
