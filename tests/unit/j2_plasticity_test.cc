// J2 plasticity without a grid: the elastic limit, the closed form under
// uniaxial strain, the yield surface after every return, objectivity, simple
// shear to gamma = 10, power-law hardening and the energy balance.
#include <dealmpm/materials/hencky.h>
#include <dealmpm/materials/j2_plasticity.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "material_point.h"

using namespace dealmpm;

namespace
{
  /** K = 10, G = 5 as Lame constants. */
  LameParameters
  lame_of(const double K, const double G)
  {
    return {K - 2. / 3. * G, G};
  }

  /** A J2 point in dim dimensions with K, G and a hardening law. */
  template <int dim>
  struct Point3 : test::MaterialPoint<dim, J2Plasticity<dim>>
  {
    Point3(const double K, const double G, const IsotropicHardening &h)
      : test::MaterialPoint<dim, J2Plasticity<dim>>(lame_of(K, G), h)
    {}

    double
    alpha() const
    {
      return J2Plasticity<dim>::plastic_strain(this->state());
    }

    double
    plastic_work() const
    {
      return this->model.dissipated_energy_density(this->state());
    }
  };

  using test::stretch_x;
  using test::von_mises;

  IsotropicHardening
  linear(const double yield, const double H)
  {
    IsotropicHardening h;
    h.yield_stress = yield;
    h.modulus      = H;
    return h;
  }

} // namespace

// Below yield the model is Hencky elasticity: at strain 1e-6 the stress is
// linear elasticity's to O(strain^2), nothing plastic.
TEST(J2Plasticity, ElasticBelowYield)
{
  Point3<3>    p(10, 5, linear(1, 2));
  Tensor<2, 3> F = unit_symmetric_tensor<3>();
  F[0][0] += 1e-6;
  F[0][1] += 2e-6;
  p.deform(F);
  const SymmetricTensor<2, 3> eps = symmetrize(F) - unit_symmetric_tensor<3>();
  const SymmetricTensor<2, 3> linear_stress =
    (10 - 10. / 3.) * trace(eps) * unit_symmetric_tensor<3>() + 10. * eps;
  EXPECT_LT((p.stress - linear_stress).norm(), 1e-10);
  EXPECT_EQ(p.alpha(), 0);
  EXPECT_EQ(p.plastic_work(), 0);
}

// Uniaxial logarithmic strain 0.5 with K = 10, G = 5, sigma_y = 1, H = 2:
// d_gamma = (2 G eps - sigma_y) / (3 G + H) = 4/17 = 0.235294 and
// tau_11 = K eps + 2 G (2/3) eps (1 - 3 G d_gamma / (2 G eps)) = 5 + 50/51
// = 5.980392; radial return is exact on this proportional path, so one
// step and 50 steps give the same; in 2D (plane strain) too.
TEST(J2Plasticity, UniaxialStrainClosedForm)
{
  for (const unsigned int steps : {1u, 50u})
    {
      Point3<3> p3(10, 5, linear(1, 2));
      Point3<2> p2(10, 5, linear(1, 2));
      for (unsigned int s = 1; s <= steps; ++s)
        {
          p3.deform(stretch_x<3>(0.5 * s / steps));
          p2.deform(stretch_x<2>(0.5 * s / steps));
        }
      EXPECT_NEAR(p3.alpha(), 4. / 17., 1e-12) << steps << " steps";
      EXPECT_NEAR(p3.kirchhoff(stretch_x<3>(0.5))[0][0], 5. + 50. / 51., 1e-12);
      EXPECT_NEAR(p2.alpha(), 4. / 17., 1e-12);
      const SymmetricTensor<2, 3> tau2 = p2.kirchhoff(stretch_x<2>(0.5));
      EXPECT_NEAR(tau2[0][0], 5. + 50. / 51., 1e-12);
      // The lateral stresses are equal, in plane and out of plane.
      EXPECT_NEAR(tau2[1][1], tau2[2][2], 1e-12);
      EXPECT_NEAR(von_mises(tau2), 1. + 2. * 4. / 17., 1e-12);
    }
}

// Along a wandering strain path (stretch, shear, compression, rotation),
// every return lands on the yield surface (q <= sigma_y(alpha)), and the
// plastic strain and plastic work never decrease.
TEST(J2Plasticity, ConsistentAfterEveryReturn)
{
  Point3<3>    p(10, 5, linear(1, 0.5));
  double       alpha = 0, work = 0;
  unsigned int plastic_steps = 0;
  for (unsigned int s = 1; s <= 400; ++s)
    {
      const double t = 0.01 * s;
      Tensor<2, 3> F;
      F[0][0] = 1 + 0.3 * std::sin(3 * t);
      F[1][1] = 1 - 0.2 * std::sin(2 * t);
      F[2][2] = 1 + 0.1 * std::cos(5 * t);
      F[0][1] = 0.5 * std::sin(t);
      F[1][2] = -0.4 * std::sin(1.7 * t);
      F[2][0] = 0.2 * t;
      p.deform(F);
      const double q = von_mises(p.kirchhoff(F));
      EXPECT_LE(q, (1 + 0.5 * p.alpha()) * (1 + 1e-12)) << "step " << s;
      EXPECT_GE(p.alpha(), alpha);
      EXPECT_GE(p.plastic_work(), work);
      plastic_steps += p.alpha() > alpha;
      alpha = p.alpha();
      work  = p.plastic_work();
    }
  EXPECT_GT(plastic_steps, 100u); // the path does yield
}

