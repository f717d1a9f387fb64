#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/run_messages.h>
#include <dealmpm/base/warnings.h>
#include <dealmpm/core/run_report.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/core/stop_signal.h>
#include <dealmpm/diagnostics/run_guards.h>
#include <dealmpm/grid/grid_update.h>
#include <dealmpm/schemes/compatibility.h>
#include <dealmpm/transfer/particle_to_grid.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

// The run loop of Simulation: outputs, checks between steps, progress and
// the closing report. Construction and the step are in simulation.cc.
namespace dealmpm
{
  namespace
  {
    /** The lines of a run stopped by @p signal: where its output is and,
     * if it was @p saved, the command that continues it. */
    void
    print_stop(const ConditionalOStream &pcout,
               const int                 signal,
               const RunState           &loop,
               const RunSettings        &s,
               const std::string        &saved,
               const std::string        &resume_command)
    {
      pcout << "dealmpm: stopped by " << signal_name(signal) << " at step "
            << loop.step << " (t = " << loop.time << "); output in "
            << s.output.directory << "/ is complete" << std::endl;
      if (!saved.empty())
        pcout << "dealmpm: saved in " << saved
              << "/; continue with: " << resume_command << std::endl;
    }

    /** (m |g| + F) h / 1000: the work of gravity and of the loads (F:
     * their largest total magnitude so far) over a thousandth of the
     * smallest cell, the energy guard's scale when a scene puts in less. */
    template <int dim>
    double
    load_energy_floor(const Statistics                                &s,
                      const std::vector<std::unique_ptr<Effect<dim>>> &effects,
                      const BackgroundGrid<dim>                       &grid)
    {
      double h     = std::numeric_limits<double>::max();
      double loads = 0;
      for (const GridCell<dim> &c : grid.cells)
        h = std::min(h, c.h);
      for (const auto &effect : effects)
        loads += effect->load_magnitude();
      h     = Utilities::MPI::min(h, grid.comm);
      loads = Utilities::MPI::sum(loads, grid.comm);
      return 1e-3 * (s.mass * uniform_acceleration(effects).norm() + loads) * h;
    }
  } // namespace

  template <int dim>
  void
  Simulation<dim>::guard_fixed_time_step(const double dt)
  {
    const std::string warning = check_fixed_time_step(
      dt, max_signal_rate, run_settings.checks.cfl_warning, cfl_warned, [&] {
        return step_and_time(loop.step + 1, loop.time) + ": " +
               fastest_particle(particle_check,
                                max_signal_rate,
                                *particles,
                                comm);
      });
    if (warning.empty())
      return;
    warn("fixed time step near the stable limit", warning);
    cfl_warned = true;
  }

  template <int dim>
  void
  Simulation<dim>::write_output(const double      dt,
                                const Statistics &now,
                                const double      work,
                                const Progress   &progress)
  {
    TimerOutput::Scope          t(*computing_timer, "output");
    std::vector<DrawnBody<dim>> bodies;
    for (const auto &effect : effects)
      for (DrawnBody<dim> &body : effect->drawn_bodies(grid.bounding_box))
        bodies.push_back(std::move(body));
    output_writer.write(
      {*particles, materials, grid, nodal.core, regions.list(), bodies},
      loop.time,
      loop.step,
      loop.output,
      [&](StatisticsFile &file) {
        file.write_row(loop.step,
                       loop.time,
                       dt,
                       now,
                       work,
                       loop.accuracy.report(),
                       loop.lost_particles,
                       progress.elapsed_seconds());
      });
    // The regions' support forces are means over a row's steps.
    regions.start_statistics_row();
  }

  template <int dim>
  void
  Simulation<dim>::map_particles_for_grid_output()
  {
    // Total Lagrangian has made its stencil (the reference one) already.
    if (!stencil.reference)
      {
        kernel.compute_stencil(grid, *particles, stencil);
        if (run_settings.method.apic)
          record_positions(grid, *particles, stencil);
      }
    if (!Utilities::MPI::logical_or(stencil.failed, comm))
      {
        particle_to_grid(grid, *particles, stencil, nodal.core, true, false);
        velocity_from_momentum(nodal.core, mass_threshold, boundary_conditions);
      }
  }

