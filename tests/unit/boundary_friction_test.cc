// Coulomb's law at a node, and the boundary nodes it acts on.
#include <deal.II/base/mpi.h>

#include <dealmpm/effects/coulomb_friction.h>
#include <dealmpm/grid/boundary_nodes.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

TEST(CoulombChange, SlipsByMuTimesTheNormalImpulse)
{
  const Tensor<1, 2> n({0., -1.}); // the floor's outward normal
  // Sliding at 1 m/s; the wall took 0.5 m/s off the normal velocity.
  const Tensor<1, 2> change =
    coulomb_change(Tensor<1, 2>({1., 0.}), n, 0.5, 0.2);
  EXPECT_NEAR(change[0], -0.1, 1e-15);
  EXPECT_EQ(change[1], 0.);
}

TEST(CoulombChange, SticksWhenFrictionSuffices)
{
  const Tensor<1, 3> n({0., 0., 1.});
  const Tensor<1, 3> v({0.03, -0.04, 0.});
  const Tensor<1, 3> change = coulomb_change(v, n, 0.5, 0.2);
  EXPECT_NEAR((v + change).norm(), 0., 1e-15);
}

TEST(CoulombChange, NothingWhenTheWallDidNotPush)
{
  const Tensor<1, 2> n({0., -1.});
  const Tensor<1, 2> v({1., 0.});
  EXPECT_EQ(coulomb_change(v, n, 0., 0.5).norm(), 0.);
  EXPECT_EQ(coulomb_change(v, n, -0.3, 0.5).norm(), 0.);
  // The normal part of v is the wall's business, not friction's.
  EXPECT_EQ(coulomb_change(Tensor<1, 2>({0., 2.}), n, 0.3, 0.5).norm(), 0.);
}

// On the unit square (ids 0 left, 1 right, 2 bottom, 3 top), the bottom's
// nodes carry outward normals (0, -1) and areas that sum to its length,
// h at interior nodes and h / 2 at the two ends; nodes of two ids appear
// once per id.
TEST(BoundaryNodes, AreasSumToTheFaceAndPointOutward)
{
  auto simulation = test::make_simulation<2>(
    "subsection Grid\n set Cells = 5, 4\nend\n"
    "subsection Body 1\n set Upper corner = 0.5, 0.5\nend\n");
  const BackgroundGrid<2> &grid   = simulation->background_grid();
  Tensor<1, 2>             bottom = {}, left = {};
  unsigned int             n_bottom = 0;
  for (const BoundaryNode<2> &node : boundary_nodes(grid, {0, 2}))
    {
      EXPECT_NEAR(node.normal().norm(), 1., 1e-15);
      if (node.id == 2)
        {
          bottom += node.area;
          ++n_bottom;
          EXPECT_NEAR(node.normal()[1], -1., 1e-15);
        }
      else
        left += node.area;
    }
  bottom = Utilities::MPI::sum(bottom, MPI_COMM_WORLD);
  left   = Utilities::MPI::sum(left, MPI_COMM_WORLD);
  EXPECT_EQ(Utilities::MPI::sum(n_bottom, MPI_COMM_WORLD), 6u);
  EXPECT_NEAR(bottom[1], -1., 1e-14);
  EXPECT_NEAR(bottom[0], 0., 1e-14);
  EXPECT_NEAR(left[0], -1., 1e-14);
}
