// A rigid body with a prescribed motion (effect 'rigid body'). A punch as
// wide as a confined elastic layer pressed down by delta carries the
// oedometric force M delta / H (M = lambda + 2 mu); a block on a rigid
// half-space under tilted gravity slides by 1/2 g (sin theta - mu cos
// theta) t^2 and presses it with m g cos theta.
#include <deal.II/base/mpi.h>

#include <dealmpm/effects/rigid_body.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <tuple>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double g = 9.81;

  double
  centre_of_mass_x(Simulation<2> &simulation)
  {
    const CoreFields &f       = simulation.particle_set().fields;
    double            sums[2] = {};
    for (const auto &p : simulation.particle_set().handler)
      {
        sums[0] += p.get_properties()[f.mass] * p.get_location()[0];
        sums[1] += p.get_properties()[f.mass];
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                        MPI_COMM_WORLD,
                        ArrayView<double>(sums, 2));
    return sums[0] / sums[1];
  }
} // namespace

TEST(RigidBody, ShapesKnowTheirDistanceAndNormal)
{
  RigidShape<2> box;
  box.lower = Point<2>(0, 0);
  box.upper = Point<2>(2, 1);
  EXPECT_DOUBLE_EQ(box.distance(Point<2>(1, 0.9)), -0.1);
  EXPECT_DOUBLE_EQ(box.normal(Point<2>(1, 0.9))[1], 1.);
  EXPECT_DOUBLE_EQ(box.distance(Point<2>(-0.3, 1.4)), 0.5);
  EXPECT_NEAR(box.normal(Point<2>(-0.3, 1.4))[0], -0.6, 1e-15);
  EXPECT_NEAR(box.normal(Point<2>(-0.3, 1.4))[1], 0.8, 1e-15);
  // Beneath a face, beside one, or past a corner (where a punch's
  // footing would widen if it held what is within reach).
  EXPECT_TRUE(box.under_a_face(Point<2>(1, -0.01)));
  EXPECT_TRUE(box.under_a_face(Point<2>(2.01, 0.5)));
  EXPECT_TRUE(box.under_a_face(Point<2>(1, 0.5)));
  EXPECT_FALSE(box.under_a_face(Point<2>(-0.3, 1.4)));
  EXPECT_FALSE(box.under_a_face(Point<2>(2.01, -0.01)));

  RigidShape<2> cylinder;
  cylinder.kind   = RigidShape<2>::Kind::cylinder;
  cylinder.centre = Point<2>(1, 1);
  cylinder.radius = 0.5;
  EXPECT_DOUBLE_EQ(cylinder.distance(Point<2>(1, 2)), 0.5);
  EXPECT_DOUBLE_EQ(cylinder.normal(Point<2>(1, 0.8))[1], -1.);

  RigidShape<2> ground;
  ground.kind        = RigidShape<2>::Kind::half_space;
  ground.centre      = Point<2>(0, 0.1);
  ground.face_normal = Tensor<1, 2>({0, 1});
  EXPECT_DOUBLE_EQ(ground.distance(Point<2>(5, 0.05)), -0.05);
}

