// Axially vibrating bar, first mode (fixed at x = 0, free at x = L = 25):
// v(x, t) = v0 cos(omega t) sin(beta x), beta = pi / (2 L),
// omega = beta sqrt(E / rho). The free-end particle's velocity over one
// period must follow it, and the error must fall as the grid is refined.
#include <gtest/gtest.h>

#include <cmath>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  // v0 = 0.01 keeps the largest displacement (0.016) below a quarter of the
  // finest particle spacing: no particle crosses a cell face, so this checks
  // the convergence of linear MPM without its cell-crossing error (the
  // kernels of GIMP/CPDI/B-splines address that).
  constexpr double L = 25, E = 100, rho = 1, v0 = 0.01;
  const double     beta = M_PI / (2 * L), omega = beta * std::sqrt(E / rho);

  /** Max over one period of |v_tip - v_exact| / v0 with n cells per unit
   * length. */
  double
  tip_velocity_error(const unsigned int n)
  {
    const std::string scene =
      "set Dimension = 2\n"
      "subsection Grid\n set Lower corner = 0, 0\n set Upper corner = 26, 1\n"
      " set Cells = " +
      std::to_string(26 * n) + ", " + std::to_string(n) +
      "\n set Boundary conditions = 0: no-slip, 2: slip, 3: slip\nend\n"
      "subsection Material 1\n set Density = 1\n subsection linear elastic\n"
      "  set Young's modulus = 100\n  set Poisson's ratio = 0\n end\nend\n"
      "subsection Body 1\n set Lower corner = 0, 0\n set Upper corner = 25, 1\n"
      " set Particles per cell = 2\nend\n";
    auto              simulation = test::make_simulation<2>(scene);
    auto             &particles  = simulation->particle_set();
    const CoreFields &f          = particles.fields;
    for (auto &p : particles.handler)
      p.get_properties()[f.velocity] =
        v0 * std::sin(beta * p.get_location()[0]);

    const double       h         = 1. / n;
    const double       dt        = 0.05 * h / std::sqrt(E / rho);
    const unsigned int n_steps   = std::lround(2 * M_PI / omega / dt);
    double             max_error = 0;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        simulation->advance(dt);
        // The particles of the last column, at their reference position.
        double error = 0, count = 0;
        for (const auto &p : particles.handler)
          {
            const auto   props = p.get_properties();
            const double X     = p.get_location()[0] - props[f.displacement];
            if (X < L - 0.5 * h)
              continue;
            const double exact =
              v0 * std::cos(omega * simulation->time()) * std::sin(beta * X);
            error += std::abs(props[f.velocity] - exact);
            count += 1;
          }
        max_error = std::max(max_error, error / count / v0);
      }
    return max_error;
  }
} // namespace

TEST(VibratingBar, FreeEndFollowsFirstModeAndConverges)
{
  const double coarse = tip_velocity_error(1);
  const double medium = tip_velocity_error(2);
  const double fine   = tip_velocity_error(4);
  std::cout << "vibrating bar: max tip velocity error / v0 at h = 1, 1/2, 1/4: "
            << coarse << ", " << medium << ", " << fine << std::endl;
  EXPECT_LT(fine, medium);
  EXPECT_LT(medium, coarse);
  // With the dispersion error of linear MPM, O(h^2): a few percent at h = 1.
  EXPECT_LT(coarse, 0.05);
  EXPECT_LT(fine, 0.01);
}
