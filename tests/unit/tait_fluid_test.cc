// The Tait fluid without a grid: pressure from J, its wave speed
// sqrt(dp/drho), the viscous stress of a simple shear, the stored energy as
// the work of the pressure, and the tension cut-off.
#include <dealmpm/materials/tait_fluid.h>

#include <gtest/gtest.h>

#include <cmath>

#include "material_point.h"

using namespace dealmpm;

namespace
{
  using Water = test::MaterialPoint<2, TaitFluid<2>>;

  TaitParameters
  water(const bool cut_off)
  {
    TaitParameters t;
    t.sound_speed     = 20;
    t.exponent        = 7;
    t.viscosity       = 0.5;
    t.tension_cut_off = cut_off;
    return t;
  }

  Tensor<2, 2>
  compressed(const double J)
  {
    Tensor<2, 2> F;
    F[0][0] = J;
    F[1][1] = 1;
    return F;
  }
} // namespace

// At rest: sigma = -p I, p = rho0 c0^2 / gamma (J^-gamma - 1), sigma_zz too.
TEST(TaitFluid, PressureFromJ)
{
  Water p(water(true));
  p.model.density = 1000;
  p.deform(compressed(0.99));
  const double expected = 1000. * 400. / 7. * (std::pow(0.99, -7.) - 1.);
  EXPECT_NEAR(-p.stress[0][0], expected, 1e-9 * expected);
  EXPECT_NEAR(-p.stress[1][1], expected, 1e-9 * expected);
  EXPECT_EQ(p.stress[0][1], 0);
  EXPECT_NEAR(-p.model.out_of_plane_stress(compressed(0.99),
                                           p.stress,
                                           p.state()),
              expected,
              1e-9 * expected);
}

// The wave speed is sqrt(dp / drho), rho = rho0 / J (central difference).
TEST(TaitFluid, WaveSpeedIsSqrtDpDrho)
{
  Water p(water(false));
  p.model.density = 1000;
  for (const double J : {1.0, 0.98, 0.95})
    {
      const double dJ   = 1e-6;
      const double dp   = p.model.pressure(J - dJ) - p.model.pressure(J + dJ);
      const double drho = 1000. / (J - dJ) - 1000. / (J + dJ);
      const double c_fd = std::sqrt(dp / drho);
      EXPECT_NEAR(p.model.wave_speed(compressed(J)), c_fd, 1e-6 * c_fd)
        << "J " << J;
    }
  EXPECT_DOUBLE_EQ(p.model.wave_speed(compressed(1)), 20);
}

// Simple shear at rate 3/s at J = 1: sigma_xy = mu * 3, no normal stress;
// the viscous work grows by dt 2 mu D : D = 9 mu dt (D : D = 9 / 2).
TEST(TaitFluid, ViscousShear)
{
  Water p(water(true));
  p.model.density = 1000;
  Tensor<2, 2> L;
  L[0][1] = 3;
  p.model.update_stress(
    L, unit_symmetric_tensor<2>(), 0.01, p.stress, make_array_view(p.internal));
  EXPECT_NEAR(p.stress[0][1], 1.5, 1e-14);
  EXPECT_NEAR(p.stress[0][0], 0, 1e-14);
  EXPECT_NEAR(p.model.dissipated_energy_density(p.state()),
              0.01 * 2 * 0.5 * 2 * 1.5 * 1.5,
              1e-14);
}

// The stored energy is minus the work of the pressure from J = 1
// (trapezoidal integral), and with the cut-off a stretched fluid has no
// pressure and no energy.
TEST(TaitFluid, StoredEnergyAndCutOff)
{
  Water p(water(false));
  p.model.density         = 1000;
  double             work = 0;
  const unsigned int n    = 20000;
  for (unsigned int i = 0; i < n; ++i)
    {
      const double a = 1. - 0.03 * i / n, b = 1. - 0.03 * (i + 1) / n;
      work += 0.5 * (p.model.pressure(a) + p.model.pressure(b)) * (a - b);
    }
  const double stored =
    p.model.strain_energy_density(compressed(0.97), p.stress, p.state());
  EXPECT_NEAR(stored, work, 1e-6 * work);

  Water cut(water(true));
  cut.model.density = 1000;
  cut.deform(compressed(1.01));
  EXPECT_EQ(cut.stress[0][0], 0);
  EXPECT_EQ(cut.model.strain_energy_density(compressed(1.01),
                                            cut.stress,
                                            cut.state()),
            0);
  EXPECT_LT(p.model.pressure(1.01), 0);
}
