#include <deal.II/base/mpi.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/base/run_messages.h>
#include <dealmpm/adaptivity/split_particles.h>

#include <algorithm>

// The background grid adapting to the particles during a run: the
// criteria are in grid/adaptivity.h, the grid change in simulation.cc.
namespace dealmpm
{
  template <int dim>
  std::unique_ptr<TimerOutput::Scope>
  Simulation<dim>::timed(const std::string &section)
  {
    return computing_timer ?
             std::make_unique<TimerOutput::Scope>(*computing_timer, section) :
             nullptr;
  }

  template <int dim>
  void
  Simulation<dim>::start_adaptivity(SceneReader &reader)
  {
    {
      SectionScope section(reader, "Adaptivity");
      if (total_lagrangian())
        reader.fail("Criteria",
                    "none under 'MPM/Formulation = total Lagrangian' (its "
                    "stencil belongs to the grid it starts on)");
      if (kernel.name() == "quadratic B-spline")
        reader.fail("Criteria",
                    "none with 'MPM/Shape function = quadratic B-spline', "
                    "which needs a uniform grid (refined cells make hanging "
                    "nodes): use linear, uGIMP, cpGIMP or CPDI");
      // A surface particle's area is neither shared by its parts nor an
      // average of its group's.
      for (unsigned int e = 0; e < effects.size(); ++e)
        if (!effects[e]->particle_fields().empty())
          for (const auto &[asked, entry] :
               {std::pair{adaptivity.split, "Split particles"},
                std::pair{adaptivity.merge, "Merge particles"}})
            if (asked)
              reader.fail(entry,
                          "false with '" + effect_names[e] +
                            "', whose particle fields (a surface particle's "
                            "area) cannot be shared or averaged");
    }
    // A resumed run has its adapted grid from the checkpoint.
    if (!resumed_checkpoint.empty())
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
        const auto t = timed("adaptivity: split");
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
      const auto             t = timed("adaptivity: criteria");
      const std::vector<int> levels =
        target_levels(adaptivity,
                      AdaptivityContext<dim>{grid,
                                             *particles,
                                             adaptivity.min_level,
                                             adaptivity.max_level,
                                             comm});
      if (flag_cells(grid, levels, adaptivity.max_cells) && !cell_limit_warned)
        {
          pcout << "warning: " << step_and_time(loop.step, loop.time)
                << ": no cell refined: the grid would have more than "
                   "'Adaptivity/Maximum cells' = "
                << adaptivity.max_cells << " cells" << std::endl;
          cell_limit_warned = true;
        }
      // Coarsening flags of incomplete families go, and the level rule
      // may add refinement: count what will change.
      grid.triangulation.prepare_coarsening_and_refinement();
      double flagged = 0;
      for (const GridCell<dim> &c : grid.cells)
        flagged += c.cell->refine_flag_set() || c.cell->coarsen_flag_set();
      changed = Utilities::MPI::sum(flagged, comm) > 0;
    }
    if (changed)
      change_grid([](Triangulation<dim> &) {});
    return changed;
  }

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
  template std::unique_ptr<TimerOutput::Scope>
  Simulation<2>::timed(const std::string &);
  template std::unique_ptr<TimerOutput::Scope>
  Simulation<3>::timed(const std::string &);
} // namespace dealmpm