// E = 1e6, nu = 0.3: M = 1.346 MPa; a 1 m layer on a slip floor between
// slip walls, pressed by 0.009 m over 1 s (the speed ramped up over 0.2 s,
// slow against the 0.03 s wave transit): 12.12 kN per metre. No damping:
// Cundall's damping also acts on the held nodes and would add its
// coefficient's share to the reaction.
TEST(RigidBody, PunchOnAConfinedLayerCarriesTheOedometricForce)
{
  auto simulation = test::make_simulation<2>(R"(
set Effects = rigid body
subsection Rigid body
  set Lower corner = -1, 1
  set Upper corner = 2, 2
  set Velocity     = 0; -0.01
  set Load curve   = 0: 0, 0.2: 1
end
subsection MPM
  set Velocity update = PIC
end
subsection Grid
  set Upper corner        = 1, 1.25
  set Cells               = 20, 25
  set Boundary conditions = 0: slip, 1: slip, 2: slip
end
subsection Material 1
  set Density = 1000
  subsection linear elastic
    set Young's modulus = 1e6
    set Poisson's ratio = 0.3
  end
end
subsection Body 1
  set Upper corner = 1, 1
end
)");
  test::run_to(*simulation, 1.);
  const Statistics s        = simulation->statistics();
  const double     M        = 1e6 * 0.7 / (1.3 * 0.4);
  const double     expected = M * 0.009 / 1.;
  const double     force    = test::effect_column(s, "rigid_force_y");
  std::cout << "rigid body: punch force " << force << " N/m (oedometer "
            << expected << "), displacement "
            << test::effect_column(s, "rigid_displacement_y") << " m, sideways "
            << test::effect_column(s, "rigid_force_x") << " N/m" << std::endl;
  // The midpoint rule is exact but in the step across the ramp's kink.
  EXPECT_NEAR(test::effect_column(s, "rigid_displacement_y"), -0.009, 1e-8);
  EXPECT_NEAR(force, expected, 0.03 * expected);
  EXPECT_NEAR(test::effect_column(s, "rigid_force_x"), 0, 1e-6 * expected);
}

// The same layer pressed on along @p axis (1: down from the top, 0: in
// from the right, the grid then turned on its side) by 1.6 cells,
// at 0.05 m/s after a 0.2 s ramp: slow against the 0.027 s wave transit.
// The rate form's uniaxial stress is exact: sigma = M ln(1 - u / H). The
// force is checked at every step past 0.3 cells of travel. Without the
// nodes within reach under its face, the punch let go of the layer for
// half a particle spacing before each row of nodes: the force fell to 0
// on and off from 0.78 to 1 cell of travel (2 particles per direction).
namespace
{
  /** The least ratio of the punch's force to the exact one over the
   * travel, and the mean. */
  std::pair<double, double>
  grip_over_a_row_of_nodes(const unsigned int axis,
                           const std::string &method,
                           const std::string &body)
  {
    const bool         down = axis == 1;
    std::ostringstream scene;
    scene << "set Effects = rigid body\nsubsection Rigid body\n"
          << (down ? " set Lower corner = -1, 1\n set Velocity = 0; -0.05\n" :
                     " set Lower corner = 1, -1\n set Velocity = -0.05; 0\n")
          << " set Upper corner = 2, 2\n set Load curve = 0: 0, 0.2: 1\nend\n"
          << "subsection MPM\n set Velocity update = PIC\n"
          << method << "end\nsubsection Grid\n"
          << (down ? " set Upper corner = 1, 1.25\n set Cells = 20, 25\n" :
                     " set Upper corner = 1.25, 1\n set Cells = 25, 20\n")
          << " set Boundary conditions = 0: slip, 1: slip, 2: slip, 3: slip\n"
          << "end\nsubsection Material 1\n set Density = 1000\n"
          << " subsection linear elastic\n  set Young's modulus = 1e6\n"
          << "  set Poisson's ratio = 0.3\n end\nend\n"
          << "subsection Body 1\n set Upper corner = 1, 1\n"
          << body << "end\n";
    auto              simulation = test::make_simulation<2>(scene.str());
    const double      M = 1e6 * 0.7 / (1.3 * 0.4), h = 0.05;
    const std::string column = down ? "rigid_force_y" : "rigid_force_x";
    const std::string travel =
      down ? "rigid_displacement_y" : "rigid_displacement_x";
    double       least = 1, sum = 0;
    unsigned int steps = 0;
    while (true)
      {
        simulation->advance(simulation->time_step());
        const Statistics s = simulation->statistics();
        const double     u = -test::effect_column(s, travel);
        if (u > 1.6 * h)
          break;
        if (u < 0.3 * h)
          continue;
        const double ratio =
          test::effect_column(s, column) / (-M * std::log(1 - u / 1.));
        least = std::min(least, ratio);
        sum += ratio;
        ++steps;
      }
    return {least, sum / steps};
  }
} // namespace

