#pragma once

#include <deal.II/base/tensor.h>

namespace dealmpm
{
  using namespace dealii;

  /** One direction of a particle's weights on its cell's lattice (nodes
   * x0 - h, x0, x1, x1 + h of the cell [x0, x1]): each node's 1D weight
   * (value) and its derivative along x (slope); nodes first .. first +
   * count - 1 carry them, the others are unset. */
  struct LatticeWeights1D
  {
    double       value[4];
    double       slope[4];
    unsigned int first;
    unsigned int count;
  };

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
} // namespace dealmpm