  template <int dim>
  void
  Simulation<dim>::take_step(const double dt, Progress &progress)
  {
    const RunSettings &s           = run_settings;
    const double       n_particles = particles->handler.n_global_particles();
    // Stepping time: the step and its checks, not the output.
    const auto start = std::chrono::steady_clock::now();
    try
      {
        if (!s.time.cfl_time_step)
          guard_fixed_time_step(dt);
        advance(dt);
      }
    catch (const RunError &error)
      {
        throw with_last_output(error,
                               loop.output.last_time,
                               run_settings.output.directory);
      }
    loop.particle_steps += n_particles;
    if (adaptivity.enabled() && loop.step % adaptivity.step_interval == 0)
      adapt_grid();
    balance_load();

    const bool output_due =
      run_settings.time.finished(loop.time, loop.step) ||
      (s.output.interval > 0 &&
       loop.time >= loop.next_output - 1e-9 * s.time.end_time);
    const bool energy_check_due =
      s.checks.energy_growth_limit > 0 &&
      (output_due || loop.step % energy_check_interval == 0);
    Statistics now;
    double     work = 0;
    if (output_due || energy_check_due)
      {
        now  = statistics();
        work = external_work();
        loop.accuracy.raise_floor(load_energy_floor(now, effects, grid));
        loop.accuracy.observe(now, work);
        if (energy_check_due &&
            loop.accuracy.report().energy_drift > s.checks.energy_growth_limit)
          {
            std::vector<Tensor<1, dim>> initial_velocity;
            for (const auto &body : bodies)
              initial_velocity.push_back(body.velocity);
            throw with_last_output(
              energy_growth_error(*particles,
                                  materials,
                                  effects,
                                  initial_velocity,
                                  loop.accuracy.report().energy_drift,
                                  loop.accuracy.energy_scale(),
                                  s.checks.energy_growth_limit,
                                  step_and_time(loop.step, loop.time),
                                  comm),
              loop.output.last_time,
              s.output.directory);
          }
      }
    loop.stepping_time +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    if (output_due)
      {
        // The next multiple of the interval (no loop: a tiny interval
        // cannot make it spin).
        if (s.output.interval > 0)
          loop.next_output =
            (std::floor(loop.time / s.output.interval + 1e-9) + 1) *
            s.output.interval;
        write_output(dt, now, work, progress);
      }
    progress.update(loop.step, loop.time, dt, s.time.end_time, n_particles);
  }

  template <int dim>
  void
  Simulation<dim>::balance_load()
  {
    const LoadBalanceSettings &s = run_settings.load_balance;
    if (!s.enabled || Utilities::MPI::n_mpi_processes(comm) == 1 ||
        run_settings.method.total_lagrangian())
      return;
    const bool due =
      s.repartition_interval > 0 && loop.step % s.repartition_interval == 0;
    if (!due && loop.step % s.check_interval != 0)
      return;
    TimerOutput::Scope t(*computing_timer, "load balance");
    // The partition evens out cell weights, not particles: a trigger on
    // particles repartitioned at every check where empty cells weigh
    // much (a body in a large box), and so does one set below what the
    // cells allow.
    const double limit = s.imbalance_limit * std::max(1., balanced_imbalance);
    if (due || weight_imbalance(grid.triangulation,
                                particles->handler,
                                s.particle_weight) > limit)
      repartition();
  }

