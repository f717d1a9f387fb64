#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/run_messages.h>
#include <dealmpm/base/warnings.h>
#include <dealmpm/core/run_report.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/core/stop_signal.h>
#include <dealmpm/diagnostics/region_totals.h>
#include <dealmpm/diagnostics/run_guards.h>
#include <dealmpm/grid/grid_update.h>
#include <dealmpm/io/progress.h>
#include <dealmpm/materials/geostatic_start.h>
#include <dealmpm/particles/fill_bodies.h>
#include <dealmpm/schemes/compatibility.h>
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/particle_to_grid.h>
#include <dealmpm/transfer/reference_stencil.h>
#include <dealmpm/transfer/stress_update.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <iomanip>
#include <limits>
#include <sstream>


namespace dealmpm
{
  namespace
  {
    /** @p word as one shell word: quoted unless it is plain. */
    std::string
    shell_word(const std::string &word)
    {
      const bool plain =
        !word.empty() && word.find_first_not_of(
                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTU"
                           "VWXYZ0123456789_./+-=,:@%") == std::string::npos;
      if (plain)
        return word;
      std::string quoted = "'";
      for (const char c : word)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
      return quoted + "'";
    }

    /** The command that resumes this run: the program as it was started
     * (as typed: build/dealmpm or dealmpm), under mpirun when on several
     * ranks, the scene, its overrides and --resume. */
    std::string
    resume_command_line(const std::string              &scene_file,
                        const std::vector<std::string> &overrides,
                        const MPI_Comm                  comm)
    {
      const unsigned int ranks = Utilities::MPI::n_mpi_processes(comm);
      std::string        command =
        ranks > 1 ? "mpirun -np " + std::to_string(ranks) + " " : "";
      command +=
        shell_word(program_invocation_name) + " " + shell_word(scene_file);
      for (const std::string &item : overrides)
        command += " -s " + shell_word(item);
      return command + " --resume";
    }
  } // namespace


  template <int dim>
  Simulation<dim>::Simulation(ParameterHandler                 &prm,
                              const std::string                &scene_file,
                              const SceneShape                 &shape,
                              const MPI_Comm                    comm,
                              const std::vector<std::string>   &overrides,
                              const std::optional<std::string> &resume)
    : comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , scene_file(scene_file)
    , grid(comm)
    , regions(effects)
    , output_writer(run_settings.output, comm)
  {
    resume_command = resume_command_line(scene_file, overrides, comm);
    SceneReader reader(prm, scene_file, overrides);
    read_scene(reader, shape);
    scene_entry_list = scene_entries(prm);
    std::optional<CheckpointInfo> saved;
    if (resume)
      saved = find_saved_run(
        reader, resume->empty() ? run_settings.checkpoint.directory : *resume);
    const CheckpointInfo *saved_run = saved ? &*saved : nullptr;
    setup_clock.lap("scene");
    build_grid(reader, saved_run);
    setup_clock.lap("grid");
    create_particles(reader, saved_run);
    setup_clock.lap(saved ? "particles read" : "particles");
    start_adaptivity(reader);
    start_load_balance(saved_run);
    setup_clock.lap("load balance");
    for (const auto &effect : effects)
      {
        for (const FieldDescription &field : effect->nodal_fields_per_body())
          nodal.request_per_body(field);
        if (effect->needs_body_fields())
          nodal.request_body_fields();
      }
    nodal.reinit(grid.partitioner, bodies.size());
    setup_clock.lap("nodal fields");
    regions.make(reader,
                 shape.n_fem_regions,
                 materials,
                 bodies.size(),
                 grid,
                 run_settings.method.apic);
    if (!regions.empty())
      setup_clock.lap("FEM regions");
    if (run_settings.method.total_lagrangian())
      make_reference_stencil(reader);
    choose_stages();
    if (saved)
      restore_saved_run(*saved);
    setup_clock.lap("stages");
    // Each rank times its own sections: an MPI timer costs a barrier and
    // three reductions per section and step (21 of a step's 28 reductions
    // on 2 ranks); the summary reduces them once (print_run_summary()).
    computing_timer = std::make_unique<TimerOutput>(pcout,
                                                    TimerOutput::never,
                                                    TimerOutput::wall_times);
  }

  template <int dim>
  Statistics
  Simulation<dim>::statistics() const
  {
    Statistics s =
      compute_statistics(grid, *particles, materials, effects, loop.time, comm);
    if (!regions.empty())
      add_region_totals(regions.totals(comm), s);
    return s;
  }

