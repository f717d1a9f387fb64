// The grid adapting to the particles: splitting keeps what it must, the
// criteria refine where they should and nowhere else, a run conserves
// through refinement, coarsening and splitting, and what adaptivity
// cannot run with is refused. Runs on 1 rank and, through ctest, on 2.
#include <deal.II/base/mpi.h>

#include <dealmpm/adaptivity/split_particles.h>
#include <dealmpm/transfer/stencil_order.h>

#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** Mass, current volume, momentum and first moment of mass of all
   * particles. */
  template <int dim>
  std::vector<double>
  moments(Simulation<dim> &simulation)
  {
    const CoreFields   &f = simulation.particle_set().fields;
    std::vector<double> m(2 + 2 * dim, 0.);
    for (const auto &p : simulation.particle_set().handler)
      {
        const auto props = p.get_properties();
        m[0] += props[f.mass];
        m[1] += current_volume<dim>(props.data(), f);
        for (unsigned int d = 0; d < dim; ++d)
          {
            m[2 + d] += props[f.mass] * props[f.velocity + d];
            m[2 + dim + d] += props[f.mass] * p.get_location()[d];
          }
      }
    std::vector<double> total(m.size());
    Utilities::MPI::sum(make_array_view(std::as_const(m)),
                        MPI_COMM_WORLD,
                        make_array_view(total));
    return total;
  }

  template <int dim>
  void
  split_after_refinement(const std::string &kernel)
  {
    SCOPED_TRACE(kernel + " in " + std::to_string(dim) + "D");
    const std::string grid =
      dim == 2 ? "set Cells = 8, 8\n" : "set Cells = 4, 4, 4\n";
    const std::string box =
      dim == 2 ? " set Lower corner = 0.3, 0.3\n set Upper corner = 0.6, "
                 "0.55\n set Velocity = 1, 0.5\n" :
                 " set Lower corner = 0.3, 0.3, 0.3\n set Upper corner = "
                 "0.6, 0.55, 0.7\n set Velocity = 1, 0.5, -0.2\n";
    auto simulation = test::make_simulation<dim>(
      "set Dimension = " + std::to_string(dim) + "\nsubsection Grid\n" + grid +
      "end\nsubsection MPM\n set Shape function = " + kernel +
      "\nend\nsubsection Body 1\n" + box + "end\n");
    // A deformed state, so that F maps the parts' offsets.
    for (unsigned int i = 0; i < 3; ++i)
      simulation->advance(simulation->time_step());
    const std::vector<double> before = moments(*simulation);
    const Statistics          s0     = simulation->statistics();
    simulation->change_grid([&](Triangulation<dim> &) {
      for (const GridCell<dim> &c : simulation->background_grid().cells)
        c.cell->set_refine_flag();
    });
    const double     n_split = split_particles(simulation->background_grid(),
                                           simulation->particle_set(),
                                           2);
    const Statistics s1      = simulation->statistics();
    // Every particle filled a quarter (an eighth) of its old cell, which
    // is now its new cell's whole: all split.
    EXPECT_EQ(n_split, s0.n_particles);
    EXPECT_EQ(s1.n_particles, s0.n_particles * (1u << dim));
    const std::vector<double> after = moments(*simulation);
    for (unsigned int i = 0; i < before.size(); ++i)
      EXPECT_NEAR(after[i], before[i], 1e-13 * std::abs(before[0] + 1.))
        << "moment " << i;
    EXPECT_NEAR(s1.kinetic_energy,
                s0.kinetic_energy,
                1e-13 * s0.kinetic_energy);
    EXPECT_NEAR(s1.strain_energy,
                s0.strain_energy,
                1e-12 * s0.strain_energy + 1e-300);
    // Ids unique on all ranks.
    std::vector<double> ids;
    for (const auto &p : simulation->particle_set().handler)
      ids.push_back(p.get_id());
    const std::vector<std::vector<double>> all =
      Utilities::MPI::all_gather(MPI_COMM_WORLD, ids);
    std::set<double> unique;
    std::size_t      n = 0;
    for (const auto &rank : all)
      {
        unique.insert(rank.begin(), rank.end());
        n += rank.size();
      }
    EXPECT_EQ(unique.size(), n);
    // A step on: the nodes carry all the mass.
    simulation->advance(simulation->time_step());
    EXPECT_NEAR(simulation->nodal_fields().mass.l1_norm(),
                s0.mass,
                1e-12 * s0.mass);
  }
} // namespace

