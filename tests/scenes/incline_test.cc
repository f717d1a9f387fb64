// Coulomb friction on a slip floor under tilted gravity (an incline of
// angle theta): a block slides by s(t) = 1/2 g (sin theta - mu cos theta)
// t^2 and stays put when tan theta <= mu; a disk rolls without slip at
// 2/3 g sin theta when mu >= tan(theta) / 3, and slips otherwise with
// g (sin theta - mu cos theta). doc/research.md 5.2 has the numbers.
#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double g = 9.81;

  /** A scene on the floor (id 2, slip with friction mu) of a 1.2 x 0.3
   * grid of cells of size h, gravity tilted by theta (degrees) towards
   * +x, and one body (its section text); PIC, which the wall's friction
   * needs (BoundaryFriction). */
  std::string
  incline(const double       theta,
          const double       mu,
          const double       h,
          const std::string &body)
  {
    const double       t = theta * M_PI / 180;
    std::ostringstream s;
    s.precision(17);
    s << "set Effects = gravity, boundary friction\n"
      << "subsection Gravity\n set Acceleration = " << g * std::sin(t) << ", "
      << -g * std::cos(t) << "\nend\n"
      << "subsection Boundary friction\n set Coefficients = 2: " << mu
      << "\nend\n"
      << "subsection Grid\n set Upper corner = 1.2, 0.3\n set Cells = "
      << std::lround(1.2 / h) << ", " << std::lround(0.3 / h)
      << "\n set Boundary conditions = 2: slip\nend\n"
      << "subsection Material 1\n set Density = 1000\n"
      << " subsection linear elastic\n  set Young's modulus = 1e7\n end\n"
      << "end\n"
      << "subsection MPM\n set Velocity update = PIC\nend\n"
      << "subsection Body 1\n"
      << body << "end\n";
    return s.str();
  }

  const std::string block = " set Lower corner = 0.1, 0\n"
                            " set Upper corner = 0.3, 0.1\n";
  const std::string disk  = " set Shape = ball\n set Center = 0.2, 0.1\n"
                            " set Radius = 0.1\n";

  struct Slide
  {
    double distance;     ///< of the centre of mass along the floor
    double energy_error; ///< |E - W - E0| / |W| (W: friction work)
    double friction_work;
  };

  /** The block on a base (body 1, 0.1 thick, held by a no-slip floor)
   * instead of the floor: contact between them with friction mu; FLIP,
   * gravity ramped up over the first 0.05 s (a sudden load sets the
   * block ringing on the base). */
  constexpr double ramp = 0.05;

  std::string
  block_on_base(const double       theta,
                const double       mu,
                const double       h,
                const std::string &extra = "")
  {
    const double       t = theta * M_PI / 180;
    std::ostringstream s;
    s.precision(17);
    s << "set Number of bodies = 2\n"
      << "set Effects = gravity, frictional contact\n"
      << "subsection Gravity\n set Acceleration = " << g * std::sin(t) << ", "
      << -g * std::cos(t) << "\n set Ramp time = " << ramp << "\nend\n"
      << "subsection Frictional contact\n set Friction coefficient = " << mu
      << "\nend\n"
      << "subsection Grid\n set Upper corner = 1.2, 0.3\n set Cells = "
      << std::lround(1.2 / h) << ", " << std::lround(0.3 / h)
      << "\n set Boundary conditions = 2: no-slip\nend\n"
      << "subsection Material 1\n set Density = 1000\n"
      << " subsection linear elastic\n  set Young's modulus = 1e7\n end\n"
      << "end\n"
      << "subsection Body 1\n set Upper corner = 1.2, 0.1\nend\n"
      << "subsection Body 2\n set Lower corner = 0.1, 0.1\n"
      << " set Upper corner = 0.3, 0.2\nend\n"
      << extra;
    return s.str();
  }

  /** The block on a base of finite elements (an FEM region 0.1 thick,
   * fixed at its bottom, id 2) instead of MPM: the region's top (id 3) in
   * contact with friction mu (RegionContact). USL, which the region's
   * contact needs, with cpGIMP: with linear shape functions the block's
   * front corner turns inside out as it crosses a cell face at t = 0.074,
   * on a plain slip floor too. */
  std::string
  block_on_fem_base(const double       theta,
                    const double       mu,
                    const double       h,
                    const std::string &extra = "")
  {
    const double       t = theta * M_PI / 180;
    std::ostringstream s;
    s.precision(17);
    s << "set Number of FEM regions = 1\n"
      << "set Effects = gravity\n"
      << "subsection Gravity\n set Acceleration = " << g * std::sin(t) << ", "
      << -g * std::cos(t) << "\n set Ramp time = " << ramp << "\nend\n"
      << "subsection Grid\n set Upper corner = 1.2, 0.3\n set Cells = "
      << std::lround(1.2 / h) << ", " << std::lround(0.3 / h) << "\nend\n"
      << "subsection Material 1\n set Density = 1000\n"
      << " subsection linear elastic\n  set Young's modulus = 1e7\n end\n"
      << "end\n"
      << "subsection FEM region 1\n set Upper corner = 1.2, 0.1\n"
      << " set Cells = " << std::lround(1.2 / h) << ", " << std::lround(0.1 / h)
      << "\n set Fixed boundaries = 2\n"
      << " set Contact boundaries = 3: " << mu << "\nend\n"
      << "subsection MPM\n set Stress update = USL\n"
      << " set Shape function = cpGIMP\nend\n"
      << "subsection Body 1\n set Lower corner = 0.1, 0.1\n"
      << " set Upper corner = 0.3, 0.2\nend\n"
      << extra;
    return s.str();
  }

  /** Centre of mass of body @p body's particles, or of all with
   * numbers::invalid_unsigned_int (all ranks). */
  template <int dim>
  Point<dim>
  centre_of_mass(Simulation<dim>   &simulation,
                 const unsigned int body = numbers::invalid_unsigned_int)
  {
    const CoreFields &f             = simulation.particle_set().fields;
    double            sums[dim + 1] = {};
    for (const auto &p : simulation.particle_set().handler)
      if (body == numbers::invalid_unsigned_int ||
          simulation.particle_set().body_of(p.get_properties()) == body)
        {
          const double m = p.get_properties()[f.mass];
          sums[dim] += m;
          for (unsigned int d = 0; d < dim; ++d)
            sums[d] += m * p.get_location()[d];
        }
    Utilities::MPI::sum(ArrayView<const double>(sums, dim + 1),
                        MPI_COMM_WORLD,
                        ArrayView<double>(sums, dim + 1));
    Point<dim> x;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] = sums[d] / sums[dim];
    return x;
  }

  Slide
  slide(const std::string &scene,
        const double       end_time,
        const unsigned int n_bodies      = 1,
        const unsigned int n_fem_regions = 0)
  {
    auto simulation =
      test::make_simulation<2>(scene, n_bodies, 1, n_fem_regions);
    // The last body is the one that slides.
    const auto where = [&] {
      return centre_of_mass(*simulation,
                            n_bodies == 1 ? numbers::invalid_unsigned_int :
                                            n_bodies - 1);
    };
    const Point<2>   start = where();
    const Statistics s0    = simulation->statistics();
    while (simulation->time() < end_time - 1e-12)
      simulation->advance(
        std::min(simulation->time_step(), end_time - simulation->time()));
    const Statistics s    = simulation->statistics();
    const double     work = simulation->external_work();
    return {where()[0] - start[0],
            std::abs(s.total_energy() - work - s0.total_energy()) /
              std::max(std::abs(work), 1e-300),
            work};
  }

  /** The rigid block's s(t), gravity ramped up linearly over [0, T]
   * (acceleration a t / T, then a). */
  double
  sliding_distance(const double theta,
                   const double mu,
                   const double t,
                   const double T = 0)
  {
    const double r = theta * M_PI / 180;
    const double a = std::max(0., g * (std::sin(r) - mu * std::cos(r)));
    if (t <= T)
      return a * t * t * t / (6 * T);
    return a * T * T / 6 + a * T / 2 * (t - T) + a * (t - T) * (t - T) / 2;
  }
} // namespace

