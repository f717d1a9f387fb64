// Slip walls: a block sliding along a floor keeps its momentum, also when the
// floor's faces meet at a tiny kink (a curved or imperfect Gmsh boundary),
// where a node must get one averaged normal, not two (which would fix it).
#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  double
  momentum_kept(const std::string &mesh)
  {
    auto simulation = test::make_simulation<2>(
      "set Effects = gravity\nsubsection Grid\n set Type = mesh file\n"
      " set Mesh file = " DEALMPM_SOURCE_DIR "/tests/data/" +
      mesh +
      "\n set Global refinements = 3\n set Boundary conditions = 12: slip\n"
      "end\nsubsection Body 1\n set Lower corner = 0.1, 0\n"
      " set Upper corner = 0.4, 0.2\n set Velocity = 0.2, 0\nend\n");
    const double initial = simulation->statistics().momentum[0];
    while (simulation->time() < 0.25)
      simulation->advance(simulation->time_step());
    return simulation->statistics().momentum[0] / initial;
  }
} // namespace

TEST(Slip, BlockSlidesFreelyOnStraightAndKinkedFloors)
{
  const double straight = momentum_kept("kinked_square.msh");
  std::cout << "slip: momentum kept on the kinked floor: " << straight
            << std::endl;
  // The kink tilts the floor by 2e-4 rad: gravity pulls the block along
  // it by at most g * 2e-4 * t / 0.2 = 2.5e-3 of its momentum.
  EXPECT_NEAR(straight, 1., 3e-3);
}
