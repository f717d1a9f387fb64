// The step's particle order (ParticleSet::order_over, the handles into
// deal.II's property pool that every sweep visits) lists each of this
// rank's particles once, under the cell the handler has it in, in the
// grid's cell order, with the handler's own data: after the set-up, after
// particles moved cells and were sorted, after a grid change with
// particle splitting, and along a run whose particles cross cells.
// ParticleSet::relocate (the step's own move of particles into neighbour
// cells) leaves every particle where deal.II's sort would put it, and the
// neighbour tables it searches hold what deal.II's vertex-to-cell map does.
// Runs on 1 rank and, through ctest, on 2.
#include <deal.II/base/geometry_info.h>
#include <deal.II/grid/grid_tools.h>

#include <dealmpm/adaptivity/split_particles.h>
#include <dealmpm/transfer/stencil_order.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** Visit the particles in the step's order and compare each with what
   * the handler says of it: its location and first property, and its cell
   * unless the handler's lists lag behind the order (relocate() moved
   * particles since deal.II last sorted them). The order runs through the
   * cells in the grid's order and through each cell's particles by id
   * (the order of sums a run gives whether it relocated or sorted). */
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
    const bool                            lags = particles.handler_lags_order();
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
    std::size_t                                   n_seen        = 0;
    std::size_t                                   previous_cell = 0;
    types::particle_index                         previous_id   = 0;
    unsigned int                                  wrong         = 0;
    const std::size_t n = for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t, const auto &p, const GridCell<dim> &c) {
        const std::size_t cell = index_in_grid(grid, c);
        const auto        it   = handler_view.find(p.get_id());
        ++visits[p.get_id()];
        wrong +=
          it == handler_view.end() || (!lags && it->second.cell != cell) ||
          it->second.x != p.get_location() ||
          it->second.mass != p.get_properties()[particles.fields.mass] ||
          cell < previous_cell ||
          (n_seen > 0 && cell == previous_cell && p.get_id() <= previous_id);
        previous_cell = cell;
        previous_id   = p.get_id();
        ++n_seen;
      });
    EXPECT_EQ(n, handler_view.size());
    EXPECT_EQ(visits.size(), handler_view.size());
    EXPECT_EQ(wrong, 0u);
    for (const auto &[id, count] : visits)
      ASSERT_EQ(count, 1u) << "particle " << id;
  }

  /** Every particle lies in the cell the step's order has it in: its
   * reference location is in the unit cell (up to the 1e-12 by which the
   * step lets a particle overstep a face before it relocates) and maps to
   * its location. */
  template <int dim>
  void
  expect_particles_in_their_cells(const BackgroundGrid<dim> &grid,
                                  const ParticleSet<dim>    &particles)
  {
    unsigned int wrong = 0;
    for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t, const auto &p, const GridCell<dim> &c) {
        const Point<dim> xi = p.get_reference_location();
        wrong += !GeometryInfo<dim>::is_inside_unit_cell(xi, 1e-12) ||
                 c.real_point(xi).distance(p.get_location()) > 1e-12 * c.h;
      });
    EXPECT_EQ(wrong, 0u);
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
        expect_particles_in_their_cells(grid, particles);
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

namespace
{
  /** Where each particle is: its cell's index, its reference location,
   * location and mass. */
  template <int dim>
  using Places =
    std::map<types::particle_index,
             std::tuple<unsigned int, Point<dim>, Point<dim>, double>>;

  /** From the step's order, or (@p from_handler) from deal.II's lists. */
  template <int dim>
  Places<dim>
  places(const BackgroundGrid<dim> &grid,
         const ParticleSet<dim>    &particles,
         const bool                 from_handler)
  {
    Places<dim> result;
    const auto  add = [&](const auto &p, const unsigned int cell) {
      result[p.get_id()] = {cell,
                            p.get_reference_location(),
                            p.get_location(),
                            p.get_properties()[particles.fields.mass]};
    };
    if (from_handler)
      for (const auto &p : particles.handler)
        add(p, p.get_surrounding_cell()->active_cell_index());
    else
      for_each_particle_in_stencil_order(grid,
                                         particles,
                                         [&](const std::size_t,
                                             const auto          &p,
                                             const GridCell<dim> &c) {
                                           add(p, c.cell->active_cell_index());
                                         });
    return result;
  }

