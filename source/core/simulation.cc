#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/core/stop_signal.h>
#include <dealmpm/diagnostics/run_messages.h>
#include <dealmpm/grid/grid_update.h>
#include <dealmpm/io/grid_output.h>
#include <dealmpm/io/output_file.h>
#include <dealmpm/io/output_folder.h>
#include <dealmpm/io/particle_csv.h>
#include <dealmpm/io/progress.h>
#include <dealmpm/io/statistics_file.h>
#include <dealmpm/materials/stress_update.h>
#include <dealmpm/particles/fill_bodies.h>
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/particle_to_grid.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
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
  {
    SceneReader reader(prm, scene_file, overrides);
    read_run_settings(reader);
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
    grid.create(reader, [&](const GridSize<dim> &size) {
      memory = check_memory(reader.file_name(),
                            estimate_memory(size, bodies),
                            run_settings.checks.memory_limit,
                            comm);
    });
    {
      const std::string problem =
        kernel.setup(run_settings.method.shape_function, grid);
      if (!problem.empty())
        {
          SectionScope mpm(reader, "MPM");
          reader.fail("Shape function", problem);
        }
    }
    boundary_conditions.setup(grid,
                              BoundaryConditions<dim>::read(
                                reader, grid.triangulation.get_boundary_ids()));
    create_particles(reader);
    fields.reinit(grid.partitioner);
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
  Simulation<dim>::read_run_settings(SceneReader &reader)
  {
    run_settings.time   = TimeStepping::read(reader);
    run_settings.method = MethodSettings::read(reader);
    run_settings.checks = CheckSettings::read(reader);
    run_settings.output = OutputSettings::read(reader);
  }

  template <int dim>
  void
  Simulation<dim>::create_particles(SceneReader &reader)
  {
    std::vector<std::vector<FieldDescription>> internal;
    for (const auto &m : materials)
      internal.push_back(m->internal_variables());
    particles =
      std::make_unique<ParticleSet<dim>>(grid.triangulation,
                                         *grid.mapping,
                                         material_models,
                                         internal,
                                         run_settings.method.apic,
                                         has_particle_domain(
                                           run_settings.method.shape_function));
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
    return compute_statistics(
      *particles, materials, effects, current_time, comm);
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
  void
  Simulation<dim>::advance(const double dt)
  {
    StepState<dim> state(grid,
                         *particles,
                         kernel,
                         stencil,
                         fields,
                         boundary_conditions,
                         materials,
                         effects,
                         effect_names,
                         run_settings.method,
                         mass_threshold,
                         step + 1,
                         current_time,
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
      accuracy.observe_step(extremes[1], dt * max_signal_rate);
    }
    if (Utilities::MPI::logical_or(check.failed, comm))
      stop_on_particle(check.failed,
                       check.particle,
                       check.location,
                       check.reason,
                       step + 1,
                       current_time + dt,
                       comm);
    current_time += dt;
    ++step;
    if (Utilities::MPI::logical_or(state.left_cell, comm))
      {
        TimerOutput::Scope t(*computing_timer, "relocate");
        relocate_particles();
      }
  }

  template <int dim>
  std::string
  Simulation<dim>::fastest_particle() const
  {
    const bool here = particles->handler.n_locally_owned_particles() > 0 &&
                      particle_check.max_signal_rate == max_signal_rate;
    return first_message(here ?
                           "particle " +
                             std::to_string(particle_check.fastest) + " at " +
                             format_point(particle_check.fastest_location) :
                           "",
                         comm);
  }

  template <int dim>
  void
  Simulation<dim>::check_fixed_time_step(const double dt)
  {
    const double cfl = dt * max_signal_rate;
    if (cfl <= run_settings.checks.cfl_warning || (cfl_warned && cfl <= 1))
      return;
    std::ostringstream text;
    text << std::setprecision(3) << "step " << step + 1
         << " (t = " << current_time << "): " << fastest_particle()
         << ": the fixed time step " << dt
         << " gives a particle CFL number dt (c + |v|) / h of " << cfl;
    if (cfl > 1)
      throw RunError(text.str() +
                     " > 1, which is unstable; the largest stable step "
                     "here is " +
                     short_number(1. / max_signal_rate) +
                     ": set a smaller 'Time/Time step' or 'Time/Time step "
                     "method = CFL'");
    pcout << "warning: " << text.str() << " (above 'Checks/CFL warning' = "
          << run_settings.checks.cfl_warning
          << "; unstable above 1, at a step of "
          << short_number(1. / max_signal_rate) << "); warned once"
          << std::endl;
    cfl_warned = true;
  }

  template <int dim>
  RunError
  Simulation<dim>::energy_growth_error() const
  {
    std::vector<Tensor<1, dim>> initial_velocity;
    for (const auto &body : bodies)
      initial_velocity.push_back(body.velocity);
    const EnergyGain<dim> local =
      largest_energy_gain(*particles, materials, effects, initial_velocity);
    const double       largest = Utilities::MPI::max(local.gain, comm);
    std::ostringstream particle;
    particle << std::setprecision(3) << "particle " << local.particle << " at "
             << format_point(local.location) << " (+" << local.gain << " J)";
    std::ostringstream message;
    message << std::setprecision(3) << "step " << step
            << " (t = " << current_time << "): the total energy grew by "
            << 100 * accuracy.report().energy_drift
            << " % of the energy put in (limit 'Checks/Energy growth limit' "
               "= "
            << 100 * run_settings.checks.energy_growth_limit
            << " %); the particle whose energy grew most: "
            << first_message(local.gain == largest ? particle.str() : "", comm)
            << ". Energy grows when particles cross cells and when nodes "
               "carry little mass: try a smaller 'Time/CFL number', "
               "'MPM/Stress update = MUSL' or a GIMP or CPDI 'MPM/Shape "
               "function'";
    return RunError(message.str());
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
    lost_particles += n_lost;
    const std::string first =
      first_message(lost_this_step.empty() ?
                      "" :
                      "id " + std::to_string(lost_this_step[0].first) + " at " +
                        format_point(lost_this_step[0].second),
                    comm);
    std::ostringstream message;
    message << "step " << step << " (t = " << current_time << "): " << n_lost
            << " particle(s) left the grid (first: " << first << ")";
    if (run_settings.method.stop_when_particles_leave)
      throw RunError(message.str() +
                     "; set 'MPM/Particles leaving the grid = remove' "
                     "to drop such particles instead");
    pcout << "warning: " << message.str() << "; removed" << std::endl;
  }

  template <int dim>
  void
  Simulation<dim>::write_output(
    const std::function<void()> &write_statistics_row)
  {
    TimerOutput::Scope t(*computing_timer, "output");
    const std::string &dir    = run_settings.output.directory;
    const bool         writer = Utilities::MPI::this_mpi_process(comm) == 0;
    std::ostringstream context;
    context << "; the output in " << dir << "/ is complete";
    if (output_counter > 0)
      context << " up to t = " << last_output_time;
    else
      context << " but empty";

    // The files a series entry points to come first, on every rank; the
    // statistics row and the entries follow once all ranks have them, so
    // that a run stopped at any moment (or by a full disk) leaves no entry
    // without its files and row. Each writer does its collective part
    // before it can fail, so a rank that failed still takes part in the
    // rest, and all ranks throw together.
    std::string problem;
    const auto  attempt = [&problem](const auto &write) {
      try
        {
          write();
        }
      catch (const OutputError &e)
        {
          if (problem.empty())
            problem = e.what();
        }
    };
    std::string particle_file, grid_file;
    if (run_settings.output.write_particles)
      attempt([&] {
        particle_output.build_patches(*particles, materials);
        particle_file = particle_output.write(dir, output_counter, comm);
      });
    if (run_settings.output.write_grid)
      attempt([&] {
        grid_file = write_grid_output(grid, fields, dir, output_counter);
      });
    if (run_settings.output.write_particle_csv)
      attempt([&] {
        std::ostringstream name;
        name << dir << "/particles_" << std::setw(5) << std::setfill('0')
             << output_counter << ".csv";
        write_particle_csv(*particles, name.str(), comm);
      });
    agree_on_output_error(problem, context.str(), comm);
    if (writer)
      attempt([&] {
        write_statistics_row();
        if (!particle_file.empty())
          particle_series.add_and_write(current_time,
                                        particle_file,
                                        dir + "/particles.pvd");
        if (!grid_file.empty())
          grid_series.add_and_write(current_time, grid_file, dir + "/grid.pvd");
      });
    agree_on_output_error(problem, context.str(), comm);
    ++output_counter;
    last_output_time = current_time;
  }

  template <int dim>
  void
  Simulation<dim>::run()
  {
    const RunSettings &s      = run_settings;
    const bool         writer = Utilities::MPI::this_mpi_process(comm) == 0;
    const StopSignalHandlers        signal_handlers;
    const Statistics                initial = statistics();
    std::unique_ptr<StatisticsFile> stats;
    // Every rank learns whether rank 0 could make the folder: a rank that
    // throws alone would leave the others waiting. The broadcast also keeps
    // the others from writing before rank 0 has removed the earlier run's
    // files.
    std::string  problem, output_problem;
    unsigned int n_removed = 0;
    if (writer)
      try
        {
          std::filesystem::create_directories(s.output.directory);
          try
            {
              // An earlier run's series beside the new one (its later
              // steps, its grid files) would mislead whoever opens the
              // folder.
              n_removed = remove_earlier_output(s.output.directory);
              stats     = std::make_unique<StatisticsFile>(
                s.output.directory + "/statistics.csv", dim, initial.has_error);
            }
          catch (const OutputError &e)
            {
              output_problem = e.what();
            }
        }
      catch (const std::exception &e)
        {
          problem = e.what();
        }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw InputError(scene_file + ": entry 'Output/Directory' = '" +
                       s.output.directory +
                       "': expected a folder that can be created and "
                       "written (" +
                       problem + ")");
    agree_on_output_error(output_problem, "", comm);
    Progress progress(std::cout,
                      s.output.progress_interval,
                      writer && s.output.verbose);

    const double local_particles =
      particles->handler.n_locally_owned_particles();
    const double fewest = Utilities::MPI::min(local_particles, comm);
    const double most   = Utilities::MPI::max(local_particles, comm);
    if (s.output.verbose)
      {
        pcout << "dealmpm: " << dim << "D, "
              << grid.triangulation.n_global_active_cells() << " cells, "
              << grid.dof_handler.n_dofs() << " nodes, "
              << static_cast<unsigned long>(initial.n_particles)
              << " particles, " << Utilities::MPI::n_mpi_processes(comm)
              << " rank(s) (" << fewest << " to " << most
              << " particles per rank), about "
              << short_number(memory.bytes / 1e9) << " GB estimated; output in "
              << s.output.directory << "/";
        if (n_removed > 0)
          pcout << " (removed " << n_removed << " files of an earlier run)";
        pcout << std::endl;
      }
    if (s.output.write_grid)
      {
        // The grid output at t = 0 shows the particles' mass and velocity
        // p / m on the nodes, as every later one does, instead of zeros.
        kernel.compute_stencil(grid, *particles, stencil);
        if (s.method.apic)
          record_positions(grid, *particles, stencil);
        if (!Utilities::MPI::logical_or(stencil.failed, comm))
          {
            particle_to_grid(grid, *particles, stencil, fields, true, false);
            velocity_from_momentum(fields, mass_threshold, boundary_conditions);
          }
      }
    accuracy.start(initial);
    write_output([&] {
      stats->write_row(0,
                       0.,
                       0.,
                       initial,
                       0.,
                       accuracy.report(),
                       0,
                       progress.elapsed_seconds());
    });
    unsigned int last_output_step = step;
    // The statistics of the state written (already observed).
    const auto output =
      [&](const double dt, const Statistics &now, const double work) {
        write_output([&] {
          stats->write_row(step,
                           current_time,
                           dt,
                           now,
                           work,
                           accuracy.report(),
                           lost_particles,
                           progress.elapsed_seconds());
        });
        last_output_step = step;
      };

    double       next_output      = s.output.interval;
    double       particle_steps   = 0;
    double       stepping_time    = 0;
    double       dt               = 0;
    const double time_tolerance   = 1e-9 * s.time.end_time;
    const auto   with_last_output = [&](const RunError &error) {
      return RunError(
        std::string(error.what()) + ". The last good output (t = " +
        short_number(last_output_time) + ") is in " + s.output.directory + "/");
    };
    while (current_time < s.time.end_time - time_tolerance &&
           (s.time.max_steps == 0 || step < s.time.max_steps))
      {
        // mpirun passes the signal to every rank, but not at the same
        // moment: the ranks stop at the same step only if they agree.
        stopped_by_signal = Utilities::MPI::max(stop_signal(), comm);
        if (stopped_by_signal != 0)
          break;
        if (particles->handler.n_global_particles() == 0)
          throw RunError("step " + std::to_string(step) +
                         " (t = " + short_number(current_time) +
                         "): no particles are left in the grid");
        dt = std::min(time_step(), s.time.end_time - current_time);
        const double n_particles = particles->handler.n_global_particles();
        // Stepping time: the step and its checks, not the output.
        const auto start = std::chrono::steady_clock::now();
        try
          {
            if (!s.time.cfl_time_step)
              check_fixed_time_step(dt);
            advance(dt);
          }
        catch (const RunError &error)
          {
            throw with_last_output(error);
          }
        particle_steps += n_particles;

        const bool last = !(current_time < s.time.end_time - time_tolerance) ||
                          (s.time.max_steps != 0 && step >= s.time.max_steps);
        const bool output_due =
          last || (s.output.interval > 0 &&
                   current_time >= next_output - time_tolerance);
        const bool energy_check_due =
          s.checks.energy_growth_limit > 0 &&
          (output_due || step % energy_check_interval == 0);
        Statistics now;
        double     work = 0;
        if (output_due || energy_check_due)
          {
            now  = statistics();
            work = external_work();
            accuracy.observe(now, work);
            if (energy_check_due &&
                accuracy.report().energy_drift > s.checks.energy_growth_limit)
              throw with_last_output(energy_growth_error());
          }
        stepping_time += std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count();
        if (output_due)
          {
            // The next multiple of the interval (no loop: a tiny interval
            // cannot make it spin).
            if (s.output.interval > 0)
              next_output =
                (std::floor(current_time / s.output.interval + 1e-9) + 1) *
                s.output.interval;
            output(dt, now, work);
          }
        progress.update(step, current_time, dt, s.time.end_time, n_particles);
      }
    if (stopped_by_signal != 0 && last_output_step != step)
      {
        const Statistics now  = statistics();
        const double     work = external_work();
        accuracy.observe(now, work);
        output(dt, now, work);
      }

    if (s.output.verbose)
      {
        computing_timer->print_summary();
        pcout << "dealmpm: " << accuracy.report() << std::endl;
        const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
        const double       rate =
          stepping_time > 0 ? particle_steps / stepping_time : 0;
        pcout << "dealmpm: " << step << " steps to t = " << current_time << ", "
              << std::setprecision(4) << rate / 1e6 << " M particle-steps/s on "
              << n_ranks << " rank(s) (" << rate / 1e6 / n_ranks
              << " M per core)";
        Utilities::System::MemoryStats memory;
        Utilities::System::get_memory_stats(memory);
        pcout << ", peak memory " << memory.VmHWM / 1024 << " MB on rank 0";
        if (lost_particles > 0)
          pcout << ", " << lost_particles << " particle(s) left the grid";
        pcout << std::endl;
      }
    if (stopped_by_signal != 0)
      pcout << "dealmpm: stopped by " << signal_name(stopped_by_signal)
            << " at step " << step << " (t = " << current_time
            << "); output in " << s.output.directory << "/ is complete"
            << std::endl;
  }

  template class Simulation<2>;
  template class Simulation<3>;
} // namespace dealmpm
