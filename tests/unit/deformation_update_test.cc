// The deformation gradient update variants (DeformationUpdate) against the
// exact exp(t L) for a constant L: rigid rotation, uniaxial stretch and
// simple shear, each converging at its order (first order and subcycle 1,
// Cayley 2, Taylor series K); Cayley keeps a rotation a rotation (J = 1 to
// round-off) and J > 0 where first order turns the point inside out.
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <dealmpm/transfer/deformation_update.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace dealmpm;
using Variant = DeformationUpdate::Variant;

namespace
{
  DeformationUpdate
  variant(const Variant v, const unsigned int terms = 4)
  {
    DeformationUpdate u;
    u.variant      = v;
    u.taylor_terms = terms;
    return u;
  }

  /** F after n equal steps of dF from I up to t = 1. */
  template <int dim>
  Tensor<2, dim>
  advance(const DeformationUpdate &u, const Tensor<2, dim> &L, const int n)
  {
    Tensor<2, dim>       F  = unit_symmetric_tensor<dim>();
    const Tensor<2, dim> dF = u.increment(Tensor<2, dim>(L / n));
    for (int i = 0; i < n; ++i)
      F = dF * F;
    return F;
  }

  /** The observed order of the error at t = 1 between n and 2n steps. */
  template <int dim>
  double
  order(const DeformationUpdate &u,
        const Tensor<2, dim>    &L,
        const Tensor<2, dim>    &exact,
        const int                n)
  {
    const double coarse = (advance(u, L, n) - exact).norm();
    const double fine   = (advance(u, L, 2 * n) - exact).norm();
    return std::log2(coarse / fine);
  }

  const Tensor<2, 2> spin({{0., -1.}, {1., 0.}});
  const Tensor<2, 2> rotation({{std::cos(1.), -std::sin(1.)},
                               {std::sin(1.), std::cos(1.)}});
  const Tensor<2, 2> stretch({{0.8, 0.}, {0., 0.}});
  const Tensor<2, 2> stretched({{std::exp(0.8), 0.}, {0., 1.}});
} // namespace

TEST(DeformationUpdate, EachVariantConvergesAtItsOrder)
{
  for (const auto &[L, exact] :
       {std::make_pair(spin, rotation), std::make_pair(stretch, stretched)})
    {
      EXPECT_NEAR(order(variant(Variant::first_order), L, exact, 16), 1., 0.1);
      EXPECT_NEAR(order(variant(Variant::subcycle), L, exact, 16), 1., 0.1);
      EXPECT_NEAR(order(variant(Variant::cayley), L, exact, 16), 2., 0.1);
      EXPECT_NEAR(order(variant(Variant::taylor_series, 2), L, exact, 8),
                  2.,
                  0.15);
      EXPECT_NEAR(order(variant(Variant::taylor_series, 4), L, exact, 4),
                  4.,
                  0.2);
      // Subcycling N = 4 times cuts the first-order error about 4 times.
      const double first =
        (advance(variant(Variant::first_order), L, 16) - exact).norm();
      const double subcycled =
        (advance(variant(Variant::subcycle), L, 16) - exact).norm();
      EXPECT_NEAR(first / subcycled, 4., 0.4);
    }
}

TEST(DeformationUpdate, CayleyKeepsARotationARotation)
{
  // Even at dt |L| = 0.5, F^T F = I and J = 1 to round-off; first order's J
  // grows by (1 + dt^2 |L|^2) per step.
  const Tensor<2, 2> F = advance(variant(Variant::cayley), spin, 2);
  EXPECT_LT((transpose(F) * F - unit_symmetric_tensor<2>()).norm(), 1e-14);
  EXPECT_NEAR(determinant(F), 1., 1e-14);
  EXPECT_NEAR(determinant(advance(variant(Variant::first_order), spin, 2)),
              1.25 * 1.25,
              1e-14);
  // In 3D about an oblique axis.
  const Tensor<1, 3> w({0.3, -0.5, 0.8});
  const Tensor<2, 3> W(
    {{0., -w[2], w[1]}, {w[2], 0., -w[0]}, {-w[1], w[0], 0.}});
  const Tensor<2, 3> F3 = advance(variant(Variant::cayley), W, 3);
  EXPECT_LT((transpose(F3) * F3 - unit_symmetric_tensor<3>()).norm(), 1e-14);
  EXPECT_NEAR(determinant(F3), 1., 1e-14);
}

TEST(DeformationUpdate, SimpleShearIsExactForEveryVariant)
{
  // L is nilpotent: exp(dt L) = I + dt L, which every variant reproduces.
  const Tensor<2, 2> shear({{0., 3.}, {0., 0.}});
  const Tensor<2, 2> exact({{1., 3.}, {0., 1.}});
  for (const Variant v : {Variant::first_order,
                          Variant::taylor_series,
                          Variant::cayley,
                          Variant::subcycle})
    EXPECT_LT((advance(variant(v), shear, 3) - exact).norm(), 1e-14);
}

TEST(DeformationUpdate, CayleyKeepsJPositiveWhereFirstOrderDoesNot)
{
  // A compression of dt L = -1.5 in one step: first order gives J = -0.5;
  // Cayley (1 - 0.75) / (1 + 0.75), exp(-1.5) = 0.22 exactly.
  const Tensor<2, 2> squeeze({{-1.5, 0.}, {0., 0.}});
  EXPECT_LT(determinant(variant(Variant::first_order).increment(squeeze)), 0.);
  EXPECT_NEAR(determinant(variant(Variant::cayley).increment(squeeze)),
              0.25 / 1.75,
              1e-15);
}

TEST(DeformationUpdate, ParsesItsNames)
{
  EXPECT_EQ(DeformationUpdate::parse("Cayley"), Variant::cayley);
  EXPECT_EQ(DeformationUpdate::parse("Taylor series"), Variant::taylor_series);
  EXPECT_EQ(DeformationUpdate::parse("subcycle"), Variant::subcycle);
  EXPECT_EQ(DeformationUpdate::parse("first order"), Variant::first_order);
  EXPECT_THROW(DeformationUpdate::parse("second order"), std::exception);
}
