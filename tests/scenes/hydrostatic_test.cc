// A Tait water column at rest (0.3 m deep in a walled box, gravity, local
// damping to settle): the pressure is hydrostatic, rho g depth, within 3 %
// of the pressure at the bottom averaged in bands of depth (0.7 % seen; the
// MPM pressure carries a cell-scale ripple); F of every
// particle is isotropic, J^(1/2) I (the fluid's reset), and the density
// stays within 1 % of rho0 (c0 = 20 m/s, 12 times the wave speed sqrt(g H)
// of the column: weakly compressible).
#include <gtest/gtest.h>

#include <array>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const char *water_column = R"(
set Effects = gravity, local damping
subsection Grid
  set Type                = rectangle
  set Lower corner        = 0, 0
  set Upper corner        = 0.2, 0.4
  set Cells               = 10, 20
  set Boundary conditions = 0: slip, 1: slip, 2: slip
end
subsection Material 1
  set Model   = Tait fluid
  set Density = 1000
  subsection Tait fluid
    set Sound speed = 20
    set Viscosity   = 1e-3
  end
end
subsection Body 1
  set Shape              = box
  set Lower corner       = 0, 0
  set Upper corner       = 0.2, 0.3
  set Particles per cell = 2
  set Material           = 1
end
subsection Gravity
  set Acceleration = 0, -9.81
end
subsection Local damping
  set Coefficient = 0.3
end
)";
} // namespace

TEST(Hydrostatic, TaitColumnAtRest)
{
  auto simulation = test::make_simulation<2>(water_column);
  while (simulation->time() < 1.0)
    simulation->advance(simulation->time_step());

  const ParticleSet<2> &particles = simulation->particle_set();
  const CoreFields     &f         = particles.fields;
  // Mean pressure in six bands of depth (0.05 m each) against rho g depth.
  std::array<double, 6> sum{}, count{};
  double                max_anisotropy = 0, max_density_change = 0;
  for (const auto &p : particles.handler)
    {
      const auto         props = p.get_properties();
      const Tensor<2, 2> F     = read_tensor<2>(&props[f.deformation_gradient]);
      max_anisotropy           = std::max({max_anisotropy,
                                           std::abs(F[0][1]),
                                           std::abs(F[1][0]),
                                           std::abs(F[0][0] - F[1][1])});
      max_density_change =
        std::max(max_density_change, std::abs(1. / determinant(F) - 1.));
      const SymmetricTensor<2, 2> s     = read_symmetric<2>(&props[f.stress]);
      const double                depth = 0.3 - p.get_location()[1];
      const unsigned int          band =
        std::min(5u, static_cast<unsigned int>(std::max(0., depth) / 0.05));
      sum[band] -= 0.5 * (s[0][0] + s[1][1]);
      count[band] += 1;
    }
  const double bottom = 1000. * 9.81 * 0.3;
  for (unsigned int band = 0; band < 6; ++band)
    {
      ASSERT_GT(count[band], 0);
      const double expected = 1000. * 9.81 * 0.05 * (band + 0.5);
      std::cout << "depth " << 0.05 * (band + 0.5)
                << " m: p = " << sum[band] / count[band]
                << " Pa, rho g d = " << expected << " Pa" << std::endl;
      EXPECT_NEAR(sum[band] / count[band], expected, 0.03 * bottom)
        << "band " << band;
    }
  EXPECT_EQ(max_anisotropy, 0);
  EXPECT_LT(max_density_change, 0.01);
}