  /** The same particles in the same cells at the same reference locations
   * (1e-12 of the unit cell: both invert the same affine map, in
   * different order). */
  template <int dim>
  void
  expect_same_places(const Places<dim> &a, const Places<dim> &b)
  {
    ASSERT_EQ(a.size(), b.size());
    unsigned int differ = 0;
    for (const auto &[id, place] : a)
      {
        const auto &other = b.at(id);
        differ += std::get<0>(place) != std::get<0>(other) ||
                  std::get<1>(place).distance(std::get<1>(other)) > 1e-12 ||
                  std::get<2>(place) != std::get<2>(other) ||
                  std::get<3>(place) != std::get<3>(other);
      }
    EXPECT_EQ(differ, 0u);
  }

  /** Move every particle by up to @p reach cell widths along each axis, in
   * a direction that depends on its id: most change cell, to every side
   * and across corners. */
  template <int dim>
  void
  scatter(ParticleSet<dim> &particles, const double h, const double reach)
  {
    for (auto &p : particles.handler)
      {
        Point<dim> x = p.get_location();
        for (unsigned int d = 0; d < dim; ++d)
          x[d] += reach * h * std::sin(1.7 * p.get_id() + 2.3 * d + 0.4);
        p.set_location(x);
      }
  }

  /** Two identical scenes, their particles moved alike; one relocated by
   * ParticleSet::relocate, the other by deal.II's sort: each particle must
   * end in the same cell at the same reference location, in the step's
   * order and, once update_handler() brought them up, in deal.II's lists. */
  template <int dim>
  void
  relocation_matches_sort(const bool   refine_half,
                          const double reach,
                          const bool   expect_own)
  {
    SCOPED_TRACE(std::to_string(dim) + "D, reach " + std::to_string(reach) +
                 (refine_half ? ", hanging nodes" : ""));
    auto own = moving_block<dim>(), sorted = moving_block<dim>();
    for (auto *s : {own.get(), sorted.get()})
      {
        if (refine_half)
          s->change_grid([&](Triangulation<dim> &) {
            for (const GridCell<dim> &c : s->background_grid().cells)
              if (c.cell->center()[0] < 0.45)
                c.cell->set_refine_flag();
          });
        double h = 1;
        for (const GridCell<dim> &c : s->background_grid().cells)
          h = std::min(h, c.h);
        scatter(s->particle_set(),
                Utilities::MPI::min(h, MPI_COMM_WORLD),
                reach);
      }
    // The step's grid, which relocate() may give its neighbour tables (the
    // Simulation owns it as non-const).
    auto &grid = const_cast<BackgroundGrid<dim> &>(own->background_grid());
    EXPECT_EQ(own->particle_set().relocate(grid), expect_own);
    sorted->particle_set().sort();

    ParticleSet<dim> &particles = own->particle_set();
    EXPECT_EQ(particles.handler_lags_order(), expect_own);
    expect_order_matches_handler(grid, particles);
    expect_particles_in_their_cells(grid, particles);
    const Places<dim> truth =
      places(sorted->background_grid(), sorted->particle_set(), true);
    expect_same_places(places(grid, particles, false), truth);

    particles.update_handler(grid);
    EXPECT_FALSE(particles.handler_lags_order());
    expect_same_places(places(grid, particles, true), truth);
    expect_order_matches_handler(grid, particles);
  }
} // namespace

// An effect's initial state may move particles: the manufactured solution
// starts deformed, by up to 0.7 of a cell here. The set-up notices without
// a copy of the locations (each untouched particle is still where its
// reference location puts it) and sorts: every particle starts inside the
// cell the step lists it in, at its reference location.
TEST(ParticleOrder, SetUpSortsWhatAnEffectMoved)
{
  std::ifstream file(DEALMPM_SOURCE_DIR "/prm/manufactured_solution_2d.prm");
  std::stringstream text;
  text << file.rdbuf() << "\nsubsection Grid\n set Cells = 16, 16\nend\n";
  auto                     simulation = test::make_simulation<2>(text.str());
  const BackgroundGrid<2> &grid       = simulation->background_grid();
  const ParticleSet<2>    &particles  = simulation->particle_set();
  unsigned int             crossed    = 0;
  for_each_particle_in_stencil_order(
    grid,
    particles,
    [&](const std::size_t, const auto &p, const GridCell<2> &c) {
      const Point<2> X =
        p.get_location() -
        read_vector<2>(&p.get_properties()[particles.fields.displacement]);
      crossed += !GeometryInfo<2>::is_inside_unit_cell(c.reference_point(X));
    });
  EXPECT_GT(Utilities::MPI::sum(crossed, MPI_COMM_WORLD), 0u);
  expect_particles_in_their_cells(grid, particles);
  expect_order_matches_handler(grid, particles);
}

