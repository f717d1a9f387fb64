// Slip walls: a block sliding along a floor keeps its momentum, on a straight
// floor and also when the floor's faces meet at a tiny kink (a curved or
// imperfect Gmsh boundary), where a node must get one averaged normal, not
// two (which would fix it).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const std::string kinked_mesh =
    DEALMPM_SOURCE_DIR "/tests/data/kinked_square.msh";

  /** The kinked square with its kink straightened (node 2 from y = -1e-4
   * to 0): the same cells and boundary ids on a flat floor, so that the two
   * runs differ only by the kink. Returns the file's path. */
  std::string
  straightened_copy()
  {
    std::ifstream     in(kinked_mesh);
    std::stringstream text;
    text << in.rdbuf();
    std::string       mesh = text.str();
    const std::string kink = "\n2 0.5 -1e-4 0\n";
    const auto        at   = mesh.find(kink);
    if (at == std::string::npos)
      throw std::runtime_error(kinked_mesh + " has no kinked node 2");
    mesh.replace(at, kink.size(), "\n2 0.5 0 0\n");
    const std::string file =
      (std::filesystem::temp_directory_path() /
       ("dealmpm_straight_square_" + std::to_string(getpid()) + ".msh"))
        .string();
    std::ofstream(file) << mesh;
    return file;
  }

  double
  momentum_kept(const std::string &mesh_file)
  {
    auto simulation = test::make_simulation<2>(
      "set Effects = gravity\nsubsection Grid\n set Type = mesh file\n"
      " set Mesh file = " +
      mesh_file +
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
  const std::string straight_mesh = straightened_copy();
  const double      straight      = momentum_kept(straight_mesh);
  std::filesystem::remove(straight_mesh);
  const double kinked = momentum_kept(kinked_mesh);
  std::cout << "slip: momentum kept on the straight floor: " << straight
            << ", on the kinked floor: " << kinked << std::endl;
  // Gravity is normal to a straight floor: nothing changes the momentum
  // along it.
  EXPECT_NEAR(straight, 1., 1e-10);
  // The kink tilts the floor by 2e-4 rad: gravity pulls the block along
  // it by at most g * 2e-4 * t / 0.2 = 2.5e-3 of its momentum.
  EXPECT_NEAR(kinked, 1., 3e-3);
}
