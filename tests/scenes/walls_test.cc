// Walls hold the particles of every kernel: the dam break (a Tait fluid
// column collapsing in a box of slip walls) on a coarse grid, with the
// GIMP kernels, whose particle domain reaches past a wall. Before walls
// held particles, particles next to the floor stepped through it and were
// lost (27 to 32 in the hard-case table's dam break; CPDI loses none). Now none
// is lost, every particle stays in the box, the mass is kept, and the count
// of particles put back shows that the walls did the holding.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  std::string
  coarse_dam_break(const std::string &kernel)
  {
    std::ifstream     file(DEALMPM_SOURCE_DIR "/prm/hard-cases/dam_break.prm");
    std::stringstream text;
    text << file.rdbuf();
    return text.str() +
           "subsection Grid\n set Cells = 56, 20\nend\n"
           "subsection MPM\n set Shape function = " +
           kernel + "\n set Particles leaving the grid = stop\nend\n";
  }
} // namespace

TEST(Walls, HoldTheParticlesOfKernelsWithDomains)
{
  for (const std::string kernel : {"uGIMP", "cpGIMP"})
    {
      auto simulation = test::make_simulation<2>(coarse_dam_break(kernel));
      const Statistics initial = simulation->statistics();
      // 'Particles leaving the grid = remove' (the default): a particle
      // through a wall would be dropped and counted.
      while (simulation->time() < 0.22)
        simulation->advance(simulation->time_step());
      const Statistics end = simulation->statistics();
      std::cout << "walls, " << kernel << ": "
                << simulation->run_state().held_particles
                << " times a particle was put back" << std::endl;
      EXPECT_EQ(simulation->run_state().lost_particles, 0) << kernel;
      EXPECT_EQ(end.n_particles, initial.n_particles) << kernel;
      EXPECT_NEAR(end.mass, initial.mass, 1e-12 * initial.mass) << kernel;
      EXPECT_GT(simulation->run_state().held_particles, 0) << kernel;
      const Point<2> upper(0.40005, 0.142875);
      for (const auto &p : simulation->particle_set().handler)
        for (unsigned int d = 0; d < 2; ++d)
          {
            EXPECT_GE(p.get_location()[d], 0.) << kernel;
            EXPECT_LE(p.get_location()[d], upper[d]) << kernel;
          }
    }
}
