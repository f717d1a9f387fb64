// Surface loads take exactly the face they are given. A bar's end, a
// block's top face and a thin bar's end in 3D, selected the way a user
// does ('x > ...'), hold surface particles at corners, whose side faces
// must not carry the load:
// - the loaded area is the face's own (end of a bar one cell high, top of
//   a block with its corner particles, a 3D bar's end and a 3D top face);
// - at rest, the mean stress of a body is the first moment of its loads
//   over its volume (the supports sit at x = 0 or y = 0 and add nothing):
//   a bar pulled at its end carries the traction, a block pressed on its
//   top carries -p vertically and nothing sideways;
// - a selection whose faces face several ways and that leaves part of the
//   surface out is refused unless the face normal is given.
#include <deal.II/base/mpi.h>

#include <dealmpm/base/errors.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double load = 1e4; // Pa

  /** A bar of length 0.4 and one 0.01 cell across, in a grid of 0.5 along
   * x, fixed at x = 0 and between slip walls, pulled at its end (particles
   * with x > 0.395) by a traction ramped over 0.1 s, damped. */
  template <int dim>
  std::string
  pulled_bar(const std::string &face_normal)
  {
    const std::string  across = dim == 2 ? "0.01" : "0.01, 0.01";
    std::ostringstream s;
    s << "set Effects = traction, local damping\n"
      << "subsection Traction\n set Bodies = 1\n"
      << " set Surface selection = x > 0.395\n"
      << " set Face normal = " << face_normal << "\n"
      << " set Traction = " << load << (dim == 2 ? "; 0" : "; 0; 0") << "\n"
      << " set Load curve = 0: 0, 0.1: 1\nend\n"
      << "subsection Local damping\n set Coefficient = 0.2\nend\n"
      << "subsection MPM\n set Velocity update = PIC\nend\n"
      << "subsection Grid\n set Upper corner = 0.5, " << across << "\n"
      << " set Cells = 50, " << (dim == 2 ? "1" : "1, 1") << "\n"
      << " set Boundary conditions = 0: no-slip, 2: slip, 3: slip"
      << (dim == 3 ? ", 4: slip, 5: slip" : "") << "\nend\n"
      << "subsection Material 1\n set Density = 1000\n"
      << " subsection linear elastic\n  set Young's modulus = 1e6\n"
      << "  set Poisson's ratio = 0.3\n end\nend\n"
      << "subsection Body 1\n set Upper corner = 0.4, " << across << "\nend\n";
    return s.str();
  }

  /** A block of 0.2 (x from 0.1 to 0.3, y and z from 0) on the slip floor
   * of a 0.4 grid of 0.0125 cells (2 particles per direction: the top two
   * rows have y > 0.19), pressed on its top (y > 0.19, or z > 0.19 in 3D)
   * by a pressure ramped over 0.1 s, damped. */
  template <int dim>
  std::string
  pressed_block(const std::string &face_normal, const unsigned int cells = 32)
  {
    const char         up = dim == 2 ? 'y' : 'z';
    std::ostringstream s;
    s << "set Effects = traction, local damping\n"
      << "subsection Traction\n set Bodies = 1\n"
      << " set Surface selection = " << up << " > 0.19\n"
      << " set Face normal = " << face_normal << "\n"
      << " set Pressure = " << load << "\n"
      << " set Load curve = 0: 0, 0.1: 1\nend\n"
      << "subsection Local damping\n set Coefficient = 0.2\nend\n"
      << "subsection MPM\n set Velocity update = PIC\nend\n"
      << "subsection Grid\n set Upper corner = "
      << (dim == 2 ? "0.4, 0.4" : "0.4, 0.4, 0.4") << "\n"
      << " set Cells = " << cells << ", " << cells
      << (dim == 3 ? ", " + std::to_string(cells) : "") << "\n"
      << " set Boundary conditions = " << (dim == 2 ? "2" : "4")
      << ": slip\nend\n"
      << "subsection Material 1\n set Density = 1000\n"
      << " subsection linear elastic\n  set Young's modulus = 1e6\n"
      << "  set Poisson's ratio = 0.3\n end\nend\n"
      << "subsection Body 1\n set Lower corner = "
      << (dim == 2 ? "0.1, 0" : "0.1, 0.1, 0")
      << "\n set Upper corner = " << (dim == 2 ? "0.3, 0.2" : "0.3, 0.3, 0.2")
      << "\nend\n";
    return s.str();
  }

  /** The loaded faces' area vector and area, summed over all ranks. */
  template <int dim>
  std::array<double, dim + 1>
  loaded_area(Simulation<dim> &simulation)
  {
    const ParticleSet<dim>     &particles = simulation.particle_set();
    const unsigned int          area = particles.layout.offset("surface_area");
    const unsigned int          size = particles.layout.offset("surface_size");
    std::array<double, dim + 1> sums{};
    for (const auto &p : particles.handler)
      {
        for (unsigned int d = 0; d < dim; ++d)
          sums[d] += p.get_properties()[area + d];
        sums[dim] += p.get_properties()[size];
      }
    Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()),
                        MPI_COMM_WORLD,
                        ArrayView<double>(sums.data(), sums.size()));
    return sums;
  }

  /** Volume-weighted mean of the particles' stress. */
  template <int dim>
  SymmetricTensor<2, dim>
  mean_stress(Simulation<dim> &simulation)
  {
    const CoreFields       &f = simulation.particle_set().fields;
    SymmetricTensor<2, dim> sum;
    double                  volume = 0;
    for (const auto &p : simulation.particle_set().handler)
      {
        const auto   props = p.get_properties();
        const double V =
          props[f.initial_volume] *
          determinant(read_tensor<dim>(&props[f.deformation_gradient]));
        sum += V * read_symmetric<dim>(&props[f.stress]);
        volume += V;
      }
    return Utilities::MPI::sum(sum, MPI_COMM_WORLD) /
           Utilities::MPI::sum(volume, MPI_COMM_WORLD);
  }

  template <int dim>
  void
  expect_loaded(const std::string    &scene,
                const Tensor<1, dim> &area_vector,
                const double          area,
                const std::string    &what)
  {
    auto simulation                        = test::make_simulation<dim>(scene);
    const std::array<double, dim + 1> sums = loaded_area(*simulation);
    for (unsigned int d = 0; d < dim; ++d)
      EXPECT_NEAR(sums[d], area_vector[d], 1e-12)
        << what << ", component " << d;
    EXPECT_NEAR(sums[dim], area, 1e-12) << what;
  }
} // namespace

