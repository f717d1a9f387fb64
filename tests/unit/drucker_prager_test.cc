// Drucker-Prager without a grid: on the cone after every return with
// non-negative dissipation, the apex return, and the dilatancy of the
// non-associative flow (plastic volume change sqrt(2) eta_bar times the
// deviatoric plastic strain; none with psi = 0), simple shear to gamma = 10.
#include <dealmpm/materials/drucker_prager.h>

#include <gtest/gtest.h>

#include <cmath>

#include "material_point.h"

using namespace dealmpm;

namespace
{
  using SoilPoint = test::MaterialPoint<3, DruckerPrager<3>>;

  /** K = 10, G = 5. */
  const LameParameters soil_lame = {10. - 10. / 3., 5.};

  DruckerPragerCone
  cone(const double phi_degrees,
       const double psi_degrees,
       const double cohesion)
  {
    return DruckerPragerCone::matched("plane strain",
                                      phi_degrees * M_PI / 180.,
                                      psi_degrees * M_PI / 180.,
                                      cohesion);
  }

  /** sqrt(J2) + eta p - xi c of a Kirchhoff stress. */
  double
  yield_function(const SymmetricTensor<2, 3> &tau, const DruckerPragerCone &c)
  {
    return std::sqrt(0.5) * deviator(tau).norm() + c.eta * trace(tau) / 3. -
           c.xi * c.cohesion;
  }

  Tensor<2, 3>
  diagonal(const double a, const double b, const double c)
  {
    Tensor<2, 3> F;
    F[0][0] = std::exp(a);
    F[1][1] = std::exp(b);
    F[2][2] = std::exp(c);
    return F;
  }
} // namespace

// Along a path of compression, shear and some extension, every return lands
// on the cone (or inside it at the apex) and the plastic work never
// decreases.
TEST(DruckerPrager, OnTheConeAfterEveryReturn)
{
  const DruckerPragerCone c = cone(30, 10, 0.05);
  SoilPoint               p(soil_lame, c);
  double                  work          = 0;
  unsigned int            plastic_steps = 0;
  for (unsigned int s = 1; s <= 300; ++s)
    {
      const double t = 0.01 * s;
      Tensor<2, 3> F =
        diagonal(-0.05 * std::sin(t), 0.02 * std::sin(2 * t), -0.01 * t);
      F[0][1]             = 0.3 * std::sin(1.3 * t);
      F[1][2]             = 0.1 * std::cos(t) - 0.1;
      const double before = p.model.plastic_strain(p.state());
      p.deform(F);
      EXPECT_LE(yield_function(p.kirchhoff(F), c), 1e-12) << "step " << s;
      EXPECT_GE(p.model.dissipated_energy_density(p.state()), work - 1e-15);
      work = p.model.dissipated_energy_density(p.state());
      plastic_steps += p.model.plastic_strain(p.state()) > before;
    }
  EXPECT_GT(plastic_steps, 50u);
}

// Stretched in every direction, a cohesionless soil returns to the apex:
// no stress at all; with cohesion, the tip's mean stress xi c / eta.
TEST(DruckerPrager, ApexReturn)
{
  const Tensor<2, 3> F = diagonal(0.01, 0.02, 0.005);
  SoilPoint          loose(soil_lame, cone(30, 0, 0));
  loose.deform(F);
  EXPECT_LT(loose.kirchhoff(F).norm(), 1e-14);

  const DruckerPragerCone c = cone(30, 0, 0.01);
  SoilPoint               cohesive(soil_lame, c);
  cohesive.deform(F);
  const SymmetricTensor<2, 3> tau = cohesive.kirchhoff(F);
  EXPECT_LT(deviator(tau).norm(), 1e-14);
  EXPECT_NEAR(trace(tau) / 3., c.xi * c.cohesion / c.eta, 1e-14);
  EXPECT_GT(cohesive.model.plastic_strain(cohesive.state()), 0);
}

// One plastic step from rest under compression and shear: the plastic
// strain d eps_p = eps_trial - eps_e (eps_e from the stress) has a
// volumetric part sqrt(2) eta_bar |dev d eps_p| (dilatancy), none with
// psi = 0, and the stress is on the cone.
TEST(DruckerPrager, Dilatancy)
{
  const double       K = 10, G = 5;
  const double       trial[3] = {-0.02, 0.005, 0.005};
  const Tensor<2, 3> F        = diagonal(trial[0], trial[1], trial[2]);
  for (const double psi : {0., 10., 30.})
    {
      const DruckerPragerCone c = cone(30, psi, 0);
      SoilPoint               p(soil_lame, c);
      p.deform(F);
      const SymmetricTensor<2, 3> tau = p.kirchhoff(F);
      EXPECT_NEAR(yield_function(tau, c), 0, 1e-14);
      double       volumetric = 0, deviatoric = 0;
      const double mean = trace(tau) / 3.;
      double       plastic[3];
      for (unsigned int a = 0; a < 3; ++a)
        {
          const double elastic =
            mean / (3. * K) + (tau[a][a] - mean) / (2. * G);
          plastic[a] = trial[a] - elastic;
          volumetric += plastic[a];
        }
      for (unsigned int a = 0; a < 3; ++a)
        deviatoric += std::pow(plastic[a] - volumetric / 3., 2);
      ASSERT_GT(deviatoric, 1e-8) << "psi " << psi << ": no plastic flow";
      EXPECT_NEAR(volumetric,
                  std::sqrt(2.) * c.eta_bar * std::sqrt(deviatoric),
                  1e-12)
        << "psi " << psi;
    }
}

// After a plastic pre-strain, a rigid rotation Q F gives Q sigma Q^T and
// leaves the plastic strain alone (the shared Hencky frame, here with a
// pressure-dependent return).
TEST(DruckerPrager, ObjectiveUnderRigidRotation)
{
  Tensor<2, 3> F0           = diagonal(-0.03, 0.01, 0.0);
  F0[0][1]                  = 0.02;
  const DruckerPragerCone c = cone(30, 10, 0.01);
  SoilPoint               reference(soil_lame, c), rotated(soil_lame, c);
  EXPECT_LT(
    test::rotation_error(reference, rotated, F0, test::rotation(1.1, 1)),
    1e-12);
  ASSERT_GT(reference.model.plastic_strain(reference.state()), 0);
  EXPECT_NEAR(rotated.model.plastic_strain(rotated.state()),
              reference.model.plastic_strain(reference.state()),
              1e-15);
}

// Simple shear to gamma = 10 of a confined soil (isotropic log strain
// -0.01), psi = 0: finite, on the cone at the end, and no plastic volume
// change, so the mean stress stays K times the confining volume strain.
TEST(DruckerPrager, SimpleShearToGammaTen)
{
  const DruckerPragerCone c = cone(30, 0, 0);
  SoilPoint               p(soil_lame, c);
  const Tensor<2, 3>      F = test::confined_simple_shear(p, -0.01, 10., 2000);
  const SymmetricTensor<2, 3> tau = p.kirchhoff(F);
  ASSERT_TRUE(test::all_finite(tau));
  EXPECT_NEAR(yield_function(tau, c), 0, 1e-12);
  EXPECT_NEAR(trace(tau) / 3., 10. * -0.03, 1e-9); // 2000 returns of round-off
  EXPECT_GT(p.model.plastic_strain(p.state()), 5.);
}
