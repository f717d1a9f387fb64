#pragma once

#include <dealmpm/transfer/lattice_weights.h>
#include <dealmpm/transfer/stencil.h>

#include <cstdint>

#include "stencil_entries.h"

namespace dealmpm
{
  /**
   * @p f(node, N, grad N) for the products over the directions of the 1D
   * weights @p w on the lattice @p block (4^dim nodes, node n at sum_d n_d
   * 4^d): N = prod_d value_d and d N / d x_d = slope_d times the other
   * directions' values, x fastest.
   */
  template <int dim, typename Function>
  DEAL_II_ALWAYS_INLINE inline void
  for_each_product(const unsigned int     *block,
                   const LatticeWeights1D *w,
                   Function              &&f)
  {
    const unsigned int count_2 = dim == 3 ? w[dim - 1].count : 1;
    for (unsigned int i2 = 0; i2 < count_2; ++i2)
      for (unsigned int i1 = w[1].first; i1 < w[1].first + w[1].count; ++i1)
        {
          double       v12 = w[1].value[i1], s12 = w[1].slope[i1];
          double       s2  = 0; // 3D: v0 v1 times this is d N / d x_2
          unsigned int row = 4 * i1;
          if constexpr (dim == 3)
            {
              const unsigned int n2 = w[2].first + i2;
              s12 *= w[2].value[n2];
              s2 = w[1].value[i1] * w[2].slope[n2];
              v12 *= w[2].value[n2];
              row += 16 * n2;
            }
          for (unsigned int i0 = w[0].first; i0 < w[0].first + w[0].count; ++i0)
            {
              Tensor<1, dim> grad_N;
              grad_N[0] = w[0].slope[i0] * v12;
              grad_N[1] = w[0].value[i0] * s12;
              if constexpr (dim == 3)
                grad_N[dim - 1] = w[0].value[i0] * s2;
              f(block[row + i0], w[0].value[i0] * v12, grad_N);
            }
        }
  }
  /** Whether the cells that the 1D weights @p w span all exist in a
   * patch whose cells are @p present (LatticeBlocks::cells_present(); the
   * cell on side k of a direction spans lattice nodes k and k + 1). */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline bool
  spans_present_cells(const LatticeWeights1D *w, const std::uint32_t present)
  {
    constexpr std::uint32_t all =
      (std::uint32_t(1) << Utilities::pow(3, dim)) - 1;
    if (present == all)
      return true;
    const unsigned int last_2 =
      dim == 3 ? w[dim - 1].first + w[dim - 1].count - 1 : 1;
    for (unsigned int k2 = dim == 3 ? w[dim - 1].first : 0; k2 < last_2; ++k2)
      for (unsigned int k1 = w[1].first; k1 + 1 < w[1].first + w[1].count; ++k1)
        for (unsigned int k0 = w[0].first; k0 + 1 < w[0].first + w[0].count;
             ++k0)
          if (!((present >> (k0 + 3 * k1 + 9 * k2)) & 1u))
            return false;
    return true;
  }

  /** Particle k's entries at @p e: for_each_product() of the 1D weights
   * @p w on the lattice @p block. Private to the stencil kernels. */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline void
  append_products(const unsigned int     *block,
                  const LatticeWeights1D *w,
                  const std::size_t       k,
                  std::size_t            &e,
                  Stencil<dim>           &stencil)
  {
    stencil.begin[k]           = e;
    const unsigned int count_2 = dim == 3 ? w[dim - 1].count : 1;
    const unsigned int n_new   = w[0].count * w[1].count * count_2;
    make_room_for_entries(stencil, e + n_new);
    // Through raw pointers: with the vectors' own, every store reloaded
    // their data pointers.
    unsigned int   *node   = stencil.node.data() + e;
    double         *N      = stencil.N.data() + e;
    Tensor<1, dim> *grad_N = stencil.grad_N.data() + e;
    e += n_new;
    for_each_product<dim>(block,
                          w,
                          [&](const unsigned int    n,
                              const double          value,
                              const Tensor<1, dim> &grad)
                            DEAL_II_ALWAYS_INLINE {
                              *node++   = n;
                              *N++      = value;
                              *grad_N++ = grad;
                            });
  }
} // namespace dealmpm
