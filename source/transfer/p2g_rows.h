#pragma once

// P2G's shares of a particle with windowed weights computed where used, a
// row of nodes along x at a time; included by particle_to_grid.cc only.

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
     * momentum and (2D) f_x as one vector of four, 3D's f_x, f_y as a pair
     * and the last force component alone (Lanes4): the same products and
     * sums as add_mass_and_momentum() and add_force(). */
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
          double       along[dim], across[dim];
          row_force_factors<dim>(P, v12, s12, s2, along, across);
          // 2D: f_x in the last lane of the four; 3D: f_x, f_y a pair.
          const Lanes4 head_along                   = {0., 0., 0., along[0]},
                       head_across                  = {0., 0., 0., across[0]};
          [[maybe_unused]] const Lanes2 pair_along  = {along[0], along[1]},
                                        pair_across = {across[0], across[1]};
          for (unsigned int k = 0; k < n_x; ++k)
            {
              double *const x    = block + std::size_t(row[k]) * stride;
              Lanes4        head = load_lanes<Lanes4>(x);
              if (mass_and_momentum)
                head += (w0.value[k] * m_v12) * one_v;
              if (internal_force && dim == 2)
                head += w0.slope[k] * head_along + w0.value[k] * head_across;
              store_lanes(x, head);
              if (!internal_force)
                continue;
              if constexpr (dim == 3)
                store_lanes(x + 4,
                            load_lanes<Lanes2>(x + 4) +
                              (w0.slope[k] * pair_along +
                               w0.value[k] * pair_across));
              x[stride - 1] +=
                w0.slope[k] * along[dim - 1] + w0.value[k] * across[dim - 1];
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
  } // namespace p2g_rows
} // namespace dealmpm