// Up to 0.9 cell widths: every particle stays within its old cell's
// neighbours, the step moves them itself (on 2 ranks those that cross into
// the other rank's cells make every rank sort with deal.II).
TEST(Relocation, MatchesDealiiSortIntoNeighbours)
{
  const bool one_rank = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1;
  relocation_matches_sort<2>(false, 0.9, one_rank);
  relocation_matches_sort<3>(false, 0.9, one_rank);
  relocation_matches_sort<2>(true, 0.9, one_rank);
  relocation_matches_sort<3>(true, 0.9, one_rank);
}

// Up to 2.5 cell widths: some go past the neighbours, and deal.II sorts.
TEST(Relocation, LeavesFarMovesToDealiiSort)
{
  relocation_matches_sort<2>(false, 2.5, false);
  relocation_matches_sort<3>(true, 2.5, false);
}

namespace
{
  /** The block moved to the wall x = 0 (boundary id 0); particles pushed
   * past the wall, into neighbour cells and by round-off only: a plan
   * holds some at the wall and sets reference locations, and cancelling it
   * puts back every location, reference location and property to the
   * bit. A relocation afterwards still puts every particle in its cell. */
  template <int dim>
  void
  cancelled_relocation_leaves_no_trace()
  {
    SCOPED_TRACE(std::to_string(dim) + "D");
    auto                 simulation = moving_block<dim>();
    BackgroundGrid<dim> &grid =
      const_cast<BackgroundGrid<dim> &>(simulation->background_grid());
    ParticleSet<dim> &particles = simulation->particle_set();
    const double      h         = grid.cells.front().h;
    // The block moved against the wall x = 0 (its first particles 0.01
    // from it), in cells along the wall.
    double x_min = 1;
    for (const auto &p : particles.handler)
      x_min = std::min(x_min, p.get_location()[0]);
    const double shift = Utilities::MPI::min(x_min, MPI_COMM_WORLD) - 0.01;
    for (auto &p : particles.handler)
      {
        Point<dim> x = p.get_location();
        x[0] -= shift;
        p.set_location(x);
      }
    particles.sort();
    particles.order_over(grid); // the step's order, as a step has it
    // Then a third of the particles by the wall past it, a third by half
    // a cell, a third by 1e-14 of a cell.
    for (auto &p : particles.handler)
      {
        Point<dim>         x    = p.get_location();
        const unsigned int kind = p.get_id() % 3;
        if (kind == 0 && x[0] < 0.5 * h)
          x[0] = -1e-3 * h;
        else
          x[0] += kind == 1 ? 0.5 * h : 1e-14 * h;
        p.set_location(x);
      }
    const auto   before = test::particle_state(particles);
    unsigned int held   = 0;
    particles.plan_relocation(grid, {0}, held);
    EXPECT_GT(Utilities::MPI::sum(held, MPI_COMM_WORLD), 0u);
    // The plan changed particles (on some rank: one may hold none).
    const bool changed = test::particle_state(particles) != before;
    EXPECT_TRUE(Utilities::MPI::logical_or(changed, MPI_COMM_WORLD));
    particles.cancel_relocation();
    EXPECT_EQ(test::particle_state(particles), before);
    expect_order_matches_handler(grid, particles);

    particles.relocate(grid, {0});
    particles.update_handler(grid);
    expect_particles_in_their_cells(grid, particles);
    expect_order_matches_handler(grid, particles);
  }

  /** @p grid's neighbour tables against the cells that share a vertex
   * with each owned cell as deal.II's GridTools::vertex_to_cell_map finds
   * them (hanging vertices included), owned or ghost, in its order: the
   * same pointers in the same order. */
  template <int dim>
  void
  expect_neighbors_as_dealii(BackgroundGrid<dim> &grid)
  {
    grid.clear_neighbors();
    grid.find_neighbors();
    std::map<unsigned int, const GridCell<dim> *> local;
    for (const auto *list : {&grid.cells, &grid.ghost_cells})
      for (const GridCell<dim> &c : *list)
        local[c.cell->active_cell_index()] = &c;
    const auto at_vertex = GridTools::vertex_to_cell_map(grid.triangulation);

    unsigned int differ = 0, hanging = 0;
    for (unsigned int i = 0; i < grid.cells.size(); ++i)
      {
        std::vector<const GridCell<dim> *> expected;
        for (const unsigned int v : grid.cells[i].cell->vertex_indices())
          for (const auto &other :
               at_vertex[grid.cells[i].cell->vertex_index(v)])
            {
              const auto it = local.find(other->active_cell_index());
              if (it != local.end() &&
                  std::find(expected.begin(), expected.end(), it->second) ==
                    expected.end())
                expected.push_back(it->second);
            }
        std::vector<const GridCell<dim> *> found;
        for (const unsigned int k : grid.neighbors_of(i))
          found.push_back(&grid.local_cell(k));
        differ += expected != found;
        for (const GridCell<dim> *n : expected)
          hanging += n->cell->level() != grid.cells[i].cell->level();
      }
    EXPECT_EQ(differ, 0u);
    // Refined somewhere: cells of two levels (the scene's cells are at
    // grid.base_level, not 0).
    if (grid.triangulation.n_global_levels() > grid.base_level + 1)
      {
        EXPECT_GT(Utilities::MPI::sum(hanging, MPI_COMM_WORLD), 0u);
      }
  }

