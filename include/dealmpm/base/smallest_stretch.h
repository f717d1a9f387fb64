#pragma once

#include <deal.II/base/numbers.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>

namespace dealmpm
{
  using namespace dealii;

  /**
   * lambda_0 lambda_1 of a symmetric 3 x 3 @p T (its eigenvalues lambda_0
   * >= lambda_1 >= lambda_2), from the smallest alone: lambda_0 lambda_1 =
   * I2 - lambda_2 (I1 - lambda_2), with I1 the trace and I2 the sum of the
   * principal 2 x 2 minors. lambda_2 is deal.II's trigonometric solution
   * (eigenvalues(), operation for operation) for the smallest root only:
   * one acos and one cos, where all three roots take two cosines and a
   * sort. For T = F^T F the minors are squared areas (not negative), so
   * I2 has no cancellation between them, and an error of lambda_2 of
   * eps I1 moves the product by eps I1^2 at most: full relative accuracy
   * also when lambda_2 is tiny.
   */
  DEAL_II_ALWAYS_INLINE inline double
  product_of_two_largest_eigenvalues(const SymmetricTensor<2, 3> &T)
  {
    const double t00 = T[0][0], t11 = T[1][1], t22 = T[2][2];
    const double t01 = T[0][1], t02 = T[0][2], t12 = T[1][2];
    const double upper_squares = t01 * t01 + t02 * t02 + t12 * t12;
    const double trace         = t00 + t11 + t22;
    const double minors = (t00 * t11 - t01 * t01) + (t00 * t22 - t02 * t02) +
                          (t11 * t22 - t12 * t12);
    double smallest;
    if (upper_squares == 0.)
      smallest = std::min(t00, std::min(t11, t22));
    else
      {
        // T = p B + q I; det(lambda I - B) = lambda^3 - 3 lambda - det B.
        const double q = trace / 3.0;
        const double p =
          std::sqrt(((t00 - q) * (t00 - q) + (t11 - q) * (t11 - q) +
                     (t22 - q) * (t22 - q) + 2.0 * upper_squares) /
                    6.0);
        const double inverse_p = 1.0 / p;
        const double b00 = (t00 - q) * inverse_p, b11 = (t11 - q) * inverse_p,
                     b22 = (t22 - q) * inverse_p;
        const double b01 = t01 * inverse_p, b02 = t02 * inverse_p,
                     b12 = t12 * inverse_p;
        const double tmp = b01 * b02 * b12;
        const double half_det_B =
          (tmp + tmp + b00 * b11 * b22 - b00 * b12 * b12 - b11 * b02 * b02 -
           b22 * b01 * b01) /
          2.0;
        // phi in [0, pi / 3]: phi + 2 pi / 3 gives the smallest root.
        const double phi = half_det_B <= -1.0 ? numbers::PI / 3.0 :
                           half_det_B >= 1.0  ? 0.0 :
                                                std::acos(half_det_B) / 3.0;
        smallest = q + 2.0 * p * std::cos(phi + (2.0 / 3.0 * numbers::PI));
      }
    return minors - smallest * (trace - smallest);
  }

  /**
   * The square of the smallest principal stretch of @p F (the smallest
   * eigenvalue of F^T F): J^2 over the product of the larger eigenvalues,
   * which keeps its accuracy when the stretch is small. Squared, so that
   * the smallest over many points takes one square root (the square root
   * is monotone: the root of the smallest square is the smallest root).
   */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline double
  smallest_stretch_squared(const Tensor<2, dim> &F)
  {
    const SymmetricTensor<2, dim> C  = symmetrize(transpose(F) * F);
    const double                  J  = determinant(F);
    const double                  J2 = J * J;
    if constexpr (dim == 2)
      {
        // The larger eigenvalue; no std::hypot: C's entries are far from
        // overflow, and hypot's care cost 130 instructions a region cell.
        const double half_trace = 0.5 * (C[0][0] + C[1][1]);
        const double half_gap   = 0.5 * (C[0][0] - C[1][1]);
        const double off        = C[0][1];
        return J2 / (half_trace + std::sqrt(half_gap * half_gap + off * off));
      }
    else
      return J2 / product_of_two_largest_eigenvalues(C);
  }

  /**
   * The smallest principal stretch of @p F (its smallest singular value):
   * a grid cell of size h in the reference configuration is at least this
   * times h long in the current one, so the stable step of a grid that stays
   * in the reference configuration (total Lagrangian) scales h by it.
   */
  template <int dim>
  DEAL_II_ALWAYS_INLINE inline double
  smallest_stretch(const Tensor<2, dim> &F)
  {
    return std::sqrt(smallest_stretch_squared(F));
  }

} // namespace dealmpm
