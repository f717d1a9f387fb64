// The axis-aligned manufactured solution (Wallstedt and Guilkey 2008) in 2D
// with linear shape functions: exact at t = 0 (the pre-deformed initial
// state), and the displacement error after one period falls with the grid
// while particles do not cross cell faces much (h = 1/4, 1/8, 1/16: 0.020,
// 0.011, 0.006 seen). On finer grids linear MPM's cell-crossing error stops
// the convergence (0.0058 at 1/32, 0.0084 at 1/64): the reason for GIMP,
// CPDI and B-splines. USL and MUSL both.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  Statistics
  run_period(const unsigned int cells,
             const std::string &scheme,
             Statistics        *initial)
  {
    std::ifstream file(DEALMPM_SOURCE_DIR "/prm/manufactured_solution_2d.prm");
    std::stringstream text;
    text << file.rdbuf() << "\nsubsection Grid\n set Cells = " << cells << ", "
         << cells << "\nend\nsubsection MPM\n set Stress update = " << scheme
         << "\nend\n";
    auto simulation = test::make_simulation<2>(text.str());
    if (initial != nullptr)
      *initial = simulation->statistics();
    while (simulation->time() < 0.02 - 1e-12)
      simulation->advance(
        std::min(simulation->time_step(), 0.02 - simulation->time()));
    return simulation->statistics();
  }
} // namespace

TEST(ManufacturedSolution, ErrorFallsWithTheGrid2D)
{
  for (const std::string scheme : {"USL", "MUSL"})
    {
      Statistics   initial;
      const double coarse = run_period(4, scheme, &initial).error_L2;
      const double medium = run_period(8, scheme, nullptr).error_L2;
      const double fine   = run_period(16, scheme, nullptr).error_L2;
      std::cout << "manufactured solution, linear, " << scheme
                << ": L2 displacement error at h = 1/4, 1/8, 1/16: " << coarse
                << ", " << medium << ", " << fine << std::endl;
      ASSERT_TRUE(initial.has_error);
      EXPECT_LT(initial.error_max, 1e-15);
      EXPECT_LT(medium, 0.7 * coarse);
      EXPECT_LT(fine, 0.7 * medium);
    }
}