// After a plastic pre-strain, a rigid rotation Q F gives Q sigma Q^T and
// leaves the plastic strain alone (to round-off: the trial b_e is
// F C_p^-1 F^T).
TEST(J2Plasticity, ObjectiveUnderRigidRotation)
{
  Tensor<2, 3> F0 = unit_symmetric_tensor<3>();
  F0[0][0]        = 1.3;
  F0[0][1]        = 0.4;
  F0[2][2]        = 0.9;
  Point3<3> reference(10, 5, linear(1, 2));
  reference.deform(0.5 * (F0 + unit_symmetric_tensor<3>()));
  reference.deform(F0);
  ASSERT_GT(reference.alpha(), 0);

  const Tensor<2, 3> Q = test::rotation(0.7, 2);
  Point3<3>          rotated(10, 5, linear(1, 2));
  rotated.deform(0.5 * (F0 + unit_symmetric_tensor<3>()));
  rotated.deform(F0);
  rotated.deform(Q * F0);
  const Tensor<2, 3> expected =
    Q * Tensor<2, 3>(reference.stress) * transpose(Q);
  EXPECT_LT((Tensor<2, 3>(rotated.stress) - expected).norm(),
            1e-12 * expected.norm());
  EXPECT_NEAR(rotated.alpha(), reference.alpha(), 1e-14);
}

// Simple shear to gamma = 10 in 2000 steps, perfectly plastic: finite,
// on the yield surface at the end, J = 1 kept by the stress (no pressure
// from an isochoric motion beyond round-off).
TEST(J2Plasticity, SimpleShearToGammaTen)
{
  Point3<3>    p(10, 5, linear(1, 0));
  Tensor<2, 3> F = unit_symmetric_tensor<3>();
  for (unsigned int s = 1; s <= 2000; ++s)
    {
      F[0][1] = 10. * s / 2000;
      p.deform(F);
    }
  const SymmetricTensor<2, 3> tau = p.kirchhoff(F);
  ASSERT_TRUE(test::all_finite(tau));
  EXPECT_NEAR(von_mises(tau), 1., 1e-10);
  EXPECT_LT(std::abs(trace(tau)), 1e-9);
  EXPECT_GT(p.alpha(), 5.); // about gamma / sqrt(3)
}

// Power-law hardening from alpha = 0, where the slope is infinite: the
// bracketed Newton solve lands on sigma_y0 + B alpha^n.
TEST(J2Plasticity, PowerLawReturnOnTheSurface)
{
  IsotropicHardening h;
  h.yield_stress = 1;
  h.coefficient  = 3;
  h.exponent     = 0.3;
  Point3<3> p(10, 5, h);
  p.deform(stretch_x<3>(0.4));
  const double q = von_mises(p.kirchhoff(stretch_x<3>(0.4)));
  ASSERT_GT(p.alpha(), 0);
  EXPECT_NEAR(q, 1 + 3 * std::pow(p.alpha(), 0.3), 1e-12);
}

// Energy balance on uniaxial loading and unloading: the stress work
// sum tau_11 d eps_11 (trapezoidal) equals the stored elastic energy plus
// the plastic work to O(d eps).
TEST(J2Plasticity, StressWorkIsStoredPlusPlastic)
{
  Point3<3>          p(10, 5, linear(1, 2));
  double             work = 0, previous_tau = 0, previous_eps = 0;
  const unsigned int n = 4000;
  for (unsigned int s = 1; s <= n; ++s)
    {
      // Up to 0.5, then back to 0.2.
      const double eps =
        s <= n / 2 ? 0.5 * s / (n / 2) : 0.5 - 0.3 * (s - n / 2) / (n / 2);
      const Tensor<2, 3> F = stretch_x<3>(eps);
      p.deform(F);
      const double tau = p.kirchhoff(F)[0][0];
      work += 0.5 * (tau + previous_tau) * (eps - previous_eps);
      previous_tau = tau;
      previous_eps = eps;
    }
  const Tensor<2, 3> F = stretch_x<3>(0.2);
  const double       stored =
    p.model.strain_energy_density(F, p.stress, make_array_view(p.internal));
  EXPECT_GT(p.plastic_work(), 0.25); // about the integral of sigma_y over alpha
  EXPECT_NEAR(stored + p.plastic_work(), work, 1e-3 * work);
}
