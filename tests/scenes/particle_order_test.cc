// The step's particle order (ParticleSet::order_over, the handles into
// deal.II's property pool that every sweep visits) lists each of this
// rank's particles once, under the cell the handler has it in, in the
// grid's cell order, with the handler's own data: after the set-up, after
// particles moved cells and were sorted, after a grid change with
// particle splitting, and along a run whose particles cross cells.
// Runs on 1 rank and, through ctest, on 2.
#include <dealmpm/adaptivity/split_particles.h>
#include <dealmpm/transfer/stencil_order.h>

#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** Visit the particles in the step's order and compare each with what
   * the handler says of it: its cell, location and first property. */
  template <int dim>
  void
  expect_order_matches_handler(const BackgroundGrid<dim> &grid,
                               const ParticleSet<dim>    &particles)
  {
    struct Seen
    {
      std::size_t cell;
      Point<dim>  x;
      double      mass;
    };
    std::map<types::particle_index, Seen> handler_view;
    for (std::size_t i = 0; i < grid.cells.size(); ++i)
      for (const auto &p :
           particles.handler.particles_in_cell(grid.cells[i].cell))
        handler_view[p.get_id()] = {i,
                                    p.get_location(),
                                    p.get_properties()[particles.fields.mass]};
    ASSERT_EQ(handler_view.size(),
              particles.handler.n_locally_owned_particles());

    std::map<types::particle_index, unsigned int> visits;
    std::size_t                                   previous_cell = 0;
    unsigned int                                  wrong         = 0;
    const std::size_t n = for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t, const auto &p, const GridCell<dim> &c) {
        const std::size_t cell = index_in_grid(grid, c);
        const auto        it   = handler_view.find(p.get_id());
        ++visits[p.get_id()];
        wrong += it == handler_view.end() || it->second.cell != cell ||
                 it->second.x != p.get_location() ||
                 it->second.mass != p.get_properties()[particles.fields.mass] ||
                 cell < previous_cell;
        previous_cell = cell;
      });
    EXPECT_EQ(n, handler_view.size());
    EXPECT_EQ(visits.size(), handler_view.size());
    EXPECT_EQ(wrong, 0u);
    for (const auto &[id, count] : visits)
      ASSERT_EQ(count, 1u) << "particle " << id;
  }

  template <int dim>
  std::unique_ptr<Simulation<dim>>
  moving_block()
  {
    const std::string grid =
      dim == 2 ? "set Cells = 8, 8\n" : "set Cells = 4, 4, 4\n";
    const std::string box =
      dim == 2 ? " set Lower corner = 0.3, 0.3\n set Upper corner = 0.6, "
                 "0.55\n set Velocity = 1, 0.5\n" :
                 " set Lower corner = 0.2, 0.3, 0.3\n set Upper corner = "
                 "0.45, 0.55, 0.7\n set Velocity = 1, 0.5, -0.2\n";
    return test::make_simulation<dim>(
      "set Dimension = " + std::to_string(dim) + "\nsubsection Grid\n" + grid +
      "end\nsubsection Body 1\n" + box + "end\n");
  }

  template <int dim>
  void
  order_follows_the_particles()
  {
    SCOPED_TRACE(std::to_string(dim) + "D");
    auto                       simulation = moving_block<dim>();
    const BackgroundGrid<dim> &grid       = simulation->background_grid();
    ParticleSet<dim>          &particles  = simulation->particle_set();
    expect_order_matches_handler(grid, particles);

    // Every particle moved by three quarters of a cell's width in x: most
    // change cell, and the sort renumbers the pool.
    const double h = grid.cells.front().h;
    for (auto &p : particles.handler)
      {
        Point<dim> x = p.get_location();
        x[0] += 0.75 * h;
        p.set_location(x);
      }
    particles.sort();
    expect_order_matches_handler(grid, particles);

    // A run that moves the block across cells (the step's relocation).
    for (unsigned int i = 0; i < 8; ++i)
      {
        simulation->advance(simulation->time_step());
        expect_order_matches_handler(grid, particles);
      }

    // A grid change (every cell refined) and the particles split into
    // the new cells.
    simulation->change_grid([&](Triangulation<dim> &) {
      for (const GridCell<dim> &c : simulation->background_grid().cells)
        c.cell->set_refine_flag();
    });
    expect_order_matches_handler(simulation->background_grid(), particles);
    split_particles(simulation->background_grid(), particles, 2);
    expect_order_matches_handler(simulation->background_grid(), particles);
    simulation->advance(simulation->time_step());
    expect_order_matches_handler(simulation->background_grid(), particles);
  }
} // namespace

TEST(ParticleOrder, FollowsSortsRunsAndGridChanges2D)
{
  order_follows_the_particles<2>();
}

TEST(ParticleOrder, FollowsSortsRunsAndGridChanges3D)
{
  order_follows_the_particles<3>();
}
