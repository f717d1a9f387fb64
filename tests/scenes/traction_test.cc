// Surface loads (effect 'traction'). A free block under a uniform pressure
// on its surface particles settles at sigma = -p (the mean stress of a
// body is the first moment of its surface loads, exactly -p V for a
// uniform pressure); the load's work is its strain and kinetic energy. A
// spinning block keeps its angular momentum under a follower pressure
// (normal to the deformed faces, no torque) but not under a dead one
// (fixed directions, a torque as soon as it turns). A bar pushed through a
// free grid boundary carries the traction as sigma_xx.
#include <deal.II/base/mpi.h>

#include <dealmpm/base/load_curve.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double p0 = 1e4; // Pa

  /** A 0.4 m block in the middle of a 1 m grid of 40 x 40 cells (2 x 2
   * particles each), E = 1e6, nu = 0.3, rho = 1000 (c_p = 36.7 m/s: a
   * transit takes 0.011 s), under a pressure ramped up over 0.05 s. */
  std::string
  pressed_block(const std::string &extra_effects,
                const bool         follower,
                const std::string &update = "PIC",
                const unsigned int cells  = 40)
  {
    std::ostringstream s;
    s << "set Effects = traction" << extra_effects << "\n"
      << "subsection Traction\n set Bodies = 1\n set Pressure = " << p0
      << "\n set Follower pressure = " << (follower ? "true" : "false")
      << "\n set Load curve = 0: 0, 0.05: 1\nend\n"
      << "subsection Local damping\n set Coefficient = 0.2\nend\n"
      << "subsection MPM\n set Velocity update = " << update << "\nend\n"
      << "subsection Grid\n set Cells = " << cells << ", " << cells << "\nend\n"
      << "subsection Material 1\n set Density = 1000\n"
      << " subsection linear elastic\n  set Young's modulus = 1e6\n"
      << "  set Poisson's ratio = 0.3\n end\nend\n"
      << "subsection Body 1\n set Lower corner = 0.3, 0.3\n"
      << " set Upper corner = 0.7, 0.7\nend\n";
    return s.str();
  }

  /** Volume-weighted mean of the particles' stress (xx, yy, xy). */
  std::array<double, 3>
  mean_stress(Simulation<2> &simulation)
  {
    const CoreFields &f       = simulation.particle_set().fields;
    double            sums[4] = {};
    for (const auto &p : simulation.particle_set().handler)
      {
        const auto   props = p.get_properties();
        const double V =
          props[f.initial_volume] *
          determinant(read_tensor<2>(&props[f.deformation_gradient]));
        const SymmetricTensor<2, 2> s = read_symmetric<2>(&props[f.stress]);
        sums[0] += V * s[0][0];
        sums[1] += V * s[1][1];
        sums[2] += V * s[0][1];
        sums[3] += V;
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 4),
                        MPI_COMM_WORLD,
                        ArrayView<double>(sums, 4));
    return {{sums[0] / sums[3], sums[1] / sums[3], sums[2] / sums[3]}};
  }

  /** Angular momentum about (0.5, 0.5). */
  double
  angular_momentum(Simulation<2> &simulation)
  {
    const CoreFields &f = simulation.particle_set().fields;
    double            L = 0;
    for (const auto &p : simulation.particle_set().handler)
      {
        const auto         props = p.get_properties();
        const Tensor<1, 2> r     = p.get_location() - Point<2>(0.5, 0.5);
        const Tensor<1, 2> v     = read_vector<2>(&props[f.velocity]);
        L += props[f.mass] * (r[0] * v[1] - r[1] * v[0]);
      }
    return Utilities::MPI::sum(L, MPI_COMM_WORLD);
  }

  /** Spin the block rigidly at omega about its centre. */
  void
  spin(Simulation<2> &simulation, const double omega)
  {
    const CoreFields &f = simulation.particle_set().fields;
    for (auto &p : simulation.particle_set().handler)
      {
        const Tensor<1, 2> r = p.get_location() - Point<2>(0.5, 0.5);
        write_vector<2>(&p.get_properties()[f.velocity],
                        Tensor<1, 2>({-omega * r[1], omega * r[0]}));
      }
  }
} // namespace

