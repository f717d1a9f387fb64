#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>

namespace dealmpm
{
  using namespace dealii;

  /**
   * The smallest principal stretch of @p F (its smallest singular value):
   * a grid cell of size h in the reference configuration is at least this
   * times h long in the current one, so the stable step of a grid that stays
   * in the reference configuration (total Lagrangian) scales h by it. |J| /
   * sqrt of the product of the larger eigenvalues of F^T F, which keeps its
   * accuracy when the stretch is small.
   */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline double
  smallest_stretch(const Tensor<2, dim> &F)
  {
    const SymmetricTensor<2, dim> C = symmetrize(transpose(F) * F);
    const double                  J = std::abs(determinant(F));
    if constexpr (dim == 2)
      {
        const double half_trace = 0.5 * (C[0][0] + C[1][1]);
        const double radius =
          std::hypot(0.5 * (C[0][0] - C[1][1]), double(C[0][1]));
        return J / std::sqrt(half_trace + radius);
      }
    else
      {
        const auto lambda = eigenvalues(C); // descending
        return J / std::sqrt(lambda[0] * lambda[1]);
      }
  }

} // namespace dealmpm
