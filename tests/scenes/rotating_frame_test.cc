// The rotating frame (effect 'rotating frame'): a free block released at
// rest in a frame turning at Omega moves in a straight line at Omega r0 in
// the inertial frame, so that in the rotating frame its centre of mass
// follows x(t) = R(-Omega t) (x0 + t Omega z x x0), centrifugal and
// Coriolis together (exact for the centre of mass: both forces are linear
// in x and v). A bar held by the outer wall of a centrifuge carries
// sigma_xx(r) = -rho Omega^2 (r^2 - r_in^2) / 2.
#include <deal.II/base/mpi.h>

#include <dealmpm/effects/rotating_frame.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double omega = 2;

  std::string
  free_block(const double cfl)
  {
    std::ostringstream s;
    s << "set Effects = rotating frame\n"
      << "subsection Rotating frame\n set Angular velocity = " << omega
      << "\nend\n"
      << "subsection Grid\n set Lower corner = -1, -1\n"
      << " set Upper corner = 1, 1\n set Cells = 100, 100\nend\n"
      << "subsection Material 1\n set Density = 1000\n"
      << " subsection linear elastic\n  set Young's modulus = 1e6\n end\n"
      << "end\n"
      << "subsection Time\n set CFL number = " << cfl << "\nend\n"
      << "subsection Body 1\n set Lower corner = 0.45, -0.05\n"
      << " set Upper corner = 0.55, 0.05\nend\n";
    return s.str();
  }

  Point<2>
  centre_of_mass(Simulation<2> &simulation)
  {
    const CoreFields &f       = simulation.particle_set().fields;
    double            sums[3] = {};
    for (const auto &p : simulation.particle_set().handler)
      {
        const double m = p.get_properties()[f.mass];
        sums[0] += m * p.get_location()[0];
        sums[1] += m * p.get_location()[1];
        sums[2] += m;
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 3),
                        MPI_COMM_WORLD,
                        ArrayView<double>(sums, 3));
    return Point<2>(sums[0] / sums[2], sums[1] / sums[2]);
  }

  struct Flight
  {
    double error;   ///< |x_c - exact| at the end
    double balance; ///< |E - W - E0| / W
  };

  Flight
  fly(const double cfl, const double end)
  {
    auto           simulation = test::make_simulation<2>(free_block(cfl));
    const Point<2> x0         = centre_of_mass(*simulation);
    const double   E0         = simulation->statistics().total_energy();
    while (simulation->time() < end - 1e-12)
      simulation->advance(
        std::min(simulation->time_step(), end - simulation->time()));
    // Inertial: x0 + t omega z x x0; seen from the frame: turned by -omega t.
    const Point<2> inertial(x0[0] - end * omega * x0[1],
                            x0[1] + end * omega * x0[0]);
    const double   a = -omega * end;
    const Point<2> exact(std::cos(a) * inertial[0] - std::sin(a) * inertial[1],
                         std::sin(a) * inertial[0] + std::cos(a) * inertial[1]);
    const double   W = simulation->external_work();
    return {centre_of_mass(*simulation).distance(exact),
            std::abs(simulation->statistics().total_energy() - W - E0) / W};
  }
} // namespace

TEST(RotatingFrame, AccelerationIsCentrifugalCoriolisAndEuler)
{
  const Tensor<1, 3> w({0, 0, 2}), w_dot({0, 0, 3});
  const Point<2>     c(1, 0), x(2, 1);
  const Tensor<1, 2> v({0.5, -1});
  // r = (1, 1): omega^2 r = (4, 4); -2 w x v = 2 * 2 (v_y, -v_x) =
  // (-4, -2); -w' x r = 3 (r_y, -r_x) = (3, -3).
  const Tensor<1, 2> b = RotatingFrame<2>::acceleration(w, w_dot, c, x, v);
  EXPECT_NEAR(b[0], 4 - 4 + 3, 1e-14);
  EXPECT_NEAR(b[1], 4 - 2 - 3, 1e-14);
  // 3D: the same about an axis along y (x -> z, y -> x).
  const Tensor<1, 3> w3({0, 2, 0}), w3_dot({0, 3, 0});
  const Tensor<1, 3> b3 =
    RotatingFrame<3>::acceleration(w3,
                                   w3_dot,
                                   Point<3>(0, 0, 1),
                                   Point<3>(1, 5, 2),
                                   Tensor<1, 3>({-1, 7, 0.5}));
  EXPECT_NEAR(b3[2], 4 - 4 + 3, 1e-14);
  EXPECT_NEAR(b3[0], 4 - 2 - 3, 1e-14);
  EXPECT_NEAR(b3[1], 0, 1e-14);
}