TEST(Traction, LoadCurveIsPiecewiseLinearAndConstantOutside)
{
  ParameterHandler prm;
  prm.declare_entry("Load curve", "", Patterns::Anything());
  prm.set("Load curve", "0.1: 0, 0.3: 2, 0.4: -1");
  const SceneReader reader(prm, "test.prm");
  const LoadCurve   curve = LoadCurve::read(reader, "Load curve");
  EXPECT_DOUBLE_EQ(curve(0.), 0.);
  EXPECT_DOUBLE_EQ(curve(0.2), 1.);
  EXPECT_NEAR(curve(0.35), 0.5, 1e-14);
  EXPECT_DOUBLE_EQ(curve(7.), -1.);
  EXPECT_DOUBLE_EQ(LoadCurve()(3.), 1.);
  prm.set("Load curve", "0: 1, 0: 2");
  EXPECT_THROW(LoadCurve::read(reader, "Load curve"), std::exception);
}

// The integral from 0 (a base velocity from an acceleration record): by
// hand, the constant before the first point, the trapezoids, the part of
// a segment (quadratic in t) and the constant after the last point.
TEST(Traction, LoadCurveIntegralIsExact)
{
  ParameterHandler prm;
  prm.declare_entry("Load curve", "", Patterns::Anything());
  prm.set("Load curve", "1: 2, 3: 4");
  const SceneReader reader(prm, "test.prm");
  const LoadCurve   curve = LoadCurve::read(reader, "Load curve");
  EXPECT_DOUBLE_EQ(curve.integral(0.), 0.);
  EXPECT_DOUBLE_EQ(curve.integral(-1.), -2.);
  EXPECT_DOUBLE_EQ(curve.integral(1.), 2.);
  EXPECT_DOUBLE_EQ(curve.integral(2.), 4.5); // 2 + int_1^2 (1 + s) ds
  EXPECT_DOUBLE_EQ(curve.integral(3.), 8.);
  EXPECT_DOUBLE_EQ(curve.integral(5.), 16.);
  EXPECT_DOUBLE_EQ(LoadCurve().integral(2.5), 2.5);
}

// The surface particles' faces close around the block: their area vectors
// sum to zero and those facing +x add up to its height.
TEST(Traction, SurfaceFacesCloseAroundTheBody)
{
  auto simulation = test::make_simulation<2>(pressed_block("", false));
  const ParticleSet<2> &particles = simulation->particle_set();
  const unsigned int    area      = particles.layout.offset("surface_area");
  double                sums[3]   = {};
  for (const auto &p : particles.handler)
    {
      const Tensor<1, 2> A = read_vector<2>(&p.get_properties()[area]);
      sums[0] += A[0];
      sums[1] += A[1];
      sums[2] += std::max(A[0], 0.);
    }
  Utilities::MPI::sum(ArrayView<const double>(sums, 3),
                      MPI_COMM_WORLD,
                      ArrayView<double>(sums, 3));
  EXPECT_NEAR(sums[0], 0, 1e-14);
  EXPECT_NEAR(sums[1], 0, 1e-14);
  EXPECT_NEAR(sums[2], 0.4, 1e-13);
}

TEST(Traction, UniformPressureGivesMinusPInTheBlock)
{
  auto simulation =
    test::make_simulation<2>(pressed_block(", local damping", false));
  test::run_to(*simulation, 0.3);
  const auto s = mean_stress(*simulation);
  std::cout << "traction: pressed block mean stress " << s[0] / p0 << ", "
            << s[1] / p0 << ", " << s[2] / p0 << " of p" << std::endl;
  EXPECT_NEAR(s[0], -p0, 0.005 * p0);
  EXPECT_NEAR(s[1], -p0, 0.005 * p0);
  EXPECT_NEAR(s[2], 0, 0.001 * p0);
}

