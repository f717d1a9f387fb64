// The axis-aligned manufactured solution (Wallstedt and Guilkey 2008) in 2D
// with linear shape functions: exact at t = 0 (the pre-deformed initial
// state), and the displacement error after one period falls with the grid
// while particles do not cross cell faces much (h = 1/4, 1/8, 1/16: 0.020,
// 0.011, 0.006 seen). On finer grids linear MPM's cell-crossing error stops
// the convergence (0.0058 at 1/32, 0.0084 at 1/64): the reason for GIMP,
// CPDI and B-splines. USL and MUSL both.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  Statistics
  run_period(const unsigned int cells,
             const std::string &scheme,
             Statistics        *initial,
             const std::string &more = "")
  {
    std::ifstream file(DEALMPM_SOURCE_DIR "/prm/manufactured_solution_2d.prm");
    std::stringstream text;
    text << file.rdbuf() << "\nsubsection Grid\n set Cells = " << cells << ", "
         << cells << "\nend\nsubsection MPM\n set Stress update = " << scheme
         << "\nend\n"
         << more;
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

TEST(ManufacturedSolution, GIMPCPDIAndBSplineConvergeAtSecondOrder2D)
{
  // GIMP, CPDI and the B-spline remove the cell-crossing error: L2 errors at
  // small CFL (0.1) for h = 1/8, 1/16, 1/32: uGIMP 6.8e-3, 1.6e-3, 4.5e-4;
  // cpGIMP 6.9e-3, 1.6e-3, 3.8e-4; CPDI 7.1e-3, 1.7e-3, 4.1e-4; B-spline
  // 8.5e-3, 2.2e-3, 5.9e-4 (observed rates 1.9-2.1; the issue asks >= 1.5).
  for (const std::string kernel :
       {"uGIMP", "cpGIMP", "CPDI", "quadratic B-spline"})
    {
      const auto error = [&](const unsigned int cells) {
        return run_period(
                 cells,
                 "USL",
                 nullptr,
                 "subsection MPM\n set Shape function = " + kernel +
                   "\nend\nsubsection Time\n set CFL number = 0.1\nend\n")
          .error_L2;
      };
      const double coarse = error(8), medium = error(16), fine = error(32);
      const double rate = std::log2(medium / fine);
      std::cout << "manufactured solution, " << kernel
                << ": L2 error at h = 1/8, 1/16, 1/32: " << coarse << ", "
                << medium << ", " << fine << "; rate " << rate << std::endl;
      EXPECT_LT(medium, coarse);
      EXPECT_GE(rate, 1.5) << kernel;
    }
}

TEST(ManufacturedSolution, CpGIMPCPDIAndBSplineConverge3D)
{
  // 3D, CFL 0.1, L2 errors at h = 1/8, 1/16: cpGIMP 7.0e-3, 1.6e-3 (rate
  // 2.08); CPDI 7.1e-3, 1.7e-3 (2.04); quadratic B-spline 8.6e-3, 2.2e-3
  // (1.96); linear: 1.2e-2, 8.3e-3.
  for (const std::string kernel : {"cpGIMP", "CPDI", "quadratic B-spline"})
    {
      const auto error = [&](const unsigned int n) {
        std::ifstream     file(DEALMPM_SOURCE_DIR
                           "/prm/manufactured_solution_3d.prm");
        std::stringstream text;
        text << file.rdbuf() << "\nsubsection Grid\n set Cells = " << n << ", "
             << n << ", " << n
             << "\nend\nsubsection MPM\n set Shape function = " << kernel
             << "\nend\nsubsection Time\n set CFL number = 0.1\nend\n";
        auto simulation = test::make_simulation<3>(text.str());
        while (simulation->time() < 0.02 - 1e-12)
          simulation->advance(
            std::min(simulation->time_step(), 0.02 - simulation->time()));
        return simulation->statistics().error_L2;
      };
      const double coarse = error(8), fine = error(16);
      std::cout << "manufactured solution 3D, " << kernel
                << ": L2 error at h = 1/8, 1/16: " << coarse << ", " << fine
                << "; rate " << std::log2(coarse / fine) << std::endl;
      EXPECT_GE(std::log2(coarse / fine), 1.5) << kernel;
    }
}
