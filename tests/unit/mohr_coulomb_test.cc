// Mohr-Coulomb without a grid: on the surface after every return (3D and
// plane strain) with non-decreasing plastic work; the triaxial compression
// and extension strengths tau_1 - tau_3 = 2 c cos(phi) - (tau_1 + tau_3)
// sin(phi) (tension positive) reached on the edge returns; the apex; the
// tension cut-off; objectivity after a plastic pre-strain; simple shear to
// gamma = 10.
#include <dealmpm/materials/mohr_coulomb.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "material_point.h"

using namespace dealmpm;

namespace
{
  /** K = 10, G = 5. */
  const LameParameters rock_lame = {10. - 10. / 3., 5.};

  MohrCoulombParameters
  rock(const double phi_degrees,
       const double psi_degrees,
       const double cohesion)
  {
    MohrCoulombParameters mc;
    mc.friction_angle = phi_degrees * M_PI / 180.;
    mc.dilation_angle = psi_degrees * M_PI / 180.;
    mc.cohesion       = cohesion;
    return mc;
  }

  /** Principal stresses, largest first. */
  std::array<double, 3>
  principal(const SymmetricTensor<2, 3> &tau)
  {
    auto values = eigenvalues(tau);
    std::sort(values.begin(), values.end(), std::greater<double>());
    return {{values[0], values[1], values[2]}};
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

  template <int dim>
  void
  check_on_the_surface_after_every_return()
  {
    const MohrCoulombParameters                mc = rock(30, 10, 0.05);
    test::MaterialPoint<dim, MohrCoulomb<dim>> p(rock_lame, mc);
    double                                     work          = 0;
    unsigned int                               plastic_steps = 0;
    for (unsigned int s = 1; s <= 300; ++s)
      {
        const Tensor<2, dim> F = test::wandering_deformation<dim>(0.01 * s);
        const double         before = p.model.plastic_strain(p.state());
        p.deform(F);
        EXPECT_LE(p.model.yield_function(principal(p.kirchhoff(F))), 1e-12)
          << dim << "D, step " << s;
        EXPECT_GE(p.model.dissipated_energy_density(p.state()), work - 1e-15);
        work = p.model.dissipated_energy_density(p.state());
        plastic_steps += p.model.plastic_strain(p.state()) > before;
      }
    EXPECT_GT(plastic_steps, 50u) << dim << "D";
  }

  /** Load a sample under isotropic compression (log strain -0.01) by an
   * isochoric axial log strain (lateral -axial/2), and return the
   * principal stresses. */
  std::array<double, 3>
  triaxial(const MohrCoulombParameters &mc, const double axial)
  {
    test::MaterialPoint<3, MohrCoulomb<3>> p(rock_lame, mc);
    for (unsigned int s = 1; s <= 50; ++s)
      {
        const double e = axial * s / 50.;
        p.deform(diagonal(-0.01 - e / 2, -0.01 - e / 2, -0.01 + e));
      }
    const Tensor<2, 3> F =
      diagonal(-0.01 - axial / 2, -0.01 - axial / 2, -0.01 + axial);
    return principal(p.kirchhoff(F));
  }
} // namespace

TEST(MohrCoulomb, OnTheSurfaceAfterEveryReturn)
{
  check_on_the_surface_after_every_return<3>();
  check_on_the_surface_after_every_return<2>();
}

// Triaxial compression (the axial stress the most compressive, the two
// lateral ones equal: the edge tau_1 = tau_2) and extension (the axial
// stress the least compressive: tau_2 = tau_3) reach the Mohr-Coulomb
// strength; the main plane alone cannot hold those states.
TEST(MohrCoulomb, TriaxialCompressionAndExtensionStrengths)
{
  for (const double psi : {0., 15., 30.})
    {
      const MohrCoulombParameters mc = rock(30, psi, 0.02);
      const MohrCoulomb<3>        model(rock_lame, mc);
      const double                s = std::sin(mc.friction_angle);
      const double cc = 2 * mc.cohesion * std::cos(mc.friction_angle);

      const auto compression = triaxial(mc, -0.05);
      EXPECT_NEAR(compression[0], compression[1], 1e-12) << "psi " << psi;
      EXPECT_GT(compression[1] - compression[2], 0.01);
      EXPECT_NEAR(compression[0] - compression[2],
                  cc - (compression[0] + compression[2]) * s,
                  1e-12)
        << "psi " << psi;

      const auto extension = triaxial(mc, 0.05);
      EXPECT_NEAR(extension[1], extension[2], 1e-12) << "psi " << psi;
      EXPECT_GT(extension[0] - extension[1], 0.01);
      EXPECT_NEAR(extension[0] - extension[2],
                  cc - (extension[0] + extension[2]) * s,
                  1e-12)
        << "psi " << psi;
      EXPECT_NEAR(model.yield_function(extension), 0, 1e-12);
    }
}

// Stretched in every direction the stress goes to the apex c cot(phi):
// no stress at all without cohesion.
TEST(MohrCoulomb, ApexReturn)
{
  const Tensor<2, 3>                     F = diagonal(0.01, 0.02, 0.005);
  test::MaterialPoint<3, MohrCoulomb<3>> loose(rock_lame, rock(30, 0, 0));
  loose.deform(F);
  EXPECT_LT(loose.kirchhoff(F).norm(), 1e-14);

  const MohrCoulombParameters            mc = rock(30, 10, 0.01);
  test::MaterialPoint<3, MohrCoulomb<3>> cohesive(rock_lame, mc);
  cohesive.deform(F);
  for (const double tau : principal(cohesive.kirchhoff(F)))
    EXPECT_NEAR(tau, mc.cohesion / std::tan(mc.friction_angle), 1e-14);
  EXPECT_GT(cohesive.model.plastic_strain(cohesive.state()), 0);
}

// With a tension cut-off T below c cot(phi), no principal stress exceeds T
// and the Mohr-Coulomb surface still holds: one principal stress on the
// cut-off under a uniaxial pull, after a Mohr-Coulomb return under a
// biaxial one, all three under an equal stretch.
TEST(MohrCoulomb, TensionCutOff)
{
  MohrCoulombParameters mc = rock(30, 0, 0.1);
  mc.tension_cut_off       = 0.02;
  const MohrCoulomb<3> model(rock_lame, mc);
  const Tensor<2, 3>   stretches[3] = {diagonal(0.01, -0.01, -0.01),
                                       diagonal(0.01, 0.01, -0.01),
                                       diagonal(0.01, 0.01, 0.01)};
  for (unsigned int k = 0; k < 3; ++k)
    {
      test::MaterialPoint<3, MohrCoulomb<3>> p(rock_lame, mc);
      p.deform(stretches[k]);
      const auto tau = principal(p.kirchhoff(stretches[k]));
      EXPECT_NEAR(tau[0], mc.tension_cut_off, 1e-14) << "case " << k;
      EXPECT_LE(model.yield_function(tau), 1e-14) << "case " << k;
      EXPECT_GT(p.model.plastic_strain(p.state()), 0) << "case " << k;
    }
  {
    test::MaterialPoint<3, MohrCoulomb<3>> p(rock_lame, mc);
    p.deform(stretches[0]);
    EXPECT_LT(principal(p.kirchhoff(stretches[0]))[1], -0.1);
  }
  {
    test::MaterialPoint<3, MohrCoulomb<3>> p(rock_lame, mc);
    p.deform(stretches[2]);
    for (const double tau : principal(p.kirchhoff(stretches[2])))
      EXPECT_NEAR(tau, mc.tension_cut_off, 1e-14);
  }
}

// After a plastic pre-strain, a rigid rotation Q F gives Q sigma Q^T and
// leaves the plastic strain alone.
TEST(MohrCoulomb, ObjectiveUnderRigidRotation)
{
  Tensor<2, 3> F0                           = diagonal(-0.03, 0.01, 0.0);
  F0[0][1]                                  = 0.02;
  const MohrCoulombParameters            mc = rock(30, 10, 0.01);
  test::MaterialPoint<3, MohrCoulomb<3>> reference(rock_lame, mc),
    rotated(rock_lame, mc);
  EXPECT_LT(
    test::rotation_error(reference, rotated, F0, test::rotation(1.1, 1)),
    1e-12);
  ASSERT_GT(reference.model.plastic_strain(reference.state()), 0);
  EXPECT_NEAR(rotated.model.plastic_strain(rotated.state()),
              reference.model.plastic_strain(reference.state()),
              1e-15);
}

// Simple shear to gamma = 10 of a confined sample (isotropic log strain
// -0.01), psi = 0: finite, on the surface at the end, and no plastic volume
// change, so the mean stress stays K times the confining volume strain.
TEST(MohrCoulomb, SimpleShearToGammaTen)
{
  test::MaterialPoint<3, MohrCoulomb<3>> p(rock_lame, rock(30, 0, 0.01));
  const Tensor<2, 3> F = test::confined_simple_shear(p, -0.01, 10., 2000);
  const SymmetricTensor<2, 3> tau = p.kirchhoff(F);
  ASSERT_TRUE(test::all_finite(tau));
  EXPECT_NEAR(p.model.yield_function(principal(tau)), 0, 1e-12);
  EXPECT_NEAR(trace(tau) / 3., 10. * -0.03, 1e-9); // 2000 returns of round-off
  EXPECT_GT(p.model.plastic_strain(p.state()), 5.);
}

// Strain softening in triaxial compression (confined at log strain -0.01,
// then an isochoric axial shortening in small steps): every plastic step
// ends on the surface of the strength its plastic strain started from,
// the plastic work grows, the deviator peaks and falls, and past the
// softening strain the stress stays on the residual surface.
TEST(MohrCoulomb, SofteningFallsToTheResidualStrength)
{
  MohrCoulombParameters mc   = rock(30, 10, 0.02);
  mc.softening_strain        = 0.05;
  mc.residual_cohesion       = 0.005;
  mc.residual_friction_angle = 20 * M_PI / 180.;
  mc.residual_dilation_angle = 0;
  test::MaterialPoint<3, MohrCoulomb<3>> p(rock_lame, mc);
  double                                 work = 0, peak = 0, last = 0;
  unsigned int                           plastic_steps = 0;
  for (unsigned int s = 1; s <= 400; ++s)
    {
      const double       e = -0.2 * s / 400.;
      const Tensor<2, 3> F = diagonal(-0.01 - e / 2, -0.01 - e / 2, -0.01 + e);
      const double       before = p.model.plastic_strain(p.state());
      p.deform(F);
      const auto tau = principal(p.kirchhoff(F));
      if (p.model.plastic_strain(p.state()) > before)
        {
          ++plastic_steps;
          EXPECT_NEAR(p.model.yield_function(tau, before), 0, 1e-12)
            << "step " << s;
        }
      EXPECT_GE(p.model.dissipated_energy_density(p.state()), work - 1e-15);
      work = p.model.dissipated_energy_density(p.state());
      last = tau[0] - tau[2];
      peak = std::max(peak, last);
    }
  const auto tau =
    principal(p.kirchhoff(diagonal(-0.01 + 0.1, -0.01 + 0.1, -0.01 - 0.2)));
  EXPECT_GT(plastic_steps, 300u);
  EXPECT_GT(p.model.plastic_strain(p.state()), 2 * mc.softening_strain);
  // The residual surface: tau_1 - tau_3 = 2 c_r cos(phi_r) - (tau_1 +
  // tau_3) sin(phi_r).
  const double sin_r = std::sin(mc.residual_friction_angle);
  EXPECT_NEAR(tau[0] - tau[2],
              2 * mc.residual_cohesion * std::cos(mc.residual_friction_angle) -
                (tau[0] + tau[2]) * sin_r,
              1e-12);
  EXPECT_LT(last, 0.8 * peak);
  std::cout << "softening: peak deviator " << peak << ", residual " << last
            << std::endl;
}

// A regularisation length scales the softening strain by length / h: on
// cells of edge h the strength at plastic strain e is the unregularised
// model's at e h / length, so that the band's displacement (about e h)
// at each strength is the same on every grid. Without a cell size it
// does not need one, and a model without the length ignores one.
TEST(MohrCoulomb, RegularisationScalesTheSofteningWithTheCell)
{
  MohrCoulombParameters mc   = rock(30, 10, 0.02);
  mc.softening_strain        = 0.05;
  mc.residual_cohesion       = 0.005;
  mc.residual_friction_angle = 20 * M_PI / 180.;
  const MohrCoulomb<3> plain(rock_lame, mc);
  mc.regularisation_length = 0.01;
  const std::array<double, 3> tau{{-0.01, -0.02, -0.06}};
  for (const double h : {0.005, 0.01, 0.04})
    {
      MohrCoulomb<3> regularised(rock_lame, mc);
      ASSERT_TRUE(regularised.needs_cell_size());
      regularised.set_cell_size(h);
      EXPECT_DOUBLE_EQ(regularised.softening_strain(), 0.05 * 0.01 / h);
      for (const double e : {0., 0.01, 0.03, 0.1, 1.})
        EXPECT_NEAR(regularised.yield_function(tau, e),
                    plain.yield_function(tau, e * h / 0.01),
                    1e-15)
          << "h = " << h << ", plastic strain " << e;
    }
  MohrCoulomb<3> unscaled(rock_lame, rock(30, 10, 0.02));
  EXPECT_FALSE(unscaled.needs_cell_size());
  EXPECT_FALSE(plain.needs_cell_size());
}
