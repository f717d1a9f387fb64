#include <deal.II/base/mpi.h>

#include <dealmpm/adaptivity/split_particles.h>
#include <dealmpm/base/errors.h>
#include <dealmpm/base/run_messages.h>
#include <dealmpm/base/warnings.h>
#include <dealmpm/core/run_report.h>
#include <dealmpm/core/simulation.h>

#include <algorithm>

// Changes of the background grid during a run: refinement and coarsening
// to the adaptivity criteria (adaptivity/adaptivity.h), repartitions for
// load balance, and the ordered rebuild of what keeps grid data.
namespace dealmpm
{
  template <int dim>
  void
  Simulation<dim>::start_adaptivity(SceneReader &reader)
  {
    // A resumed run has its adapted grid from the checkpoint.
    if (!adaptivity.enabled() || !resumed_checkpoint.empty())
      return;
    // One level per round (the particles criterion refines only the cells
    // that hold particles now); after each, the bodies are filled again on
    // the new grid: particles made in their cells with the body's and the
    // effects' exact initial state, where split parts would copy their
    // parent's.
    for (unsigned int round = 0; round <= adaptivity.max_level; ++round)
      {
        if (!change_grid_to_criteria())
          break;
        particles.reset();
        create_particles(reader, nullptr);
      }
    loop.adaptations = 0;
  }

  template <int dim>
  bool
  Simulation<dim>::adapt_grid()
  {
    const bool changed = change_grid_to_criteria();
    if (changed)
      ++loop.adaptations;
    // Also on an unchanged grid: particles may have moved into finer cells.
    if (adaptivity.split)
      {
        const auto t = timed(computing_timer.get(), "adaptivity: split");
        loop.split_particles +=
          split_particles(grid, *particles, adaptivity.particles_per_direction);
      }
    return changed;
  }

  template <int dim>
  bool
  Simulation<dim>::change_grid_to_criteria()
  {
    bool changed = false;
    {
      const auto t = timed(computing_timer.get(), "adaptivity: criteria");
      // A user's criterion may ask deal.II's handler for a cell's
      // particles; the built-in ones walk the step's order, and deal.II's
      // sort (tens of ms a call on large grids) runs only before a change.
      if (std::any_of(adaptivity.criteria.begin(),
                      adaptivity.criteria.end(),
                      [](const auto &c) { return c->reads_handler_lists(); }))
        particles->update_handler(grid);
      const std::vector<int> levels =
        target_levels(adaptivity,
                      AdaptivityContext<dim>{grid,
                                             *particles,
                                             adaptivity.min_level,
                                             adaptivity.max_level,
                                             comm});
      if (flag_cells(grid, levels, adaptivity.max_cells) && !cell_limit_warned)
        {
          warn("adaptivity at its cell limit",
               step_and_time(loop.step, loop.time) +
                 ": no cell refined: the grid would have more than "
                 "'Adaptivity/Maximum cells' = " +
                 std::to_string(static_cast<long long>(adaptivity.max_cells)) +
                 " cells");
          cell_limit_warned = true;
        }
      // Coarsening flags of incomplete families go, and the level rule
      // may add refinement: count what will change. deal.II's preparation
      // walks the whole grid several times, so only when it may matter.
      if (Utilities::MPI::logical_or(flags_may_change_grid(grid), comm))
        {
          grid.triangulation.prepare_coarsening_and_refinement();
          double flagged = 0;
          for (const GridCell<dim> &c : grid.cells)
            flagged += c.cell->refine_flag_set() || c.cell->coarsen_flag_set();
          changed = Utilities::MPI::sum(flagged, comm) > 0;
        }
      else
        for (const GridCell<dim> &c : grid.cells)
          c.cell->clear_coarsen_flag(); // as deal.II would have
    }
    if (changed)
      change_grid([](Triangulation<dim> &) {});
    return changed;
  }

