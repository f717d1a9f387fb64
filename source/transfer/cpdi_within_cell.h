#pragma once

#include <dealmpm/transfer/particle_weights.h>

namespace dealmpm
{
  /**
   * The corners' sums in closed form, for a domain whose corners x_c =
   * x + R s_c all lie in one box cell, at unit-cell point @p xi of x, with
   * @p R_unit = K R (unit-cell lengths). Q1 is multilinear, so the mean
   * of N_v over the corners is N_v(xi) plus each mixed second derivative
   * d_ab N_v times the corners' second moment M_ab = sum_k R_ak R_bk
   * (the cubic term's mean is zero), and the mean of N_v(x_c) R^-T s_c
   * is grad N_v(x), in 3D plus d_012 N_v R^-T T with T_i = R_0i M_12 +
   * R_1i M_02 + R_2i M_01 - 2 R_0i R_1i R_2i (the mean of s_i times the
   * cubic term). The corners' sums to round-off; about half the domains
   * of a column take this. Private to cpdi_stencil.cc, whose corner loops
   * it replaces for those domains.
   */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline void
  sums_within_cell(const Point<dim>     &xi,
                   const Tensor<2, dim> &R_unit,
                   const Tensor<2, dim> &R_inverse_transpose,
                   const Tensor<1, dim> &K,
                   double               *N,
                   Tensor<1, dim>       *grad_N)
  {
    constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
    double                 M[dim][dim];
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a + 1; b < dim; ++b)
        M[a][b] = R_unit[a] * R_unit[b];
    q1_values<dim>(xi, N, grad_N);
    Tensor<1, dim> QT;
    if constexpr (dim == 3)
      {
        Tensor<1, dim> T;
        for (unsigned int i = 0; i < dim; ++i)
          T[i] = R_unit[0][i] * M[1][2] + R_unit[1][i] * M[0][2] +
                 R_unit[2][i] * M[0][1] -
                 2. * R_unit[0][i] * R_unit[1][i] * R_unit[2][i];
        QT = R_inverse_transpose * T;
      }
#pragma GCC unroll 8
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        double sign[dim], f[dim];
        for (unsigned int d = 0; d < dim; ++d)
          {
            const bool upper = (v >> d) & 1u;
            sign[d]          = upper ? 1. : -1.;
            f[d]             = upper ? xi[d] : 1. - xi[d];
          }
        for (unsigned int d = 0; d < dim; ++d)
          grad_N[v][d] *= K[d];
        if constexpr (dim == 2)
          N[v] += sign[0] * sign[1] * M[0][1];
        else
          {
            N[v] += sign[0] * sign[1] * f[2] * M[0][1] +
                    sign[0] * sign[2] * f[1] * M[0][2] +
                    sign[1] * sign[2] * f[0] * M[1][2];
            // R^-T T of K R is K_0 K_1 K_2 R^-T T of R: d_012 N_v's
            // factor K_0 K_1 K_2 is in it.
            grad_N[v] += sign[0] * sign[1] * sign[2] * QT;
          }
      }
  }
} // namespace dealmpm