// Without damping the block rings (FLIP keeps its energy); what it holds
// is what the load did, and the closed surface's loads add up to nothing.
TEST(Traction, LoadWorkIsStrainAndKineticEnergy)
{
  auto simulation = test::make_simulation<2>(pressed_block("", false, "FLIP"));
  test::run_to(*simulation, 0.1);
  const Statistics s = simulation->statistics();
  const double     W = simulation->external_work();
  std::cout << "traction: work " << W << " J, energy "
            << s.kinetic_energy + s.strain_energy << " J; momentum "
            << s.momentum[0] << ", " << s.momentum[1] << std::endl;
  EXPECT_GT(W, 0.);
  EXPECT_NEAR(s.momentum[0], 0, 1e-10);
  EXPECT_NEAR(s.momentum[1], 0, 1e-10);
  EXPECT_NEAR(s.kinetic_energy + s.strain_energy, W, 0.02 * W);
}

// A block spinning at 2 rad/s turns 0.5 rad in 0.25 s: a dead load's
// torque changes its angular momentum several times over, a follower
// pressure's does not.
TEST(Traction, FollowerPressureExertsNoTorque)
{
  std::array<double, 2> change;
  for (const bool follower : {true, false})
    {
      // FLIP: PIC would damp the spin.
      auto simulation =
        test::make_simulation<2>(pressed_block("", follower, "FLIP"));
      spin(*simulation, 2);
      const double L0 = angular_momentum(*simulation);
      test::run_to(*simulation, 0.25);
      change[follower ? 0 : 1] =
        std::abs(angular_momentum(*simulation) - L0) / L0;
      if (follower)
        {
          const auto s = mean_stress(*simulation);
          std::cout << "traction: spinning block, follower pressure: mean "
                    << "pressure " << -(s[0] + s[1]) / 2 / p0 << " of p"
                    << std::endl;
          EXPECT_NEAR(-(s[0] + s[1]) / 2, p0, 0.06 * p0);
        }
    }
  std::cout << "traction: spinning block, angular momentum changed by "
            << change[0] << " (follower), " << change[1] << " (dead load)"
            << std::endl;
  // Measured 0.22 against 6.4: the follower's loads have no torque (their
  // moment is exact on the grid), what is left is FLIP's transfer error
  // at the loaded, partly filled surface cells (0.009 without a load).
  EXPECT_LT(change[0], 0.05 * change[1]);
  EXPECT_GT(change[1], 1.);
}

// A bar filling a confined channel (slip walls above and below, fixed at
// x = 0), pushed at x = 1 through the free grid boundary id 1.
TEST(Traction, GridBoundaryTractionIsCarriedAsStress)
{
  auto simulation = test::make_simulation<2>(R"(
set Effects = traction, local damping
subsection Traction
  set Boundary ids = 1
  set Traction     = -1e4; 0
  set Load curve   = 0: 0, 0.1: 1
end
subsection Local damping
  set Coefficient = 0.2
end
subsection MPM
  set Velocity update = PIC
end
subsection Grid
  set Upper corner        = 1, 0.1
  set Cells               = 40, 4
  set Boundary conditions = 0: no-slip, 2: slip, 3: slip
end
subsection Material 1
  set Density = 1000
  subsection linear elastic
    set Young's modulus = 1e6
    set Poisson's ratio = 0.3
  end
end
subsection Body 1
  set Upper corner = 1, 0.1
end
)");
  test::run_to(*simulation, 0.4);
  const auto s = mean_stress(*simulation);
  std::cout << "traction: bar pushed through a grid boundary, sigma_xx "
            << s[0] / p0 << " of the traction" << std::endl;
  EXPECT_NEAR(s[0], -p0, 0.01 * p0);
}
