#pragma once

// P2G's shares of a particle as vectors: with windowed weights computed
// where used a row of nodes along x at a time, with stored weights into an
// interleaved block entry by entry; included by particle_to_grid.cc only.

#include <dealmpm/base/lanes.h>
#include <dealmpm/transfer/particle_weights.h>

#include "p2g_targets.h"

namespace dealmpm
{
  namespace p2g_rows
  {
    /** A row's force shares along and across x (add_by_rows()). */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline void
    row_force_factors(const double (&P)[dim][dim],
                      const double v12,
                      const double s12,
                      const double s2,
                      double (&along)[dim],
                      double (&across)[dim])
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          along[d]  = P[d][0] * v12;
          across[d] = P[d][1] * s12;
          if constexpr (dim == 3)
            across[d] += P[d][2] * s2;
        }
    }

    /** add_by_rows() into an InterleavedNodes block, a node's mass,
     * momentum and (2D) f_x as one vector of four, 2D's f_y alone and 3D's
     * force as a second vector of four (its fourth lane the node's padding:
     * not read), a row's force factors from P's columns as vectors: the
     * same products and sums as row_force_factors(),
     * add_mass_and_momentum() and add_force(). */
    template <int  dim,
              bool mass_and_momentum,
              bool internal_force,
              typename Particle>
    DEAL_II_ALWAYS_INLINE inline void
    add_rows_to_block(const WindowWeights<dim> &weights,
                      const std::size_t         k,
                      const Particle           &p,
                      const GridCell<dim>      &c,
                      const double              m,
                      const Tensor<1, dim>     &v,
                      const double (&P)[dim][dim],
                      double *const block)
    {
      constexpr unsigned int stride = InterleavedNodes<dim>::stride;
      // m N (1, v): the lane of 2D's f_x adds m N 0.
      const Lanes4 one_v = {1., v[0], v[1], dim == 3 ? v[dim - 1] : 0.};
      // 3D: P's columns, so that a row's force factors (row_force_factors()'s
      // products and sums) are vector products, not nine scalar ones (in
      // 2D the scalar ones cost less than building the vectors). The
      // fourth lane repeats the third (not read): zeroing it compiled to a
      // vmovq that valgrind 3.19 cannot run.
      [[maybe_unused]] Lanes4 column[dim];
      if constexpr (dim == 3)
        for (unsigned int j = 0; j < dim; ++j)
          column[j] = Lanes4{P[0][j], P[1][j], P[2][j], P[2][j]};
      weights.rows(
        k,
        p,
        c,
        [&](const auto          n_x,
            const unsigned int *row,
            const NodeWindow   &w0,
            const double        v12,
            const double        s12,
            const double        s2) DEAL_II_ALWAYS_INLINE {
          const double m_v12 = m * v12;
          const auto   head  = [&](double *const x, const unsigned int k) {
            Lanes4 sums = load_lanes<Lanes4>(x);
            if (mass_and_momentum)
              sums += (w0.value[k] * m_v12) * one_v;
            return sums;
          };
          if constexpr (dim == 2)
            {
              double along[dim], across[dim];
              row_force_factors<dim>(P, v12, s12, s2, along, across);
              // f_x in the last lane of the four, f_y alone.
              const Lanes4 head_along  = {0., 0., 0., along[0]},
                           head_across = {0., 0., 0., across[0]};
              for (unsigned int k = 0; k < n_x; ++k)
                {
                  double *const x    = block + std::size_t(row[k]) * stride;
                  Lanes4        sums = head(x, k);
                  if (internal_force)
                    sums +=
                      w0.slope[k] * head_along + w0.value[k] * head_across;
                  store_lanes(x, sums);
                  if (internal_force)
                    x[stride - 1] +=
                      w0.slope[k] * along[1] + w0.value[k] * across[1];
                }
            }
          else
            {
              const Lanes4 along  = v12 * column[0],
                           across = s12 * column[1] + s2 * column[2];
              for (unsigned int k = 0; k < n_x; ++k)
                {
                  double *const x = block + std::size_t(row[k]) * stride;
                  store_lanes(x, head(x, k));
                  if (internal_force)
                    store_lanes(x + 4,
                                load_lanes<Lanes4>(x + 4) +
                                  (w0.slope[k] * along + w0.value[k] * across));
                }
            }
        });
    }

    /** A particle's shares with windowed weights computed where used, a
     * row of nodes along x at a time (WindowWeights::rows()): a node's
     * force is x's slope times the row's P_d0 v12 plus x's value times
     * its P_d1 s12 + P_d2 s2, each taken once a row. @p P: the force per
     * gradient (-V sigma). */
    template <int  dim,
              bool mass_and_momentum,
              bool internal_force,
              typename Particle,
              typename Fields>
    DEAL_II_ALWAYS_INLINE inline void
    add_by_rows(const WindowWeights<dim> &weights,
                const std::size_t         k,
                const Particle           &p,
                const GridCell<dim>      &c,
                const double              m,
                const Tensor<1, dim>     &v,
                const double (&P)[dim][dim],
                const Fields &to)
    {
      if constexpr (Fields::interleaved)
        {
          add_rows_to_block<dim, mass_and_momentum, internal_force>(
            weights, k, p, c, m, v, P, to.block);
          return;
        }
      weights.rows(k,
                   p,
                   c,
                   [&](const auto          n_x,
                       const unsigned int *row,
                       const NodeWindow   &w0,
                       const double        v12,
                       const double        s12,
                       const double        s2) DEAL_II_ALWAYS_INLINE {
                     const double m_v12 = m * v12;
                     double       along[dim], across[dim];
                     row_force_factors<dim>(P, v12, s12, s2, along, across);
                     for (unsigned int k = 0; k < n_x; ++k)
                       {
                         if (mass_and_momentum)
                           to.add_mass_and_momentum(row[k],
                                                    w0.value[k] * m_v12,
                                                    v);
                         if (internal_force)
                           {
                             double f[dim];
                             for (unsigned int d = 0; d < dim; ++d)
                               f[d] = w0.slope[k] * along[d] +
                                      w0.value[k] * across[d];
                             to.add_force(row[k], f);
                           }
                       }
                   });
    }

    /** Particle @p k's stored entries added into the InterleavedNodes
     * @p block as vectors: the mass and momentum m N (1, v) one product
     * and sum, the force P grad N the columns of P (@p P[d][j]) times
     * grad N's components, summed in increasing j as node by node. The
     * same numbers as InterleavedNodes::add_mass_and_momentum() and
     * add_force(); the 3D CPDI column's P2G took about 38 instructions an
     * entry that way. */
    template <int dim, bool mass_and_momentum, bool internal_force>
    DEAL_II_ALWAYS_INLINE inline void
    add_entries_to_block(const Stencil<dim>   &stencil,
                         const std::size_t     k,
                         const double          m,
                         const Tensor<1, dim> &v,
                         const double (&P)[dim][dim],
                         double *const block)
    {
      constexpr unsigned int stride = InterleavedNodes<dim>::stride;
      // Lanes: 3D (m, m v) and the force with a fourth (padding) lane;
      // 2D the momentum and the force as pairs.
      using Pair  = std::conditional_t<dim == 3, Lanes4, Lanes2>;
      Pair unit_v = {}, P_column[dim] = {};
      for (unsigned int d = 0; d < dim; ++d)
        {
          unit_v[d + (dim == 3)] = v[d];
          for (unsigned int j = 0; j < dim; ++j)
            P_column[j][d] = P[d][j];
        }
      if constexpr (dim == 3)
        unit_v[0] = 1.;
      for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
        {
          double *const x = block + std::size_t(stencil.node[e]) * stride;
          if (mass_and_momentum)
            {
              const double mN = m * stencil.N[e];
              if constexpr (dim == 2)
                x[0] += mN;
              double *const momentum = x + (dim == 2);
              store_lanes(momentum, load_lanes<Pair>(momentum) + mN * unit_v);
            }
          if (internal_force)
            {
              const Tensor<1, dim> &grad_N = stencil.grad_N[e];
              Pair                  fi     = P_column[0] * grad_N[0];
              for (unsigned int j = 1; j < dim; ++j)
                fi += P_column[j] * grad_N[j];
              double *const force = x + 1 + dim;
              store_lanes(force, load_lanes<Pair>(force) + fi);
            }
        }
    }
  } // namespace p2g_rows
} // namespace dealmpm