TEST(Adaptivity, MergingAfterCoarseningUndoesTheSplitsCount)
{
  auto simulation = test::make_simulation<2>(
    "subsection Grid\n set Cells = 8, 8\nend\nsubsection MPM\n set Shape "
    "function = cpGIMP\nend\nsubsection Body 1\n set Lower corner = 0.3, "
    "0.3\n set Upper corner = 0.6, 0.55\n set Velocity = 0.1, 0.05\nend\n");
  // A little deformed and moved (the parts of a particle stay in its
  // sub-cell).
  for (unsigned int i = 0; i < 3; ++i)
    simulation->advance(simulation->time_step());
  const Statistics          s0     = simulation->statistics();
  const std::vector<double> before = moments(*simulation);
  const auto                every  = [&](const bool refine) {
    simulation->change_grid([&](Triangulation<2> &) {
      for (const GridCell<2> &c : simulation->background_grid().cells)
        refine ? c.cell->set_refine_flag() : c.cell->set_coarsen_flag();
    });
  };
  every(true);
  split_particles(simulation->background_grid(), simulation->particle_set(), 2);
  EXPECT_EQ(simulation->statistics().n_particles, 4 * s0.n_particles);
  every(false);
  const double     n_removed = merge_particles(simulation->background_grid(),
                                           simulation->particle_set(),
                                           2);
  const Statistics s1        = simulation->statistics();
  EXPECT_EQ(n_removed, 3 * s0.n_particles);
  EXPECT_EQ(s1.n_particles, s0.n_particles);
  const std::vector<double> after = moments(*simulation);
  for (unsigned int i = 0; i < before.size(); ++i)
    EXPECT_NEAR(after[i], before[i], 1e-13 * std::abs(before[0] + 1.))
      << "moment " << i;
  // Each merged particle is its four parts' parent again: at its place,
  // with its velocity (and so its kinetic energy) and its F.
  EXPECT_NEAR(s1.kinetic_energy, s0.kinetic_energy, 1e-12 * s0.kinetic_energy);
  EXPECT_NEAR(s1.strain_energy,
              s0.strain_energy,
              1e-9 * s0.strain_energy + 1e-300);
  // A cell of usual crowding is left alone.
  EXPECT_EQ(merge_particles(simulation->background_grid(),
                            simulation->particle_set(),
                            2),
            0.);
}

TEST(Adaptivity, SplittingKeepsMassVolumeMomentumAndFirstMoment)
{
  split_after_refinement<2>("linear");
  split_after_refinement<2>("cpGIMP");
  split_after_refinement<2>("CPDI");
  split_after_refinement<3>("uGIMP");
}

namespace
{
  const std::string corner_block =
    "subsection Grid\n set Cells = 8, 8\nend\n"
    "subsection Body 1\n set Lower corner = 0.05, 0.05\n"
    " set Upper corner = 0.3, 0.3\n set Velocity = 0.2, 0.1\nend\n"
    "subsection Adaptivity\n set Criteria = particles\n set Minimum level = 0\n"
    " set Maximum level = 2\nend\n";
}

TEST(Adaptivity, ParticlesCriterionRefinesTheMaterialAndItsBufferOnly)
{
  auto                     simulation = test::make_simulation<2>(corner_block);
  const BackgroundGrid<2> &grid       = simulation->background_grid();
  const auto              &handler    = simulation->particle_set().handler;
  // The block covers 2 x 2 coarse cells of 1/8, refined twice, with a
  // buffer of one cell around it.
  for (const GridCell<2> &c : grid.cells)
    {
      const Point<2> x      = c.cell->center();
      const bool     filled = handler.n_particles_in_cell(c.cell) > 0;
      if (filled)
        {
          EXPECT_EQ(grid.level(c.cell), 2) << x;
          EXPECT_LE(handler.n_particles_in_cell(c.cell), 4u) << x;
        }
      if (x[0] > 0.55 || x[1] > 0.55)
        {
          EXPECT_EQ(grid.level(c.cell), 0) << x;
        }
    }
  // The block is filled again on the adapted grid: the particles of the
  // uniform grid two levels finer, the same mass.
  auto uniform = test::make_simulation<2>(
    corner_block + "subsection Adaptivity\n set Criteria =\nend\n"
                   "subsection Grid\n set Global refinements = 2\nend\n");
  EXPECT_NEAR(simulation->statistics().mass, uniform->statistics().mass, 1e-13);
  EXPECT_EQ(simulation->statistics().n_particles,
            uniform->statistics().n_particles);
}

