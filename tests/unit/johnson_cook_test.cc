// Johnson-Cook without a grid: the quasi-static curve, the rate factor, the
// adiabatic temperature rise and thermal softening, each against the flow
// stress formula (A + B alpha^n)(1 + C ln(rate / rate_0))(1 - T*^m), and
// simple shear to gamma = 10 at 1e4 /s.
#include <dealmpm/materials/johnson_cook.h>

#include <gtest/gtest.h>

#include <cmath>

#include "material_point.h"

using namespace dealmpm;

namespace
{
  const LameParameters copper_lame = {124e9 * 0.34 / (1.34 * (1 - 0.68)),
                                      124e9 / 2.68};

  using CopperPoint = test::MaterialPoint<3, JohnsonCook<3>>;

  double
  alpha(const CopperPoint &p)
  {
    return JohnsonCook<3>::plastic_strain(p.state());
  }

  double
  temperature(const CopperPoint &p)
  {
    return p.model.temperature(p.state());
  }

  /** Copper's constants with or without heating. */
  JohnsonCookParameters
  copper(const double taylor_quinney)
  {
    JohnsonCookParameters jc;
    jc.taylor_quinney = taylor_quinney;
    return jc;
  }
} // namespace

// Loaded slowly (plastic rate below the reference rate) and without heating,
// the flow stress is A + B alpha^n after every return, up to 20 % strain.
TEST(JohnsonCook, QuasiStaticCurve)
{
  CopperPoint p(copper_lame, copper(0));
  p.model.density = 8960;
  for (unsigned int s = 1; s <= 200; ++s)
    {
      const double eps = 0.2 * s / 200;
      p.deform(test::stretch_x<3>(eps), /*dt=*/10.);
      if (alpha(p) == 0)
        continue;
      const double q = test::von_mises(p.kirchhoff(test::stretch_x<3>(eps)));
      ASSERT_NEAR(q, 90e6 + 292e6 * std::pow(alpha(p), 0.31), 1e-9 * q)
        << "step " << s;
    }
  EXPECT_GT(alpha(p), 0.12); // eps minus the elastic part, times 2/3
  EXPECT_EQ(temperature(p), 298);
}

// One fast step from the virgin state: the return lands on the rate-
// dependent surface at the rate d_gamma / dt it produced, and that stress is
// above the quasi-static one by the factor 1 + C ln(rate).
TEST(JohnsonCook, RateFactor)
{
  const double dt = 1e-6;
  CopperPoint  p(copper_lame, copper(0));
  p.model.density = 8960;
  p.deform(test::stretch_x<3>(0.05), dt);
  const double rate = alpha(p) / dt;
  ASSERT_GT(rate, 1e4);
  const double static_stress = 90e6 + 292e6 * std::pow(alpha(p), 0.31);
  const double q = test::von_mises(p.kirchhoff(test::stretch_x<3>(0.05)));
  EXPECT_NEAR(q, static_stress * (1 + 0.025 * std::log(rate)), 1e-9 * q);
  EXPECT_GT(q, 1.2 * static_stress);
}

// With heating, the temperature rises by chi times the plastic work over
// rho c_p, and the flow stress is softened by 1 - T*^m at the temperature
// each step started from.
TEST(JohnsonCook, AdiabaticHeatingSoftens)
{
  CopperPoint hot(copper_lame, copper(0.9)), cold(copper_lame, copper(0));
  hot.model.density = cold.model.density = 8960;
  double start_temperature               = 298;
  for (unsigned int s = 1; s <= 100; ++s)
    {
      const double eps  = 1.0 * s / 100;
      start_temperature = temperature(hot);
      hot.deform(test::stretch_x<3>(eps), 10.);
      cold.deform(test::stretch_x<3>(eps), 10.);
    }
  const double work = hot.model.dissipated_energy_density(hot.state());
  EXPECT_NEAR(temperature(hot), 298 + 0.9 * work / (8960 * 383), 1e-9);
  EXPECT_GT(temperature(hot), 320);
  const double homologous = (start_temperature - 298) / (1356 - 298);
  const double q = test::von_mises(hot.kirchhoff(test::stretch_x<3>(1.0)));
  EXPECT_NEAR(q,
              (90e6 + 292e6 * std::pow(alpha(hot), 0.31)) *
                (1 - std::pow(homologous, 1.09)),
              1e-9 * q);
  EXPECT_LT(q, test::von_mises(cold.kirchhoff(test::stretch_x<3>(1.0))));
}