  template <int dim>
  void
  Simulation<dim>::run()
  {
    const RunSettings       &s = run_settings;
    const StopSignalHandlers signal_handlers;
    const bool               resumed   = !resumed_checkpoint.empty();
    const Statistics         initial   = statistics();
    const unsigned int       n_removed = open_output(initial);
    setup_clock.lap("output folder");
    Progress progress(std::cout,
                      s.output.progress_interval,
                      Utilities::MPI::this_mpi_process(comm) == 0 &&
                        s.output.verbose);
    if (s.output.verbose)
      print_start(initial, n_removed);
    if (!resumed)
      {
        // The grid output at t = 0 shows the particles' mass and velocity
        // p / m on the nodes, as every later one does, instead of zeros.
        if (s.output.write_grid)
          map_particles_for_grid_output();
        loop.accuracy.start(initial, load_energy_floor(initial, effects, grid));
        write_output(0., initial, 0., progress);
        loop.next_output = s.output.interval;
      }
    // Not saved with a checkpoint: the scene says it, resumed or not.
    loop.accuracy.set_momentum_conserved(conserves_momentum());

    double dt = 0;
    while (!run_settings.time.finished(loop.time, loop.step))
      {
        // mpirun passes the signal to every rank, but not at the same
        // moment: the ranks stop at the same step only if they agree, and
        // save at the same step only if they agree on the time too.
        test_term_at_step(loop.step);
        int flags[2] = {
          stop_signal(),
          run_settings.checkpoint.due_by_time(last_checkpoint_time) ? 1 : 0};
        Utilities::MPI::max(ArrayView<const int>(flags, 2),
                            comm,
                            ArrayView<int>(flags, 2));
        stopped_by_signal = flags[0];
        if (stopped_by_signal != 0)
          break;
        if (flags[1] != 0 && last_checkpoint_step != loop.step)
          write_checkpoint();
        if (particles->handler.n_global_particles() == 0)
          throw RunError(step_and_time(loop.step, loop.time) +
                         ": no particles are left in the grid");
        dt = std::min(time_step(), s.time.end_time - loop.time);
        take_step(dt, progress);
        if (s.checkpoint.step_interval > 0 &&
            loop.step % s.checkpoint.step_interval == 0)
          write_checkpoint();
      }
    std::string saved;
    if (stopped_by_signal != 0)
      saved = save_stopped_run(dt, progress);
    else if ((s.checkpoint.step_interval > 0 ||
              s.checkpoint.wall_interval > 0) &&
             last_checkpoint_step != loop.step)
      // A run that saves checkpoints saves its end too: a longer 'End
      // time' with --resume then continues from there.
      write_checkpoint();
    if (s.output.verbose)
      print_run_summary(pcout,
                        *computing_timer,
                        loop,
                        grid.triangulation.n_global_active_cells(),
                        comm);
    if (stopped_by_signal != 0)
      print_stop(pcout, stopped_by_signal, loop, s, saved, resume_command);
  }

  template <int dim>
  bool
  Simulation<dim>::conserves_momentum() const
  {
    if (!boundary_conditions.walls().empty() || !regions.empty())
      return false;
    for (const auto &effect : effects)
      if (!effect->conserves_momentum())
        return false;
    return true;
  }

  template <int dim>
  std::string
  Simulation<dim>::save_stopped_run(const double dt, const Progress &progress)
  {
    // The checkpoint comes before the stop's output, so that it holds the
    // run as the uninterrupted one had it at this step: a resumed run
    // drops the stop's row and files (they are not in the saved output
    // record), and the regions' support forces, means over a row's steps,
    // go on over the whole row.
    std::string saved;
    if (run_settings.checkpoint.on_stop_signal)
      saved = last_checkpoint_step == loop.step ?
                run_settings.checkpoint.directory :
                write_checkpoint();
    if (loop.output.last_step != loop.step)
      {
        const Statistics now  = statistics();
        const double     work = external_work();
        loop.accuracy.observe(now, work);
        write_output(dt, now, work, progress);
      }
    return saved;
  }

  template <int dim>
  void
  Simulation<dim>::print_start(const Statistics  &initial,
                               const unsigned int n_removed) const
  {
    const double local_particles =
      particles->handler.n_locally_owned_particles();
    const double fewest = Utilities::MPI::min(local_particles, comm);
    const double most   = Utilities::MPI::max(local_particles, comm);
    pcout << "dealmpm: " << dim << "D, "
          << grid.triangulation.n_global_active_cells() << " cells, "
          << grid.dof_handler.n_dofs() << " nodes, "
          << static_cast<unsigned long>(initial.n_particles) << " particles, "
          << Utilities::MPI::n_mpi_processes(comm) << " rank(s) (" << fewest
          << " to " << most << " particles per rank), about "
          << short_number(memory.bytes / 1e9) << " GB estimated; output in "
          << run_settings.output.directory << "/";
    if (n_removed > 0)
      pcout << " (removed " << n_removed
            << (resumed_checkpoint.empty() ?
                  " files of an earlier run)" :
                  " files the interrupted run wrote after its checkpoint)");
    pcout << std::endl;
    if (!run_settings.method.anti_locking_reason.empty())
      pcout << "dealmpm: " << run_settings.method.anti_locking_reason
            << std::endl;
    // The set-up ends here: the output at t = 0 is the timer's "output".
    const std::string setup_time = setup_clock.report(comm);
    pcout << "dealmpm: " << setup_time << std::endl;
    if (!resume_warning.empty())
      warn("resumed from an older checkpoint", resume_warning);
    if (!resumed_checkpoint.empty())
      pcout << "dealmpm: resumed from " << resumed_checkpoint << " at step "
            << loop.step << " (t = " << loop.time << ")" << std::endl;
  }

  // run() instantiates the loop's other members it calls.
  template void
  Simulation<2>::run();
  template void
  Simulation<3>::run();
} // namespace dealmpm