// theta = 30 deg, mu = 0.2: a = 3.2059 m/s^2 (doc/research.md 5.2), and the
// friction's work -mu m g cos(theta) s closes the energy balance.
TEST(Incline, BlockSlidesAtTheCoulombRate)
{
  const double end = 0.5, exact = sliding_distance(30, 0.2, end);
  for (const double h : {0.05, 0.025, 0.0125})
    {
      const Slide  run   = slide(incline(30, 0.2, h, block), end);
      const double error = std::abs(run.distance / exact - 1);
      std::cout << "incline block, h = " << h << ": s(0.5 s) = " << run.distance
                << " (exact " << exact << "), relative error " << error
                << ", friction work " << run.friction_work
                << ", energy balance error " << run.energy_error << std::endl;
      EXPECT_LT(error, 0.01);
      EXPECT_LT(run.energy_error, 0.02);
    }
}

// tan(30 deg) = 0.577 <= mu = 0.6: the block does not move (the frictionless
// block would slide 0.61 m).
TEST(Incline, BlockStaysWhenFrictionHoldsIt)
{
  const Slide run = slide(incline(30, 0.6, 0.025, block), 0.5);
  std::cout << "incline block, mu = 0.6: moved " << run.distance << std::endl;
  EXPECT_LT(std::abs(run.distance), 1e-3 * sliding_distance(30, 0, 0.5));
}