TEST(Adaptivity, RunConservesThroughRefinementCoarseningAndSplitting)
{
  // The block flies across the grid: cells are refined ahead of it and
  // coarsened behind it every 5 steps.
  auto simulation = test::make_simulation<2>(
    corner_block + "subsection Adaptivity\n set Steps between adaptations = 5\n"
                   " set Maximum level = 1\nend\n"
                   "subsection Body 1\n set Velocity = 2, 1\nend\n");
  const Statistics start = simulation->statistics();
  const double     cells_before =
    simulation->background_grid().triangulation.n_global_active_cells();
  double n_cells_changed = 0;
  while (simulation->time() < 0.2)
    {
      simulation->advance(simulation->time_step());
      if (simulation->step_number() % 5 == 0)
        {
          simulation->adapt_grid();
          n_cells_changed +=
            simulation->background_grid()
              .triangulation.n_global_active_cells() != cells_before;
        }
    }
  const Statistics end = simulation->statistics();
  EXPECT_GT(n_cells_changed, 0);
  EXPECT_GE(end.n_particles, start.n_particles);
  EXPECT_NEAR(end.mass, start.mass, 1e-13 * start.mass);
  for (unsigned int d = 0; d < 2; ++d)
    EXPECT_NEAR(end.momentum[d], start.momentum[d], 1e-12 * start.mass);
  EXPECT_NEAR(end.kinetic_energy + end.strain_energy,
              start.kinetic_energy,
              0.02 * start.kinetic_energy);
}

TEST(Adaptivity, VelocityJumpRefinesWhereTheBodiesMeet)
{
  // Two blocks side by side, moving apart, meet in the cells around
  // x = 0.5: only those differ in velocity.
  auto simulation = test::make_simulation<2>(
    "set Number of bodies = 2\nsubsection Grid\n set Cells = 5, 5\nend\n"
    "subsection Body 1\n set Lower corner = 0.1, 0.1\n"
    " set Upper corner = 0.5, 0.9\n set Velocity = -0.1, 0\nend\n"
    "subsection Body 2\n set Lower corner = 0.5, 0.1\n"
    " set Upper corner = 0.9, 0.9\n set Velocity = 0.1, 0\nend\n"
    "subsection Adaptivity\n set Criteria = velocity jump\n"
    " set Maximum level = 1\nend\n",
    2);
  for (const GridCell<2> &c : simulation->background_grid().cells)
    {
      const double x = c.cell->center()[0];
      EXPECT_EQ(simulation->background_grid().level(c.cell),
                (x > 0.4 && x < 0.6) ? 1 : 0)
        << x;
    }
}

TEST(Adaptivity, RefusedWhereItCannotWork)
{
  const std::string with = corner_block + "subsection MPM\n set ";
  EXPECT_THROW(test::make_simulation<2>(
                 with + "Shape function = quadratic B-spline\nend\n"),
               InputError);
  EXPECT_THROW(test::make_simulation<2>(
                 with + "Formulation = total Lagrangian\nend\n"),
               InputError);
}

namespace
{
  /** How many of this grid's owned cells carry a flag, over all ranks. */
  double
  n_flagged(const BackgroundGrid<2> &grid)
  {
    double n = 0;
    for (const GridCell<2> &c : grid.cells)
      n += c.cell->refine_flag_set() || c.cell->coarsen_flag_set();
    return Utilities::MPI::sum(n, grid.comm);
  }

  /** Whether flags_may_change_grid() says "no" on some rank's behalf for
   * all of them, that is whether deal.II's preparation is skipped. */
  bool
  predicted_unchanged(const BackgroundGrid<2> &grid)
  {
    return !Utilities::MPI::logical_or(flags_may_change_grid(grid), grid.comm);
  }

  /** deal.II's preparation of the flags, as the grid change runs it. */
  void
  prepare(const BackgroundGrid<2> &grid)
  {
    // The test's grid is the simulation's (const outside); only the flags
    // change.
    const_cast<parallel::distributed::Triangulation<2> &>(grid.triangulation)
      .prepare_coarsening_and_refinement();
  }
} // namespace