  template <int dim>
  double
  Simulation<dim>::external_work() const
  {
    double work = 0;
    for (const auto &effect : effects)
      work += effect->work_done();
    return Utilities::MPI::sum(work + regions.external_work(), comm);
  }

  template <int dim>
  double
  Simulation<dim>::time_step() const
  {
    if (!run_settings.time.cfl_time_step)
      return run_settings.time.fixed_time_step;
    // No particle and no FEM region sets a rate: all have left the grid
    // or were removed (run() says so before it asks).
    if (!(max_signal_rate > 0))
      throw RunError(step_and_time(loop.step, loop.time) +
                     ": no particles are left in the grid to set the time "
                     "step");
    return run_settings.time.cfl_number / max_signal_rate;
  }

  template <int dim>
  RunState
  Simulation<dim>::run_state() const
  {
    RunState saved = loop;
    saved.effect_states.clear();
    for (const auto &effect : effects)
      saved.effect_states.push_back(effect->saved_state());
    return saved;
  }

  template <int dim>
  void
  Simulation<dim>::advance(const double dt)
  {
    StepState<dim> state(grid,
                         *particles,
                         kernel,
                         stencil,
                         nodal,
                         boundary_conditions,
                         materials,
                         effects,
                         effect_names,
                         run_settings.method,
                         mass_threshold,
                         loop.step + 1,
                         loop.time,
                         dt,
                         *computing_timer);
    state.mixed_cells = mixed_cells.get();
    if (!regions.empty())
      state.fem_regions = &regions;
    state.previous_dt = loop.last_dt;
    // Not with APIC yet: its C = B D^-1 is not reliable with linear shape
    // functions (doc/guide/limits.md), and a spinning APIC body went unstable
    // with the weights.
    if (run_settings.method.scheme == UpdateScheme::USL &&
        !run_settings.method.particle_update.newmark &&
        !run_settings.method.apic && !kernel.gradient_shrinks_with_weight())
      state.stable_mass =
        stable_nodal_mass(dim, dt * max_signal_rate, mean_particle_mass);
    for (const Stage<dim> &stage : stages)
      stage.run(state, stage.name);

    finish_step(state.stress_update.check, state.left_cell, dt);
  }

  template <int dim>
  void
  Simulation<dim>::finish_step(const ParticleCheck<dim> &step_check,
                               const bool                left_cell,
                               const double              dt)
  {
    particle_check                  = step_check;
    const ParticleCheck<dim> &check = particle_check;
    const RelocationPlan      relocation =
      plan_relocation(left_cell, check.failed || stencil.failed);
    // The step's one reduction, a min over the ranks: the largest signal
    // rate (the next step's size), the smallest J, whether a particle
    // failed, whether one left its cell, whether a stencil failed, whether
    // an FEM region's coupling failed or asks to publish its boxes, the
    // largest relocation plan, whether particles were held at walls,
    // whether cpGIMP's stretched domains still fit its windows.
    const std::string coupling_failure = regions.coupling_failure();
    const double      rate =
      std::max({check.max_signal_rate,
                regions.local_signal_rate(),
                effects_signal_rate(effects, *particles, grid)});
    double reduced[10] = {-rate,
                          check.min_J,
                          check.failed ? -1. : 0.,
                          left_cell ? -1. : 0.,
                          stencil.failed ? -1. : 0.,
                          coupling_failure.empty() ? 0. : -1.,
                          regions.coupling_wants_publication() ? -1. : 0.,
                          -double(relocation.local),
                          relocation.held > 0 ? -1. : 0.,
                          check.domains_fit ? 0. : -1.};
    Utilities::MPI::min(ArrayView<const double>(reduced, 10),
                        comm,
                        ArrayView<double>(reduced, 10));
    max_signal_rate = -reduced[0];
    loop.accuracy.observe_step(reduced[1], dt * max_signal_rate);
    if (reduced[5] < 0)
      {
        std::ostringstream message;
        message << "step " << loop.step + 1 << " (t = " << loop.time + dt
                << "): " << first_message(coupling_failure, comm);
        throw RunError(message.str());
      }
    if (reduced[6] < 0)
      regions.publish_coupling_at_next_step();
    // A cpGIMP domain stretched past half a cell reaches a fourth node a
    // direction: the next step stores its weights; back on the windows
    // once all fit again.
    if (stencil.gimp_follows_deformation)
      stencil.where_used = reduced[9] == 0;
    // The stencil first: a particle's failure may follow from it.
    if (reduced[4] < 0)
      stop_on_particle(stencil.failed,
                       stencil.failed_particle,
                       stencil.failed_location,
                       stencil.failure,
                       loop.step + 1,
                       loop.time + dt,
                       comm);
    if (reduced[2] < 0)
      stop_on_particle(check.failed,
                       check.particle,
                       check.location,
                       check.reason,
                       loop.step + 1,
                       loop.time + dt,
                       comm);
    loop.time += dt;
    loop.last_dt = dt;
    ++loop.step;
    if (reduced[3] < 0 || relocation.local > 0)
      {
        TimerOutput::Scope t(*computing_timer, "relocate");
        if (reduced[3] < 0)
          finish_relocation(std::max(int(-reduced[7]) - 1, 0),
                            reduced[8] < 0,
                            relocation.held);
        else
          particles->cancel_relocation();
      }
  }