TEST(RigidBody, KeepsItsGripAsItsFacePassesARowOfNodes)
{
  // Axis, an MPM entry, a body entry (MUSL, linear, 2 x 2 by default).
  const std::tuple<unsigned int, std::string, std::string> cases[] = {
    {1, "", ""},
    {1, "", "Particles per cell = 3"},
    {1, "Shape function = uGIMP", ""},
    {1, "Stress update = USL", ""},
    {0, "", ""}};
  for (const auto &[axis, method, body] : cases)
    {
      const auto entry = [](const std::string &e) {
        return e.empty() ? e : " set " + e + "\n";
      };
      const auto [least, mean] =
        grip_over_a_row_of_nodes(axis, entry(method), entry(body));
      std::cout << "rigid body: pressed 1.6 cells along axis " << axis << " ("
                << method << body << "): force / exact at least " << least
                << ", mean " << mean << std::endl;
      // Holding on: never under 0.4 (the old code fell to 0 for a fifth
      // of a cell). The mean: a face between two rows of nodes costs
      // linear shape functions 15-21 % of the force by 1.6 cells (the
      // particles under the face take more than their share of the
      // strain; the same before the fix), uGIMP 7 %.
      EXPECT_GE(least, 0.4) << axis << method << body;
      const double error =
        method.find("GIMP") == std::string::npos ? 0.25 : 0.1;
      EXPECT_NEAR(mean, 1, error) << axis << method << body;
    }
}

namespace
{
  /** The start of a scene on a rigid half-space (the plane y = 0.1) under
   * gravity tilted by 30 deg, with Coulomb friction mu and @p more entries
   * of the rigid body's section. */
  std::string
  on_rigid_incline(const double mu, const std::string &more)
  {
    const double       theta = M_PI / 6;
    std::ostringstream scene;
    scene.precision(17);
    scene << "set Effects = gravity, rigid body\n"
          << "subsection Gravity\n set Acceleration = " << g * std::sin(theta)
          << ", " << -g * std::cos(theta) << "\nend\n"
          << "subsection Rigid body\n set Shape = half-space\n"
          << " set Point = 0, 0.1\n set Normal = 0, 1\n"
          << more << " set Friction coefficient = " << mu << "\nend\n";
    return scene.str();
  }

  /** A block (0.2 x 0.1 m) on a rigid half-space under gravity tilted by
   * 30 deg, friction mu, PIC, cells of 1 / n m: the slide of its centre of
   * mass in 0.5 s and the mean normal force on the half-space. */
  std::pair<double, double>
  slide_on_rigid_incline(const double mu, const unsigned int n)
  {
    std::ostringstream scene;
    scene << on_rigid_incline(mu, "")
          << "subsection MPM\n set Velocity update = PIC\nend\n"
          << "subsection Grid\n set Upper corner = 1.2, 0.3\n"
          << " set Cells = " << 1.2 * n << ", " << 0.3 * n << "\nend\n"
          << "subsection Material 1\n set Density = 1000\n"
          << " subsection linear elastic\n  set Young's modulus = 1e7\n end\n"
          << "end\n"
          << "subsection Body 1\n set Lower corner = 0.1, 0.1\n"
          << " set Upper corner = 0.3, 0.2\nend\n";
    auto         simulation = test::make_simulation<2>(scene.str());
    const double x0         = centre_of_mass_x(*simulation);
    double       normal_sum = 0;
    unsigned int n_steps    = 0;
    while (simulation->time() < 0.5 - 1e-12)
      {
        simulation->advance(
          std::min(simulation->time_step(), 0.5 - simulation->time()));
        normal_sum +=
          test::effect_column(simulation->statistics(), "rigid_force_y");
        ++n_steps;
      }
    return {centre_of_mass_x(*simulation) - x0, -normal_sum / n_steps};
  }
} // namespace

