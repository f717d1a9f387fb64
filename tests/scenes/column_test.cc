// Elastic column settling under gravity between slip walls (1D compression,
// nu = 0): once local damping has removed the waves, the vertical stress at
// reference height Y is -rho g (H - Y), at the base -rho g H. The column is
// stiff enough (top settles by 8 mm, a particle spacing is 125 mm) that no
// particle crosses a cell face: linear MPM's cell-crossing noise, which makes
// particle stresses of a softer column alternate around the right cell mean,
// is the business of the GIMP/CPDI/B-spline kernels.
#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const char *column = R"(
set Dimension = 2
set Effects = gravity, local damping
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 5
  set Cells = 4, 20
  set Boundary conditions = 0: slip, 1: slip, 2: slip
end
subsection Material 1
  set Density = 1000
  subsection linear elastic
    set Young's modulus = 1e7
    set Poisson's ratio = 0
  end
end
subsection Body 1
  set Lower corner = 0, 0
  set Upper corner = 1, 4
  set Particles per cell = 2
end
subsection Gravity
  set Acceleration = 0, -9.81
end
subsection Local damping
  set Coefficient = 0.15
end
subsection Time
  set CFL number = 0.5
end
)";
}

TEST(Column, SettledBaseStressIsRhoGH)
{
  auto         simulation = test::make_simulation<2>(column);
  const double rho = 1000, g = 9.81, H = 4, h = 0.25;
  while (simulation->time() < 3.)
    simulation->advance(simulation->time_step());

  const auto       &particles  = simulation->particle_set();
  const CoreFields &f          = particles.fields;
  double            base_error = 0, max_error = 0, base_count = 0;
  for (const auto &p : particles.handler)
    {
      const auto   props = p.get_properties();
      const double Y     = p.get_location()[1] - props[f.displacement + 1];
      const double exact = -rho * g * (H - Y);
      const double sigma = read_symmetric<2>(&props[f.stress])[1][1];
      const double error = std::abs(sigma - exact) / (rho * g * H);
      max_error          = std::max(max_error, error);
      if (Y < h)
        {
          base_error += error;
          base_count += 1;
        }
    }
  base_error /= base_count;
  const Statistics s = simulation->statistics();
  std::cout << "column: mean base stress error / (rho g H) = " << base_error
            << ", max over the column = " << max_error
            << ", kinetic energy / strain energy = "
            << s.kinetic_energy / s.strain_energy << std::endl;
  EXPECT_LT(s.kinetic_energy, 1e-3 * s.strain_energy); // settled
  EXPECT_LT(base_error, 0.02);
  EXPECT_LT(max_error, 0.05);
}