// Areas per metre of depth in 2D. A particle's sub-cell is 0.005 across in
// the bars, 0.00625 in the blocks.
TEST(SurfaceLoad, LoadsTheAreaOfTheFaceAsked)
{
  // The bar's end: 0.01 high. Its two particles are corners; their top and
  // bottom faces must not count (the lumped area vector made it sqrt 2).
  expect_loaded<2>(pulled_bar<2>("1, 0"),
                   Tensor<1, 2>({0.01, 0}),
                   0.01,
                   "2D bar end");
  // Every face of the selected particles: end, top and bottom.
  expect_loaded<2>(pulled_bar<2>("all"),
                   Tensor<1, 2>({0.01, 0}),
                   0.02,
                   "2D bar end, all faces");
  expect_loaded<3>(pulled_bar<3>("1, 0, 0"),
                   Tensor<1, 3>({1e-4, 0, 0}),
                   1e-4,
                   "3D bar end");
  // A block's top face: 0.2 wide, with the side faces of the top two rows'
  // corner particles left out.
  expect_loaded<2>(pressed_block<2>("0, 1"),
                   Tensor<1, 2>({0, 0.2}),
                   0.2,
                   "2D top face");
  expect_loaded<3>(pressed_block<3>("0, 0, 1"),
                   Tensor<1, 3>({0, 0, 0.04}),
                   0.04,
                   "3D top face");
  // A face normal at an angle: the faces facing it, by their projection.
  // On the top face only the top faces and the right-hand side faces of
  // the corner particles face (0.6, 0.8): 0.8 of 0.2 and 0.6 of 2 x 0.00625.
  expect_loaded<2>(pressed_block<2>("0.6, 0.8"),
                   Tensor<1, 2>({0.6 * 0.1675, 0.8 * 0.1675}),
                   0.8 * 0.2 + 0.6 * 0.0125,
                   "2D top face, inclined normal");
}

