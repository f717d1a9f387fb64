#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/core/stop_signal.h>
#include <dealmpm/diagnostics/run_guards.h>
#include <dealmpm/diagnostics/run_messages.h>
#include <dealmpm/grid/grid_update.h>
#include <dealmpm/io/progress.h>
#include <dealmpm/materials/stress_update.h>
#include <dealmpm/particles/fill_bodies.h>
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/particle_to_grid.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <sstream>

namespace dealmpm
{

  template <int dim>
  void
  Simulation<dim>::declare_parameters(ParameterHandler &prm,
                                      const SceneShape &shape)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "2 (plane strain) or 3.");
    prm.declare_entry(
      "Number of bodies",
      "1",
      Patterns::Integer(1, 10000),
      "How many 'Body N' sections the scene has (N = 1, 2, ...).");
    prm.declare_entry("Number of materials",
                      "1",
                      Patterns::Integer(1, 10000),
                      "How many 'Material N' sections the scene has.");

    BackgroundGrid<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    for (unsigned int b = 1; b <= shape.n_bodies; ++b)
      {
        prm.enter_subsection("Body " + std::to_string(b));
        Body<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
    declare_material_sections<dim>(prm, shape.n_materials);
    declare_effect_parameters<dim>(prm);
    TimeStepping::declare_parameters(prm);
    MethodSettings::declare_parameters(prm);
    CheckSettings::declare_parameters(prm);
    OutputSettings::declare_parameters(prm);
  }

  template <int dim>
  Simulation<dim>::Simulation(ParameterHandler               &prm,
                              const std::string              &scene_file,
                              const SceneShape               &shape,
                              const MPI_Comm                  comm,
                              const std::vector<std::string> &overrides)
    : comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , scene_file(scene_file)
    , grid(comm)
    , output_writer(run_settings.output, comm)
  {
    SceneReader reader(prm, scene_file, overrides);
    read_scene(reader, shape);
    build_grid(reader);
    create_particles(reader);
    for (const auto &effect : effects)
      for (const FieldDescription &field : effect->nodal_fields_per_body())
        nodal.request_per_body(field);
    nodal.reinit(grid.partitioner, bodies.size());
    stages = stages_of<dim>(run_settings.method.scheme);

    particle_check  = check_particles(grid, materials, *particles);
    max_signal_rate = Utilities::MPI::max(particle_check.max_signal_rate, comm);
    computing_timer = std::make_unique<TimerOutput>(comm,
                                                    pcout,
                                                    TimerOutput::never,
                                                    TimerOutput::wall_times);
  }

  template <int dim>
  void
  Simulation<dim>::read_scene(SceneReader &reader, const SceneShape &shape)
  {
    run_settings.time   = TimeStepping::read(reader);
    run_settings.method = MethodSettings::read(reader);
    run_settings.checks = CheckSettings::read(reader);
    run_settings.output = OutputSettings::read(reader);
    {
      MaterialSections<dim> read =
        read_material_sections<dim>(reader, shape.n_materials);
      EffectList<dim> listed = read_effects(reader, read);
      materials              = std::move(read.materials);
      material_models        = std::move(read.models);
      effects                = std::move(listed.effects);
      effect_names           = std::move(listed.names);
    }
    for (unsigned int b = 1; b <= shape.n_bodies; ++b)
      {
        SectionScope section(reader, "Body " + std::to_string(b));
        bodies.push_back(Body<dim>::read(reader, shape.n_materials));
      }
  }

  template <int dim>
  void
  Simulation<dim>::build_grid(SceneReader &reader)
  {
    grid.create(reader, [&](const GridSize<dim> &size) {
      memory = check_memory(reader.file_name(),
                            estimate_memory(size, bodies),
                            run_settings.checks.memory_limit,
                            comm);
    });
    const std::string problem =
      kernel.setup(run_settings.method.shape_function, grid);
    if (!problem.empty())
      {
        SectionScope mpm(reader, "MPM");
        reader.fail("Shape function", problem);
      }
    boundary_conditions.setup(grid,
                              BoundaryConditions<dim>::read(
                                reader, grid.triangulation.get_boundary_ids()));
  }

  template <int dim>
  void
  Simulation<dim>::create_particles(SceneReader &reader)
  {
    std::vector<std::vector<FieldDescription>> internal;
    for (const auto &m : materials)
      internal.push_back(m->internal_variables());
    std::vector<FieldDescription> method_fields = kernel.particle_fields();
    if (run_settings.method.apic)
      method_fields.push_back({"apic_B", dim * dim});
    std::vector<FieldDescription> effect_fields;
    for (const auto &effect : effects)
      for (const FieldDescription &f : effect->particle_fields())
        effect_fields.push_back(f);
    particles = std::make_unique<ParticleSet<dim>>(grid.triangulation,
                                                   *grid.mapping,
                                                   material_models,
                                                   internal,
                                                   method_fields,
                                                   effect_fields);
    particles->handler.signals.particle_lost.connect(
      [this](const typename Particles::ParticleIterator<dim> &p,
             const typename Triangulation<dim>::active_cell_iterator &) {
        lost_this_step.emplace_back(p->get_id(), p->get_location());
      });

    std::vector<double>              densities;
    std::vector<std::vector<double>> initial;
    for (unsigned int m = 0; m < materials.size(); ++m)
      {
        densities.push_back(materials[m]->density);
        initial.emplace_back(particles->n_internal[m], 0.);
        materials[m]->initialize_internal_variables(
          make_array_view(initial.back()));
      }
    fill_bodies(reader, bodies, densities, initial, grid, *particles);
    if (!effects.empty())
      {
        for (const auto &effect : effects)
          effect->initialize_particles(*particles);
        particles->handler.sort_particles_into_subdomains_and_cells();
      }
    const Statistics s = statistics();
    mass_threshold =
      run_settings.method.relative_mass_threshold * s.mass / s.n_particles;
  }

  template <int dim>
  Statistics
  Simulation<dim>::statistics() const
  {
    return compute_statistics(*particles, materials, effects, loop.time, comm);
  }

  template <int dim>
  double
  Simulation<dim>::external_work() const
  {
    double work = 0;
    for (const auto &effect : effects)
      work += effect->work_done();
    return Utilities::MPI::sum(work, comm);
  }

  template <int dim>
  double
  Simulation<dim>::time_step() const
  {
    if (!run_settings.time.cfl_time_step)
      return run_settings.time.fixed_time_step;
    AssertThrow(max_signal_rate > 0, ExcInternalError());
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
    for (const Stage<dim> &stage : stages)
      stage.run(state, stage.name);

    particle_check                  = state.stress_update.check;
    const ParticleCheck<dim> &check = particle_check;
    {
      // One reduction for both: min of (-rate, J).
      double extremes[2] = {-check.max_signal_rate, check.min_J};
      Utilities::MPI::min(ArrayView<const double>(extremes, 2),
                          comm,
                          ArrayView<double>(extremes, 2));
      max_signal_rate = -extremes[0];
      loop.accuracy.observe_step(extremes[1], dt * max_signal_rate);
    }
    if (Utilities::MPI::logical_or(check.failed, comm))
      stop_on_particle(check.failed,
                       check.particle,
                       check.location,
                       check.reason,
                       loop.step + 1,
                       loop.time + dt,
                       comm);
    loop.time += dt;
    ++loop.step;
    if (Utilities::MPI::logical_or(state.left_cell, comm))
      {
        TimerOutput::Scope t(*computing_timer, "relocate");
        relocate_particles();
      }
  }

  template <int dim>
  void
  Simulation<dim>::relocate_particles()
  {
    lost_this_step.clear();
    particles->handler.sort_particles_into_subdomains_and_cells();
    const double n_lost =
      Utilities::MPI::sum(double(lost_this_step.size()), comm);
    if (n_lost == 0)
      return;
    loop.lost_particles += n_lost;
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
    pcout << "warning: " << message.str() << "; removed" << std::endl;
  }

  template <int dim>
  std::string
  Simulation<dim>::when(const unsigned int step, const double time) const
  {
    std::ostringstream text;
    text << std::setprecision(3) << "step " << step << " (t = " << time << ")";
    return text.str();
  }

  template <int dim>
  void
  Simulation<dim>::guard_fixed_time_step(const double dt)
  {
    const std::string warning = check_fixed_time_step(
      dt, max_signal_rate, run_settings.checks.cfl_warning, cfl_warned, [&] {
        return when(loop.step + 1, loop.time) + ": " +
               fastest_particle(particle_check,
                                max_signal_rate,
                                *particles,
                                comm);
      });
    if (warning.empty())
      return;
    pcout << "warning: " << warning << std::endl;
    cfl_warned = true;
  }

  template <int dim>
  RunError
  Simulation<dim>::energy_growth_stop() const
  {
    std::vector<Tensor<1, dim>> initial_velocity;
    for (const auto &body : bodies)
      initial_velocity.push_back(body.velocity);
    return energy_growth_error(*particles,
                               materials,
                               effects,
                               initial_velocity,
                               loop.accuracy.report().energy_drift,
                               run_settings.checks.energy_growth_limit,
                               when(loop.step, loop.time),
                               comm);
  }

  template <int dim>
  RunError
  Simulation<dim>::with_last_output(const RunError &error) const
  {
    return RunError(std::string(error.what()) + ". The last good output (t = " +
                    short_number(loop.output.last_time) + ") is in " +
                    run_settings.output.directory + "/");
  }

  template <int dim>
  void
  Simulation<dim>::write_output(const double      dt,
                                const Statistics &now,
                                const double      work,
                                const Progress   &progress)
  {
    TimerOutput::Scope t(*computing_timer, "output");
    output_writer.write({*particles, materials, grid, nodal.core},
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
  }

  template <int dim>
  void
  Simulation<dim>::map_particles_for_grid_output()
  {
    kernel.compute_stencil(grid, *particles, stencil);
    if (run_settings.method.apic)
      record_positions(grid, *particles, stencil);
    if (!Utilities::MPI::logical_or(stencil.failed, comm))
      {
        particle_to_grid(grid, *particles, stencil, nodal.core, true, false);
        velocity_from_momentum(nodal.core, mass_threshold, boundary_conditions);
      }
  }

  template <int dim>
  bool
  Simulation<dim>::finished() const
  {
    const TimeStepping &t = run_settings.time;
    return !(loop.time < t.end_time - 1e-9 * t.end_time) ||
           (t.max_steps != 0 && loop.step >= t.max_steps);
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
        throw with_last_output(error);
      }
    loop.particle_steps += n_particles;

    const bool output_due =
      finished() || (s.output.interval > 0 &&
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
        loop.accuracy.observe(now, work);
        if (energy_check_due &&
            loop.accuracy.report().energy_drift > s.checks.energy_growth_limit)
          throw with_last_output(energy_growth_stop());
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
  Simulation<dim>::run()
  {
    const RunSettings       &s = run_settings;
    const StopSignalHandlers signal_handlers;
    const Statistics         initial = statistics();
    const unsigned int       n_removed =
      output_writer.open(scene_file, initial.has_error);
    Progress progress(std::cout,
                      s.output.progress_interval,
                      Utilities::MPI::this_mpi_process(comm) == 0 &&
                        s.output.verbose);
    if (s.output.verbose)
      print_start(initial, n_removed);
    // The grid output at t = 0 shows the particles' mass and velocity p / m
    // on the nodes, as every later one does, instead of zeros.
    if (s.output.write_grid)
      map_particles_for_grid_output();
    loop.accuracy.start(initial);
    write_output(0., initial, 0., progress);

    loop.next_output = s.output.interval;
    double dt        = 0;
    while (!finished())
      {
        // mpirun passes the signal to every rank, but not at the same
        // moment: the ranks stop at the same step only if they agree.
        stopped_by_signal = Utilities::MPI::max(stop_signal(), comm);
        if (stopped_by_signal != 0)
          break;
        if (particles->handler.n_global_particles() == 0)
          throw RunError(when(loop.step, loop.time) +
                         ": no particles are left in the grid");
        dt = std::min(time_step(), s.time.end_time - loop.time);
        take_step(dt, progress);
      }
    if (stopped_by_signal != 0 && loop.output.last_step != loop.step)
      {
        const Statistics now  = statistics();
        const double     work = external_work();
        loop.accuracy.observe(now, work);
        write_output(dt, now, work, progress);
      }
    if (s.output.verbose)
      print_summary();
    if (stopped_by_signal != 0)
      pcout << "dealmpm: stopped by " << signal_name(stopped_by_signal)
            << " at step " << loop.step << " (t = " << loop.time
            << "); output in " << s.output.directory << "/ is complete"
            << std::endl;
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
      pcout << " (removed " << n_removed << " files of an earlier run)";
    pcout << std::endl;
  }

  template <int dim>
  void
  Simulation<dim>::print_summary() const
  {
    computing_timer->print_summary();
    pcout << "dealmpm: " << loop.accuracy.report() << std::endl;
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const double       rate =
      loop.stepping_time > 0 ? loop.particle_steps / loop.stepping_time : 0;
    pcout << "dealmpm: " << loop.step << " steps to t = " << loop.time << ", "
          << std::setprecision(4) << rate / 1e6 << " M particle-steps/s on "
          << n_ranks << " rank(s) (" << rate / 1e6 / n_ranks << " M per core)";
    Utilities::System::MemoryStats used;
    Utilities::System::get_memory_stats(used);
    pcout << ", peak memory " << used.VmHWM / 1024 << " MB on rank 0";
    if (loop.lost_particles > 0)
      pcout << ", " << loop.lost_particles << " particle(s) left the grid";
    pcout << std::endl;
  }

  template class Simulation<2>;
  template class Simulation<3>;
} // namespace dealmpm