  /** The moving block's grid, refined where @p refine says. */
  template <int dim, typename Refine>
  void
  neighbors_as_dealii(const Refine &refine)
  {
    SCOPED_TRACE(std::to_string(dim) + "D");
    auto  simulation = moving_block<dim>();
    auto &grid =
      const_cast<BackgroundGrid<dim> &>(simulation->background_grid());
    simulation->change_grid([&](Triangulation<dim> &) {
      for (const GridCell<dim> &c : grid.cells)
        if (refine(c.cell->center()))
          c.cell->set_refine_flag();
    });
    expect_neighbors_as_dealii(grid);
  }
} // namespace

// The flat neighbour tables find what deal.II's vertex-to-cell map finds:
// on a uniform grid, next to a refined slab (hanging vertices on faces) and
// around a refined corner block (in 3D also on edges alone).
TEST(Relocation, NeighbourTablesMatchDealiiVertexToCellMap)
{
  const auto none  = [](const auto &) { return false; };
  const auto slab  = [](const auto &x) { return x[0] < 0.45; };
  const auto block = [](const auto &x) {
    bool inside = true;
    for (unsigned int d = 0; d < x.dimension; ++d)
      inside = inside && x[d] < 0.45;
    return inside;
  };
  neighbors_as_dealii<2>(none);
  neighbors_as_dealii<3>(none);
  neighbors_as_dealii<2>(slab);
  neighbors_as_dealii<3>(slab);
  neighbors_as_dealii<2>(block);
  neighbors_as_dealii<3>(block);
}

namespace
{
  /** The moving block run by the step, its grid refined where x < 0.45
   * (hanging nodes) with @p refine_half: after each step every particle
   * must be where deal.II's sort would put it (its cell, its reference
   * location to 1e-12), whether G2P put it into a neighbour itself or
   * plan_relocation() did. The step's relocations follow each other for
   * two steps, then deal.II sorts (update_handler()) and says where the
   * particles are. */
  template <int dim>
  void
  step_relocation_matches_sort(const bool refine_half)
  {
    SCOPED_TRACE(std::to_string(dim) + "D" +
                 (refine_half ? ", hanging nodes" : ""));
    auto simulation = moving_block<dim>();
    if (refine_half)
      simulation->change_grid([&](Triangulation<dim> &) {
        for (const GridCell<dim> &c : simulation->background_grid().cells)
          if (c.cell->center()[0] < 0.45)
            c.cell->set_refine_flag();
      });
    const BackgroundGrid<dim> &grid      = simulation->background_grid();
    ParticleSet<dim>          &particles = simulation->particle_set();
    unsigned int               changed   = 0;
    for (unsigned int step = 0; step < 12; ++step)
      {
        const Places<dim> before = places(grid, particles, false);
        simulation->advance(simulation->time_step());
        const Places<dim> after = places(grid, particles, false);
        for (const auto &[id, place] : after)
          {
            const auto it = before.find(id);
            changed += it != before.end() &&
                       std::get<0>(it->second) != std::get<0>(place);
          }
        expect_particles_in_their_cells(grid, particles);
        expect_order_matches_handler(grid, particles);
        if (step % 3 == 2)
          {
            particles.update_handler(grid);
            expect_same_places(after, places(grid, particles, true));
          }
      }
    // Particles did change cells (a few per step).
    EXPECT_GT(Utilities::MPI::sum(changed, MPI_COMM_WORLD), 20u);
  }
} // namespace

// The step's own relocation (G2P puts a particle into the neighbour it
// entered, plan_relocation() the rest) against deal.II's sort, in 2D and
// 3D, next to hanging nodes too.
TEST(Relocation, StepPutsParticlesWhereDealiiSortDoes)
{
  step_relocation_matches_sort<2>(false);
  step_relocation_matches_sort<3>(false);
  step_relocation_matches_sort<2>(true);
  step_relocation_matches_sort<3>(true);
}

// The step plans a relocation before its reduction and cancels it where no
// particle anywhere left its cell by more than round-off.
TEST(Relocation, CancelledPlanLeavesNoTrace)
{
  cancelled_relocation_leaves_no_trace<2>();
  cancelled_relocation_leaves_no_trace<3>();
}