// Without friction the block slides at g sin(theta), exactly.
TEST(Incline, FrictionlessBlockSlidesAtGSinTheta)
{
  const Slide run = slide(incline(30, 0, 0.025, block), 0.5);
  EXPECT_NEAR(run.distance / sliding_distance(30, 0, 0.5), 1., 1e-3);
  EXPECT_EQ(run.friction_work, 0.);
}

// A disk on a 60 deg incline with mu = 0.3 < tan(60 deg) / 3 slips at
// g (sin theta - mu cos theta) = 7.0242 m/s^2. (Rolling, at 30 deg with
// mu >= tan(30 deg) / 3, wants 2/3 g sin theta; the disk does not roll:
// it slides at the Coulomb rate while mu < tan theta and sticks above;
// see doc/guide/limits.md.)
TEST(Incline, DiskSlipsAtTheCoulombRate)
{
  const double end      = 0.4;
  const double slipping = sliding_distance(60, 0.3, end);
  const Slide  slip     = slide(incline(60, 0.3, 0.0125, disk), end);
  std::cout << "incline disk, 60 deg: s = " << slip.distance << " (slipping "
            << slipping << ")" << std::endl;
  EXPECT_NEAR(slip.distance / slipping, 1., 0.01);
}

// The block on an elastic base it shares grid nodes with: contact, not the
// floor, carries the friction (theta = 30 deg; mu = 0 and 0.2 under FLIP,
// and 0.6, which holds it, under PIC). The error is the grid's: it falls
// with h (3.1 % and 5.3 % at h = 1/40, 1.7 % and 3.0 % at 1/80, measured).
TEST(Incline, BlockSlidesOnABaseAtTheCoulombRate)
{
  const double end = 0.5;
  for (const double mu : {0., 0.2})
    {
      const double exact  = sliding_distance(30, mu, end, ramp);
      double       coarse = 0;
      for (const double h : {0.025, 0.0125})
        {
          const Slide  run   = slide(block_on_base(30, mu, h), end, 2);
          const double error = std::abs(run.distance / exact - 1);
          std::cout << "block on a base, mu = " << mu << ", h = " << h
                    << ": s(0.5 s) = " << run.distance << " (exact " << exact
                    << "), relative error " << error << std::endl;
          EXPECT_LT(error, h == 0.025 ? 0.06 : 0.035);
          if (h == 0.025)
            coarse = error;
          else
            EXPECT_LT(error, 0.7 * coarse);
        }
    }
  // mu = 0.6 > tan(30 deg) holds it under PIC (3e-5 m, the elastic
  // strain, at h = 1/40 and 1/80); FLIP's particle noise lets it creep
  // (2.3 and 4.0 cm), see doc/guide/limits.md.
  for (const double h : {0.025, 0.0125})
    {
      const Slide held = slide(
        block_on_base(
          30, 0.6, h, "subsection MPM\n set Velocity update = PIC\nend\n"),
        end,
        2);
      std::cout << "block on a base, mu = 0.6, PIC, h = " << h << ": moved "
                << held.distance << std::endl;
      EXPECT_LT(std::abs(held.distance),
                1e-3 * sliding_distance(30, 0, end, ramp));
    }
}