  template <int dim>
  typename Simulation<dim>::RelocationPlan
  Simulation<dim>::plan_relocation(const bool left_cell, const bool failed)
  {
    // Wherever G2P saw a particle outside its cell, also by round-off
    // only (which relocates only if a particle somewhere left by more),
    // and not where the step failed (it stops). Where a particle here
    // left by more, the ranks relocate for sure: nothing to keep for a
    // cancel. On one rank the reduction is this rank's own, so round-off
    // alone never relocates: no plan to make and cancel.
    const auto &leavers = particles->leavers;
    const bool  roundoff =
      leavers.recorded &&
      !(leavers.position.empty() && leavers.moves.empty()) &&
      Utilities::MPI::n_mpi_processes(comm) > 1;
    if (failed || !(left_cell || roundoff))
      return {};
    TimerOutput::Scope t(*computing_timer, "relocate");
    RelocationPlan     plan;
    plan.local = 1 + particles->plan_relocation(grid,
                                                boundary_conditions.walls(),
                                                plan.held,
                                                !left_cell);
    return plan;
  }

  template <int dim>
  void
  Simulation<dim>::finish_relocation(const int          everywhere,
                                     const bool         held_anywhere,
                                     const unsigned int held)
  {
    lost_this_step.clear();
    lost_mass_this_step = 0;
    const bool sorted   = !particles->finish_relocation(grid, everywhere);
    // Particles are lost only in deal.II's sort; the counts need a sum
    // only when it ran or some rank held particles at a wall.
    if (!sorted && !held_anywhere)
      return;
    const double local[3] = {double(held),
                             double(lost_this_step.size()),
                             lost_mass_this_step};
    double       counts[3];
    Utilities::MPI::sum(ArrayView<const double>(local, 3),
                        comm,
                        ArrayView<double>(counts, 3));
    loop.held_particles += counts[0];
    const double n_lost = counts[1];
    if (n_lost == 0)
      return;
    loop.lost_particles += n_lost;
    loop.lost_mass += counts[2];
    const std::string first =
      first_message(lost_this_step.empty() ?
                      "" :
                      "id " + std::to_string(lost_this_step[0].first) + " at " +
                        format_point(lost_this_step[0].second),
                    comm);
    std::ostringstream message;
    message << "step " << loop.step << " (t = " << loop.time << "): " << n_lost
            << " particle(s) left the grid (first: " << first << ")";
    if (run_settings.method.stop_when_particles_leave)
      throw RunError(message.str() +
                     "; set 'MPM/Particles leaving the grid = remove' "
                     "to drop such particles instead");
    const double limit   = run_settings.checks.mass_loss_limit;
    const double initial = loop.accuracy.initial_mass();
    const double lost    = loop.lost_mass / initial;
    if (limit > 0 && initial > 0 && lost > limit)
      {
        std::ostringstream stop;
        stop << std::setprecision(3) << message.str()
             << "; the particles removed so far carried " << 100 * lost
             << " % of the mass (limit 'Checks/Mass loss limit' = "
             << 100 * limit
             << " %): enlarge the grid, put a wall where they leave, or raise "
                "the limit";
        throw RunError(stop.str());
      }
    warn("particles left the grid", message.str() + "; removed");
  }

  template class Simulation<2>;
  template class Simulation<3>;
} // namespace dealmpm