// theta = 30 deg, mu = 0.2, PIC: s(0.5 s) = 0.4007 m; the error at h =
// 1/20, 1/40, 1/80 measured 0.046 %, 0.031 %, 0.021 % (the block slides
// as a whole: what is left is its elastic settling on the incline).
TEST(RigidBody, BlockSlidesDownARigidIncline)
{
  const double theta = M_PI / 6, mu = 0.2;
  const double exact =
    0.5 * g * (std::sin(theta) - mu * std::cos(theta)) * 0.25;
  const double weight = 1000 * 0.02 * g * std::cos(theta);
  for (const unsigned int n : {20u, 40u, 80u})
    {
      const auto [s, normal] = slide_on_rigid_incline(mu, n);
      std::cout << "rigid body: h = 1/" << n << ", block on a rigid incline "
                << "slid " << s << " m (exact " << exact << ", error "
                << (s - exact) / exact << "), mean normal force " << normal
                << " N/m (m g cos theta " << weight << ")" << std::endl;
      EXPECT_NEAR(s, exact, 0.01 * exact) << n;
      EXPECT_NEAR(normal, weight, 0.02 * weight) << n;
    }
}

// tan 30 deg = 0.577 < mu = 0.6: the block holds.
TEST(RigidBody, BlockHoldsOnARigidInclineWhenFrictionSuffices)
{
  const auto [s, normal] = slide_on_rigid_incline(0.6, 40);
  std::cout << "rigid body: mu = 0.6, the block moved " << s << " m"
            << std::endl;
  EXPECT_LT(std::abs(s), 1e-3);
}
// A disk (R = 0.1 m) on a rigid 30 deg incline with mu = 0.5 >= tan(30
// deg) / 3 rolls without slip: s = 1/3 g sin(theta) t^2. With the touch
// check the incline holds only the nodes of particles that reach it, and
// the disk turns about its contact point; FLIP keeps its spin (PIC damps
// it). Measured, of the rolling distance in 0.4 s: 0.40, 0.78, 0.89 at
// h = 1/40, 1/80, 1/160, converging. Without the check the incline holds
// a cell-wide patch under the disk, which brakes it (0.58 at h = 1/80;
// under PIC it slides at the Coulomb rate, 0.24, the sliding 0.20).
TEST(RigidBody, DiskRollsDownARigidInclineWithTheTouchCheck)
{
  const double theta = M_PI / 6, end = 0.4;
  const double rolling = g * std::sin(theta) * end * end / 3;
  const auto   roll    = [&](const unsigned int n, const bool touch) {
    std::ostringstream scene;
    scene << on_rigid_incline(0.5,
                              std::string(" set Touch check = ") +
                                (touch ? "true" : "false") + "\n")
          << "subsection MPM\n set Velocity update = FLIP\nend\n"
          << "subsection Grid\n set Upper corner = 1.2, 0.4\n"
          << " set Cells = " << 1.2 * n << ", " << 0.4 * n << "\nend\n"
          << "subsection Material 1\n set Density = 1000\n"
          << " subsection linear elastic\n  set Young's modulus = 1e7\n end\n"
          << "end\n"
          << "subsection Body 1\n set Shape = ball\n set Center = 0.2, 0.2\n"
          << " set Radius = 0.1\nend\n";
    auto         simulation = test::make_simulation<2>(scene.str());
    const double x0         = centre_of_mass_x(*simulation);
    test::run_to(*simulation, end);
    return (centre_of_mass_x(*simulation) - x0) / rolling;
  };
  const double patch = roll(80, false), coarse = roll(80, true),
               fine = roll(160, true);
  std::cout << "rigid body: disk on a 30 deg incline, of the rolling "
            << "distance: " << patch << " without the touch check (h = "
            << "1/80), " << coarse << " and " << fine
            << " with it at h = 1/80 and 1/160" << std::endl;
  EXPECT_LT(patch, coarse - 0.1);
  EXPECT_LT(std::abs(1 - fine), 0.13);
  EXPECT_LT(std::abs(1 - fine), 0.6 * std::abs(1 - coarse));
}

