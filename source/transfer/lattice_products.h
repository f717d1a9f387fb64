#pragma once

#include <dealmpm/transfer/lattice_weights.h>
#include <dealmpm/transfer/stencil.h>

#include <cstdint>

#include "stencil_entries.h"

namespace dealmpm
{
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