// Without a face normal: the whole surface (the default selection) or
// faces that all face one way are loaded as they are; a selection with
// corners is refused.
TEST(SurfaceLoad, InfersTheFaceOnlyWhenItIsUnambiguous)
{
  std::string scene  = pressed_block<2>("");
  const auto  select = [&](const std::string &expression) {
    std::string s = scene;
    s.replace(s.find("y > 0.19"), 8, expression);
    return s;
  };
  expect_loaded<2>(select("1"), Tensor<1, 2>(), 0.8, "whole surface");
  expect_loaded<2>(select("y > 0.19 & x > 0.11 & x < 0.29"),
                   Tensor<1, 2>({0, 0.175}),
                   0.175,
                   "top without corners");
  try
    {
      test::make_simulation<2>(select("y > 0.19"));
      ADD_FAILURE() << "a selection with corners was accepted";
    }
  catch (const InputError &e)
    {
      const std::string message = e.what();
      std::cout << "surface load: " << message << std::endl;
      EXPECT_NE(message.find("Traction/Face normal"), std::string::npos);
      EXPECT_NE(message.find("-x (0.0125), +x (0.0125), +y (0.2)"),
                std::string::npos);
    }
}

// At rest the bar carries the traction: mean sigma_xx = t (the support at
// x = 0 has no moment). Measured 1.41 t when corner particles counted
// their side faces.
TEST(SurfaceLoad, BarPulledAtItsEndCarriesTheTraction)
{
  auto bar2 = test::make_simulation<2>(pulled_bar<2>("1, 0"));
  test::run_to(*bar2, 0.4);
  auto bar3 = test::make_simulation<3>(pulled_bar<3>("1, 0, 0"));
  test::run_to(*bar3, 0.4);
  const double s2 = mean_stress(*bar2)[0][0], s3 = mean_stress(*bar3)[0][0];
  std::cout << "surface load: bar pulled at its end, mean sigma_xx "
            << s2 / load << " (2D), " << s3 / load << " (3D) of the traction"
            << std::endl;
  // The damped bar's residual motion at t = 0.4 (30 transits after the
  // ramp) is far below 1 %.
  EXPECT_NEAR(s2, load, 0.01 * load);
  EXPECT_NEAR(s3, load, 0.01 * load);
}

// The block pressed on its top carries the load vertically and nothing
// sideways: its sides are free and the floor slips (sigma_xx = -0.05 p
// when the corner particles' side faces were pushed in too). The pressure
// is a dead load on the initial width, and the block widens by nu (1 +
// nu) p / E = 0.39 % (plane strain): sigma_yy = -p / 1.0039.
TEST(SurfaceLoad, BlockPressedOnItsTopHasNoSideStress)
{
  auto block = test::make_simulation<2>(pressed_block<2>("0, 1"));
  test::run_to(*block, 0.4);
  const SymmetricTensor<2, 2> s = mean_stress(*block);
  std::cout << "surface load: block pressed on its top, mean stress "
            << s[0][0] / load << ", " << s[1][1] / load << ", "
            << s[0][1] / load << " of p" << std::endl;
  EXPECT_NEAR(s[0][0], 0, 0.005 * load);
  EXPECT_NEAR(s[1][1], -load / (1 + 0.3 * 1.3 * load / 1e6), 1e-3 * load);
  EXPECT_NEAR(s[0][1], 0, 0.005 * load);
}

// The same in 3D on 16 cells per side (0.025; z > 0.19 holds the top layer
// of particles): sigma_xx = sigma_yy = 0, and sigma_zz = -p over the
// block's widening in two directions, (1 + nu p / E)^2 = 1.006.
TEST(SurfaceLoad, BlockPressedOnItsTopHasNoSideStress3D)
{
  auto block = test::make_simulation<3>(pressed_block<3>("0, 0, 1", 16));
  test::run_to(*block, 0.4);
  const SymmetricTensor<2, 3> s = mean_stress(*block);
  std::cout << "surface load: 3D block pressed on its top, mean stress "
            << s[0][0] / load << ", " << s[1][1] / load << ", "
            << s[2][2] / load << " of p" << std::endl;
  EXPECT_NEAR(s[0][0], 0, 0.005 * load);
  EXPECT_NEAR(s[1][1], 0, 0.005 * load);
  EXPECT_NEAR(s[2][2], -load / std::pow(1 + 0.3 * load / 1e6, 2), 2e-3 * load);
}