// The re-map of MUSL and USF holds the nodes the grid update pressed, no
// others and no fewer. A platen (a half-space) presses a stiff elastic
// layer (E = 1e7, 0.5 x 1 m on 4 x 8 cells) at 0.02 m/s by 9.5 % of its
// height, past a row of particles crossing a row of nodes. Before, the
// re-map held a node only where the re-mapped velocity pressed it: on one
// side of each swing after a crossing, so the stress update squeezed the
// top particles step after step where they did not move. The energy grew
// by 10.6 times the platen's work with linear shape functions under MUSL,
// by 0.95 times with uGIMP and 1.0 % with the B-spline; under USF by 1.18
// times and 1.1 %. USF re-maps before its grid update and holds the
// nodes the last step's pressed. Now MUSL and USF close the energy
// balance as USL does (seen 1.1e-3 of the platen's work at most; 0.5 %)
// with uGIMP and the B-spline, and MUSL with linear shape functions loses
// energy at the crossing (cell-crossing noise, 17 % as under USL) but
// never gains more than 0.5 %. (USF with linear shape functions throws
// particles out of this layer under its own weight, without a platen.)
// The platen carries what the layer's lower half does, within 1 % with
// the smooth kernels (equilibrium; the weightless layer's stress is
// uniform; 9-11 % off before with uGIMP).
TEST(RigidBody, ReMapHoldsTheNodesTheGridUpdatePressed)
{
  for (const std::string scheme : {"MUSL", "USF"})
    for (const std::string kernel : {"linear", "uGIMP", "quadratic B-spline"})
      {
        if (scheme == "USF" && kernel == "linear")
          continue;
        auto simulation = test::make_simulation<2>(R"(
set Effects = rigid body
subsection Rigid body
  set Shape      = half-space
  set Point      = 0, 1
  set Normal     = 0, -1
  set Velocity   = 0; -0.02
  set Load curve = 0: 0, 0.5: 1
end
subsection MPM
  set Stress update  = )" + scheme + R"(
  set Shape function = )" + kernel + R"(
end
subsection Grid
  set Upper corner        = 0.5, 1.25
  set Cells               = 4, 10
  set Boundary conditions = 0: slip, 1: slip, 2: slip
end
subsection Material 1
  set Density = 1800
  subsection linear elastic
    set Young's modulus = 1e7
    set Poisson's ratio = 0.3
  end
end
subsection Body 1
  set Upper corner = 0.5, 1
end
)");
        const CoreFields &f    = simulation->particle_set().fields;
        double            gain = 0, loss = 0, worst_force = 0;
        while (simulation->time() < 5)
          {
            simulation->advance(simulation->time_step());
            // From the first second on: the platen's work is then 140 J.
            if (simulation->time() < 1)
              continue;
            const Statistics s  = simulation->statistics();
            const double     in = simulation->external_work();
            const double     balance =
              (s.kinetic_energy + s.strain_energy + s.dissipated_work - in) /
              in;
            gain           = std::max(gain, balance);
            loss           = std::min(loss, balance);
            double sums[2] = {0, 0};
            for (const auto &p : simulation->particle_set().handler)
              if (p.get_location()[1] < 0.4)
                {
                  sums[0] -= p.get_properties()[f.stress + 1];
                  sums[1] += 1;
                }
            const double force = test::effect_column(s, "rigid_force_y") / 0.5;
            worst_force =
              std::max(worst_force, std::abs(force / (sums[0] / sums[1]) - 1));
          }
        std::cout << "rigid body, oedometer, " << scheme << ", " << kernel
                  << ": energy balance from " << loss << " to " << gain
                  << " of the platen's work; force / the lower half's "
                     "stress within "
                  << worst_force << std::endl;
        EXPECT_LT(gain, 0.005) << scheme << ", " << kernel;
        if (kernel != "linear")
          {
            EXPECT_GT(loss, -0.005) << scheme << ", " << kernel;
            EXPECT_LT(worst_force, 0.01) << scheme << ", " << kernel;
          }
      }
}
