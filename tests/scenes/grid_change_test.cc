// The grid can change during a run: refining every cell that holds
// particles keeps the particles (mass, momentum), gives shape functions that
// are a partition of unity on the new grid, and the step after it conserves
// what it should. Runs on 1 rank and, through ctest, on 2.
#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  std::string
  block(const std::string &kernel)
  {
    return "set Effects = gravity\nsubsection Grid\n set Cells = 8, 8\nend\n"
           "subsection MPM\n set Shape function = " +
           kernel +
           "\nend\nsubsection Body 1\n set Lower corner = 0.3, 0.3\n"
           " set Upper corner = 0.6, 0.55\n set Velocity = 1, 0.5\nend\n";
  }

  void
  refine_and_step(const std::string &kernel)
  {
    SCOPED_TRACE(kernel);
    auto simulation = test::make_simulation<2>(block(kernel));
    for (unsigned int i = 0; i < 3; ++i)
      simulation->advance(simulation->time_step());
    const Statistics before = simulation->statistics();
    const auto       n_cells =
      simulation->background_grid().triangulation.n_global_active_cells();
    const double dt_before = simulation->time_step();

    simulation->change_grid([&](Triangulation<2> &) {
      for (const GridCell<2> &c : simulation->background_grid().cells)
        if (simulation->particle_set().handler.n_particles_in_cell(c.cell) > 0)
          c.cell->set_refine_flag();
    });
    const BackgroundGrid<2> &grid = simulation->background_grid();
    EXPECT_GT(grid.triangulation.n_global_active_cells(), n_cells);
    EXPECT_LT(simulation->time_step(), 0.75 * dt_before);

    // Nothing lost, nothing duplicated, nothing changed.
    const Statistics after = simulation->statistics();
    EXPECT_EQ(after.n_particles, before.n_particles);
    EXPECT_DOUBLE_EQ(after.mass, before.mass);
    for (unsigned int d = 0; d < 2; ++d)
      EXPECT_NEAR(after.momentum[d], before.momentum[d], 1e-14 * before.mass);
    EXPECT_DOUBLE_EQ(after.kinetic_energy, before.kinetic_energy);

    // Partition of unity on the new grid (hanging nodes included).
    Stencil<2> stencil;
    simulation->get_kernel().compute_stencil(grid,
                                             simulation->particle_set(),
                                             stencil);
    ASSERT_FALSE(stencil.failed);
    for (std::size_t k = 0; k + 1 < stencil.begin.size(); ++k)
      {
        double       sum = 0;
        Tensor<1, 2> gradient_sum;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          {
            sum += stencil.N[e];
            gradient_sum += stencil.grad_N[e];
          }
        EXPECT_NEAR(sum, 1., 1e-12);
        EXPECT_NEAR(gradient_sum.norm(), 0., 1e-9);
      }

    // The step after: the nodes carry the whole mass, and momentum changes
    // by gravity's impulse only (no walls touched).
    const double dt = simulation->time_step();
    simulation->advance(dt);
    EXPECT_NEAR(simulation->nodal_fields().mass.l1_norm(),
                before.mass,
                1e-12 * before.mass);
    const Statistics next = simulation->statistics();
    EXPECT_NEAR(next.momentum[0], before.momentum[0], 1e-12 * before.mass);
    EXPECT_NEAR(next.momentum[1],
                before.momentum[1] - 9.81 * dt * before.mass,
                1e-12 * before.mass);
  }
} // namespace

TEST(GridChange, RefiningCellsWithParticlesKeepsThemAndTheNextStep)
{
  for (const std::string kernel : {"linear", "uGIMP", "CPDI"})
    refine_and_step(kernel);
}
