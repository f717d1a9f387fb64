// The generalized vortex (A = 0.1, 2D) at CFL 0.1: the displacement error at
// t = 1 falls with the grid (on 24, 48, 96 cells per side: cpGIMP 0.030,
// 0.0053, 0.0016; CPDI 0.031, 0.0050, 0.0015; quadratic B-spline 0.038,
// 0.0050, 0.0017: rates 1.6-2.9).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

TEST(GeneralizedVortex, ErrorConverges)
{
  for (const std::string kernel : {"cpGIMP", "CPDI", "quadratic B-spline"})
    {
      const auto error = [&](const unsigned int n) {
        std::ifstream file(DEALMPM_SOURCE_DIR "/prm/generalized_vortex.prm");
        std::stringstream text;
        text << file.rdbuf() << "\nsubsection Grid\n set Cells = " << n << ", "
             << n << "\nend\nsubsection Time\n set CFL number = 0.1\nend\n"
             << "subsection MPM\n set Shape function = " << kernel << "\nend\n";
        auto simulation = test::make_simulation<2>(text.str());
        EXPECT_LT(simulation->statistics().error_max, 1e-14);
        while (simulation->time() < 1. - 1e-12)
          simulation->advance(
            std::min(simulation->time_step(), 1. - simulation->time()));
        return simulation->statistics().error_L2;
      };
      const double coarse = error(24), medium = error(48), fine = error(96);
      std::cout << "generalized vortex, " << kernel
                << ": L2 error at 24, 48, 96 cells: " << coarse << ", "
                << medium << ", " << fine << std::endl;
      EXPECT_LT(medium, coarse) << kernel;
      EXPECT_GE(std::log2(medium / fine), 1.5) << kernel;
    }
}