  template <int dim>
  void
  Simulation<dim>::change_grid(
    const std::function<void(Triangulation<dim> &)> &set_flags)
  {
    const auto t = timed(computing_timer.get(), "grid change");
    if (run_settings.method.total_lagrangian())
      throw RunError(step_and_time(loop.step, loop.time) +
                     ": the grid cannot change under 'MPM/Formulation = total "
                     "Lagrangian': its stencil belongs to the reference grid");
    {
      // The flags may be set from the particles in each cell, and deal.II
      // moves the particles with their cells. Its execute prepares the
      // flags itself.
      const auto t_dealii =
        timed(computing_timer.get(), "grid change: deal.II and p4est");
      particles->update_handler(grid);
      set_flags(grid.triangulation);
      particles->handler.prepare_for_coarsening_and_refinement();
      grid.triangulation.execute_coarsening_and_refinement();
      particles->handler.unpack_after_coarsening_and_refinement();
      particles->changed();
    }
    const auto t_rebuild = timed(computing_timer.get(), "grid change: rebuild");
    rebuild_after_grid_change();
  }

  template <int dim>
  void
  Simulation<dim>::repartition()
  {
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    // Total Lagrangian's reference stencil holds local node indices of the
    // grid it was made on.
    if (run_settings.method.total_lagrangian() && stencil.reference)
      throw RunError(step_and_time(loop.step, loop.time) +
                     ": the grid cannot be repartitioned under 'MPM/"
                     "Formulation = total Lagrangian' once its reference "
                     "stencil is made");
    particles->update_handler(grid);
    particles->handler.prepare_for_coarsening_and_refinement();
    grid.triangulation.repartition();
    particles->handler.unpack_after_coarsening_and_refinement();
    particles->changed();
    rebuild_after_grid_change();
    ++loop.repartitions;
    if (run_settings.load_balance.enabled)
      balanced_imbalance =
        weight_imbalance(grid.triangulation,
                         particles->handler,
                         run_settings.load_balance.particle_weight);
  }

  template <int dim>
  void
  Simulation<dim>::rebuild_after_grid_change()
  {
    // The documented order: the grid's own data, then what is cached from
    // it (the shape function's tables, the boundary nodes, the nodal
    // vectors); the stencil is made anew by every step.
    grid.setup();
    const std::string problem = kernel.rebuild(grid);
    if (!problem.empty())
      throw RunError(step_and_time(loop.step, loop.time) +
                     ": after the grid changed, 'MPM/Shape function' = '" +
                     kernel.name() + "' needs " + problem);
    boundary_conditions.rebuild(grid);
    for (const auto &effect : effects)
      effect->grid_changed(grid);
    regions.grid_changed(grid);
    nodal.reinit(grid.partitioner, bodies.size());
    choose_weights(); // uGIMP's windows fit the new lattice or not
    // Smaller cells, smaller stable step.
    particle_check = check_particles(grid,
                                     materials,
                                     *particles,
                                     run_settings.method.total_lagrangian());
    max_signal_rate =
      Utilities::MPI::max(std::max(
                            {particle_check.max_signal_rate,
                             regions.local_signal_rate(),
                             effects_signal_rate(effects, *particles, grid)}),
                          comm);
  }

  template void
  Simulation<2>::change_grid(const std::function<void(Triangulation<2> &)> &);
  template void
  Simulation<3>::change_grid(const std::function<void(Triangulation<3> &)> &);
  template void
  Simulation<2>::repartition();
  template void
  Simulation<3>::repartition();
  template void
  Simulation<2>::rebuild_after_grid_change();
  template void
  Simulation<3>::rebuild_after_grid_change();
  template void
  Simulation<2>::start_adaptivity(SceneReader &);
  template void
  Simulation<3>::start_adaptivity(SceneReader &);
  template bool
  Simulation<2>::change_grid_to_criteria();
  template bool
  Simulation<3>::change_grid_to_criteria();
  template bool
  Simulation<2>::adapt_grid();
  template bool
  Simulation<3>::adapt_grid();
} // namespace dealmpm
