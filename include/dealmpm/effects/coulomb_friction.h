#pragma once

#include <deal.II/base/tensor.h>

namespace dealmpm
{
  using namespace dealii;

  /**
   * Coulomb's law at one node: a constraint along the unit normal @p n has
   * just taken @p pressed (per unit mass, > 0 when it pushed) off the
   * node's normal velocity; friction may then take at most mu * pressed off
   * the tangential velocity of @p v, and sticks the node when that is
   * enough. Returns the change of @p v (tangential, against the slip).
   */
  template <int dim>
  Tensor<1, dim>
  coulomb_change(const Tensor<1, dim> &v,
                 const Tensor<1, dim> &n,
                 const double          pressed,
                 const double          mu)
  {
    const Tensor<1, dim> tangential = v - (v * n) * n;
    const double         slip       = tangential.norm();
    if (!(pressed > 0.) || slip == 0.)
      return {};
    if (slip <= mu * pressed)
      return -tangential;
    return -(mu * pressed / slip) * tangential;
  }
} // namespace dealmpm