// Simple shear to gamma = 10 at a rate of 1e4 /s with adiabatic heating
// (the Taylor bar's regime): finite, isochoric (no pressure beyond
// round-off), hot but below melting, and on the rate- and
// temperature-dependent flow stress of the last step (softening at the
// step's starting temperature).
TEST(JohnsonCook, SimpleShearToGammaTen)
{
  CopperPoint  p(copper_lame, copper(0.9));
  Tensor<2, 3> F        = unit_symmetric_tensor<3>();
  const double dt       = 1e-3 / 2000; // gamma 10 in 1 ms
  p.model.density       = 8960;
  double previous_alpha = 0, previous_T = 0;
  for (unsigned int s = 1; s <= 2000; ++s)
    {
      previous_alpha = alpha(p);
      previous_T     = temperature(p);
      F[0][1]        = 10. * s / 2000;
      p.deform(F, dt);
    }
  const SymmetricTensor<2, 3> tau = p.kirchhoff(F);
  ASSERT_TRUE(test::all_finite(tau));
  EXPECT_LT(std::abs(trace(tau)), 1e-6 * test::von_mises(tau));
  EXPECT_GT(alpha(p), 5.); // about gamma / sqrt(3)
  const double T = temperature(p);
  EXPECT_GT(T, 400.);
  EXPECT_LT(T, 1356.);
  const double rate   = (alpha(p) - previous_alpha) / dt;
  const double T_star = (previous_T - 298.) / (1356. - 298.);
  const double flow   = (90e6 + 292e6 * std::pow(alpha(p), 0.31)) *
                      (1 + 0.025 * std::log(rate / 1.)) *
                      (1 - std::pow(T_star, 1.09));
  EXPECT_NEAR(test::von_mises(tau), flow, 1e-6 * flow);
}

namespace
{
  /** Simple shear to gamma = @p gamma in @p n slow steps (below the
   * reference rate) of a sample with isotropic log pre-strain @p e0,
   * without heating; the damage indicator on. Returns the point and, in
   * @p expected, the sum of d alpha / eps_f(sigma*) with sigma* = p / q(alpha)
   * written out here (p = 3 K e0 stays: J2 flow is isochoric). */
  CopperPoint
  sheared_with_damage(const double e0, const double gamma, double &expected)
  {
    JohnsonCookParameters jc = copper(0);
    jc.damage_indicator      = true;
    CopperPoint p(copper_lame, jc);
    p.model.density = 8960;
    Tensor<2, 3> pre;
    for (unsigned int d = 0; d < 3; ++d)
      pre[d][d] = std::exp(e0);
    const double K =
      copper_lame.lambda + 2. / 3. * copper_lame.mu; // bulk modulus
    expected = 0;
    for (unsigned int s = 1; s <= 400; ++s)
      {
        Tensor<2, 3> shear  = unit_symmetric_tensor<3>();
        shear[0][1]         = gamma * s / 400;
        const double before = alpha(p);
        p.deform(shear * pre, /*dt=*/10.);
        const double a = alpha(p);
        if (a > before)
          {
            const double q = 90e6 + 292e6 * std::pow(a, 0.31);
            expected +=
              (a - before) / (0.54 + 4.89 * std::exp(-3.03 * 3. * K * e0 / q));
          }
      }
    return p;
  }
} // namespace

// Johnson and Cook's (1985) damage: in isochoric shear (sigma* = 0) at low
// rate and room temperature D = alpha / (D1 + D2); under a mean tension,
// the sum of d alpha / eps_f(sigma*), and more of it (the failure strain
// falls with sigma*). Without the indicator the model has no damage field.
TEST(JohnsonCook, DamageIndicator)
{
  double     expected = 0;
  const auto shear    = sheared_with_damage(0, 1., expected);
  ASSERT_GT(alpha(shear), 0.4);
  EXPECT_NEAR(shear.model.damage(shear.state()),
              alpha(shear) / (0.54 + 4.89),
              1e-12);

  const auto pulled = sheared_with_damage(0.001, 1., expected);
  EXPECT_NEAR(pulled.model.damage(pulled.state()), expected, 1e-10 * expected);
  EXPECT_GT(pulled.model.damage(pulled.state()),
            1.05 * shear.model.damage(shear.state()));

  const JohnsonCook<3> plain(copper_lame, copper(0.9));
  for (const auto &field : plain.internal_variables())
    EXPECT_NE(field.name, "damage");
}
