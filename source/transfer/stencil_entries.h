#pragma once

#include <dealmpm/transfer/stencil.h>

#include <cstddef>

namespace dealmpm
{
  /** Room in @p stencil's entry arrays up to entry @p end: the kernels
   * that append a particle at a time grow them by half as they fill, so
   * that a step's appends cost amortised constant time and the arrays,
   * kept from step to step, stop growing. Private to the stencil kernels. */
  template <int dim>
  inline void
  make_room_for_entries(Stencil<dim> &stencil, const std::size_t end)
  {
    if (stencil.node.size() >= end)
      return;
    const std::size_t capacity = end * 3 / 2 + 64;
    stencil.node.resize(capacity);
    stencil.N.resize(capacity);
    stencil.grad_N.resize(capacity);
  }
} // namespace dealmpm
