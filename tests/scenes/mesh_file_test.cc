// A Gmsh mesh with distorted (non-affine) cells: boundary ids come from the
// file's physical tags, the Q1 map and its inverse drive the kernels, and a
// body in uniform motion stays rigid (J = 1, displacement v t) while its
// particles cross cells, to round-off.
#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const std::string scene = std::string(R"(
set Dimension = 2
subsection Grid
  set Type = mesh file
  set Mesh file = )") + DEALMPM_SOURCE_DIR +
                            R"(/tests/data/distorted_square.msh
  set Global refinements = 2
  set Boundary conditions = 10: no-slip, 12: slip
end
subsection Material 1
  set Model = neo-Hookean
end
subsection Body 1
  set Lower corner = 0.2, 0.2
  set Upper corner = 0.6, 0.6
  set Particles per cell = 2
  set Velocity = 0.3, 0.1
end
)";
} // namespace

TEST(MeshFile, RigidMotionThroughDistortedCellsIsExact)
{
  auto        simulation = test::make_simulation<2>(scene);
  const auto &grid       = simulation->background_grid();
  EXPECT_FALSE(grid.cartesian);
  unsigned int non_affine = 0;
  for (const auto &c : grid.cells)
    non_affine += !c.affine;
  EXPECT_GT(non_affine, 0u);
  const auto ids = grid.triangulation.get_boundary_ids();
  EXPECT_EQ(std::vector<types::boundary_id>(ids.begin(), ids.end()),
            (std::vector<types::boundary_id>{10, 11, 12, 13}));

  const double n_particles = simulation->statistics().n_particles;
  const double dt          = 2e-3;
  for (unsigned int step = 0; step < 250; ++step)
    simulation->advance(dt);
  const double t = simulation->time();

  const auto       &particles   = simulation->particle_set();
  const CoreFields &f           = particles.fields;
  double            max_J_error = 0, max_u_error = 0, max_v_error = 0;
  for (const auto &p : particles.handler)
    {
      const auto props = p.get_properties();
      max_J_error =
        std::max(max_J_error,
                 std::abs(
                   determinant(read_tensor<2>(&props[f.deformation_gradient])) -
                   1));
      const Tensor<1, 2> u = read_vector<2>(&props[f.displacement]);
      const Tensor<1, 2> v = read_vector<2>(&props[f.velocity]);
      max_u_error =
        std::max(max_u_error, (u - t * Tensor<1, 2>({0.3, 0.1})).norm());
      max_v_error =
        std::max(max_v_error, (v - Tensor<1, 2>({0.3, 0.1})).norm());
    }
  EXPECT_EQ(simulation->statistics().n_particles, n_particles);
  EXPECT_LT(max_J_error, 1e-12);
  EXPECT_LT(max_u_error, 1e-12);
  EXPECT_LT(max_v_error, 1e-12);
  EXPECT_GT(t * 0.3, 0.125); // crossed at least one cell
}