TEST(Adaptivity, FlagsThatDealIIWouldUndoAreSeenWithoutIt)
{
  // The block's grid: levels 2 (the block and its buffer), 1 (the layer
  // the level rule needs) and 0.
  auto simulation = test::make_simulation<2>(
    corner_block + "subsection Grid\n set Cells = 12, 12\nend\n"
                   "subsection Adaptivity\n subsection Particles\n"
                   "  set Margin cells = 0\n end\nend\n");
  const BackgroundGrid<2> &grid = simulation->background_grid();
  // What the 'particles' criterion flags between two steps: the layer's
  // cells (empty) to be coarsened, which the level rule undoes. Seen
  // without deal.II.
  flag_cells(
    grid,
    target_levels(
      simulation->adaptivity_settings(),
      AdaptivityContext<2>{grid, simulation->particle_set(), 0, 2, grid.comm}),
    1e9);
  EXPECT_GT(n_flagged(grid), 0);
  EXPECT_TRUE(predicted_unchanged(grid));
  prepare(grid);
  EXPECT_EQ(n_flagged(grid), 0);

  // Cells flagged for coarsening at random (the same on any number of
  // ranks: by the cell's centre), from a few to most: a "no change" said
  // without deal.II must be deal.II's answer too, and both answers must
  // occur.
  unsigned int n_skipped = 0, n_asked = 0, n_changed = 0;
  for (unsigned int seed = 1; seed <= 60; ++seed)
    {
      for (const GridCell<2> &c : grid.cells)
        {
          c.cell->clear_refine_flag();
          c.cell->clear_coarsen_flag();
          if (c.cell->level() == 0)
            continue;
          const Point<2>     x = c.cell->center();
          const unsigned int hash =
            static_cast<unsigned int>(std::floor(x[0] * 1e4)) * 7919u +
            static_cast<unsigned int>(std::floor(x[1] * 1e4)) * 104729u +
            seed * 15485863u;
          if ((hash >> 7) % 20 < seed % 20)
            c.cell->set_coarsen_flag();
        }
      const bool skipped = predicted_unchanged(grid);
      prepare(grid);
      const double kept = n_flagged(grid);
      if (skipped)
        {
          EXPECT_EQ(kept, 0) << "seed " << seed;
          ++n_skipped;
        }
      else
        ++n_asked;
      n_changed += kept > 0;
    }
  for (const GridCell<2> &c : grid.cells)
    c.cell->clear_coarsen_flag();
  EXPECT_GT(n_skipped, 5u);
  EXPECT_GT(n_changed, 5u);
  EXPECT_GE(n_asked, n_changed);
}

TEST(Adaptivity, MarginChangesTheGridLessOftenAndKeepsParticlesOnFineCells)
{
  // The block flies across the grid (0.2 s at 2.2 m/s, about 3.5 coarse
  // cells) and the grid is adapted every 5 steps: with a margin the grid
  // changes only when particles near coarser cells, and at every step
  // every particle is on a cell of the finest level.
  unsigned int changes[2] = {0, 0};
  for (const unsigned int margin : {0u, 1u})
    {
      auto simulation = test::make_simulation<2>(
        corner_block +
        "subsection Adaptivity\n set Steps between adaptations = 5\n"
        " set Maximum level = 1\n subsection Particles\n  set Margin cells = " +
        std::to_string(margin) +
        "\n end\nend\nsubsection Body 1\n set Velocity = 2, 1\nend\n");
      const BackgroundGrid<2> &grid = simulation->background_grid();
      while (simulation->time() < 0.2)
        {
          simulation->advance(simulation->time_step());
          if (simulation->step_number() % 5 == 0)
            changes[margin] += simulation->adapt_grid();
          const ParticlesByCell<2, const ParticleSet<2>> particles(
            grid, simulation->particle_set());
          for (std::size_t i = 0; i < grid.cells.size(); ++i)
            if (!particles.empty(i))
              {
                ASSERT_EQ(grid.level(grid.cells[i].cell), 1)
                  << "margin " << margin << ", step "
                  << simulation->step_number();
              }
        }
    }
  EXPECT_GT(changes[1], 0u);
  EXPECT_LT(2 * changes[1], changes[0]);
}

TEST(Adaptivity, CriteriaThatChangeNothingLeaveDealIIsListsAsTheyAre)
{
  // The built-in criteria walk the step's particle order: an adaptation
  // that changes nothing does not sort deal.II's per-cell lists (a sort
  // costs about a step), which lag behind once particles changed cells.
  // On one rank: on several, particles crossing to another rank's cells
  // make every rank sort anyway.
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    GTEST_SKIP();
  for (const std::string criterion : {"particles", "velocity jump"})
    {
      auto simulation = test::make_simulation<2>(
        corner_block + "subsection Adaptivity\n set Criteria = " + criterion +
        "\nend\n");
      const ParticleSet<2> &particles = simulation->particle_set();
      const MPI_Comm        comm      = simulation->background_grid().comm;
      // Adapted whenever particles changed cells on some rank (stepping
      // is collective), until an adaptation changed nothing.
      unsigned int n_checked = 0;
      for (unsigned int i = 0; i < 200 && n_checked == 0; ++i)
        {
          simulation->advance(simulation->time_step());
          const bool lagged = particles.handler_lags_order();
          if (!Utilities::MPI::logical_or(lagged, comm))
            continue;
          if (simulation->adapt_grid())
            continue;
          EXPECT_EQ(particles.handler_lags_order(), lagged) << criterion;
          ++n_checked;
        }
      EXPECT_EQ(n_checked, 1u) << criterion;
    }
}