// The block on a base of finite elements (issue 15): the Coulomb rate,
// with contact through the grid between the region's surface (its own
// normals, not mass gradients) and the block, to 2.4e-4 at h = 1/40 and
// 1.1e-4 at 1/80 (the MPM base: 6 % and 3.5 %); mu = 0.6 holds it under
// PIC.
TEST(Incline, BlockSlidesOnAnFemBaseAtTheCoulombRate)
{
  const double end = 0.5;
  // Frictionless on the coarse grid; mu = 0.2 on two (the error falls with
  // h). The energy balance (friction's and the gravity ramp's work) closes.
  double coarse = 0;
  for (const auto &[mu, h] :
       {std::pair<double, double>{0.0, 0.025}, {0.2, 0.025}, {0.2, 0.0125}})
    {
      const double exact = sliding_distance(30, mu, end, ramp);
      const Slide  run   = slide(block_on_fem_base(30, mu, h), end, 1, 1);
      const double error = std::abs(run.distance / exact - 1);
      std::cout << "block on an FEM base, mu = " << mu << ", h = " << h
                << ": s(0.5 s) = " << run.distance << " (exact " << exact
                << "), relative error " << error << ", energy balance error "
                << run.energy_error << std::endl;
      EXPECT_LT(error, 1e-3);
      EXPECT_LT(run.energy_error, 1e-3);
      if (mu > 0 && h == 0.025)
        coarse = error;
      else if (mu > 0)
        {
          EXPECT_LT(error, 0.7 * coarse);
        }
    }
  const Slide held = slide(
    block_on_fem_base(
      30, 0.6, 0.025, "subsection MPM\n set Velocity update = PIC\nend\n"),
    end,
    1,
    1);
  std::cout << "block on an FEM base, mu = 0.6, PIC: moved " << held.distance
            << std::endl;
  EXPECT_LT(std::abs(held.distance), 1e-3 * sliding_distance(30, 0, end, ramp));
}

// Two blocks stacked on the FEM base, bodies in contact with each other
// ('frictional contact', each body its own field: each meets the region
// on its own): the top block (0.15 x 0.05 on a 0.6 x 0.1 one, an eighth of
// its mass) slides without friction on the lower one at g sin(theta);
// the lower one carries both on the base (mu = 0.2):
// a = g (sin(theta) - 1.125 mu cos(theta)), the top block's weight
// pressing it down but not pulling it along. (The top block is shorter:
// blocks with flush ends catch at their corners, where the mass
// gradients' normals are not the surface's, MPM alone as well.)
TEST(Incline, StackedBlocksOnAnFemBase)
{
  const double end   = 0.5;
  auto         stack = test::make_simulation<2>(
    block_on_fem_base(30,
                      0.2,
                      0.025,
                      "set Effects = gravity, frictional contact\n"
                              "subsection Frictional contact\n"
                              " set Friction coefficient = 0\nend\n"
                              "subsection Body 1\n set Upper corner = 0.7, 0.2\nend\n"
                              "subsection Body 2\n set Lower corner = 0.15, 0.2\n"
                              " set Upper corner = 0.3, 0.25\nend\n"),
    2,
    1,
    1);
  const Point<2>   lower0 = centre_of_mass(*stack, 0);
  const Point<2>   upper0 = centre_of_mass(*stack, 1);
  const Statistics s0     = stack->statistics();
  while (stack->time() < end - 1e-12)
    stack->advance(std::min(stack->time_step(), end - stack->time()));
  const double     lower       = centre_of_mass(*stack, 0)[0] - lower0[0];
  const double     upper       = centre_of_mass(*stack, 1)[0] - upper0[0];
  const double     exact_lower = sliding_distance(30, 1.125 * 0.2, end, ramp);
  const double     exact_upper = sliding_distance(30, 0, end, ramp);
  const Statistics s           = stack->statistics();
  const double     work        = stack->external_work();
  const double     balance =
    std::abs(s.total_energy() - work - s0.total_energy()) / std::abs(work);
  std::cout << "stacked blocks on an FEM base: lower " << lower << " (exact "
            << exact_lower << "), upper " << upper << " (exact " << exact_upper
            << "), energy balance error " << balance << std::endl;
  EXPECT_NEAR(lower / exact_lower, 1, 1e-3);
  EXPECT_NEAR(upper / exact_upper, 1, 1e-3);
  EXPECT_LT(balance, 1e-3);
}