// Omega t = 1 rad: the block ends 0.71 m from the axis, 0.42 m from where
// it started.
TEST(RotatingFrame, FreeBlockFliesStraightInTheInertialFrame)
{
  const Flight coarse = fly(0.5, 0.5);
  const Flight fine   = fly(0.25, 0.5);
  std::cout << "rotating frame, free block: centre of mass off by "
            << coarse.error << " m (CFL 0.5), " << fine.error
            << " m (CFL 0.25); energy balance " << coarse.balance << ", "
            << fine.balance << " of the frame's work" << std::endl;
  EXPECT_LT(coarse.error, 5e-4);
  EXPECT_LT(fine.error, 0.7 * coarse.error);
  EXPECT_LT(coarse.balance, 0.01);
}

// A bar from r = 0.2 to 1 m in a box of slip walls at r = 1 and on its
// sides (they take the Euler and Coriolis forces of the spin-up), in a
// centrifuge spun up to 10 rad/s over 0.1 s, settled by local damping:
// sigma_xx(r) =
// -rho Omega^2 (r^2 - r_in^2) / 2, 48 kPa at the wall (the column's
// analogue with g = Omega^2 r).
TEST(RotatingFrame, CentrifugeBarCarriesItsSpinningWeight)
{
  const double rho = 1000, w = 10, r_in = 0.2, r_out = 1;
  auto         simulation = test::make_simulation<2>(R"(
set Effects = rotating frame, local damping
subsection Rotating frame
  set Angular velocity = 10
  set Ramp time        = 0.1
end
subsection Local damping
  set Coefficient = 0.15
end
subsection Grid
  set Lower corner        = 0, -0.1
  set Upper corner        = 1, 0.1
  set Cells               = 50, 10
  set Boundary conditions = 1: slip, 2: slip, 3: slip
end
subsection Material 1
  set Density = 1000
  subsection linear elastic
    set Young's modulus = 1e7
    set Poisson's ratio = 0
  end
end
subsection MPM
  set Shape function = cpGIMP
end
subsection Body 1
  set Lower corner = 0.2, -0.1
  set Upper corner = 1, 0.1
end
)");
  while (simulation->time() < 1.)
    simulation->advance(simulation->time_step());
  const CoreFields &f     = simulation->particle_set().fields;
  const double      scale = rho * w * w * (r_out * r_out - r_in * r_in) / 2;
  double            sum = 0, count = 0, largest = 0;
  for (const auto &p : simulation->particle_set().handler)
    {
      const auto   props = p.get_properties();
      const double r     = p.get_location()[0];
      const double exact = -rho * w * w * (r * r - r_in * r_in) / 2;
      const double error =
        std::abs(read_symmetric<2>(&props[f.stress])[0][0] - exact) / scale;
      sum += error;
      count += 1;
      largest = std::max(largest, error);
    }
  sum                = Utilities::MPI::sum(sum, MPI_COMM_WORLD);
  count              = Utilities::MPI::sum(count, MPI_COMM_WORLD);
  largest            = Utilities::MPI::max(largest, MPI_COMM_WORLD);
  const Statistics s = simulation->statistics();
  std::cout << "centrifuge bar: mean |sigma_xx - exact| / (rho Omega^2 "
               "(R^2 - r_in^2) / 2) = "
            << sum / count << ", largest " << largest
            << ", kinetic / strain energy "
            << s.kinetic_energy / s.strain_energy << std::endl;
  EXPECT_LT(s.kinetic_energy, 1e-3 * s.strain_energy); // settled
  EXPECT_LT(sum / count, 0.01);
}
