#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/core/stop_signal.h>
#include <dealmpm/diagnostics/run_guards.h>
#include <dealmpm/base/run_messages.h>
#include <dealmpm/grid/grid_update.h>
#include <dealmpm/io/progress.h>
#include <dealmpm/materials/initial_stress.h>
#include <dealmpm/transfer/stress_update.h>
#include <dealmpm/particles/fill_bodies.h>
#include <dealmpm/particles/hold_at_walls.h>
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/particle_to_grid.h>
#include <dealmpm/transfer/reference_stencil.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <limits>
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
    prm.declare_entry("Number of FEM regions",
                      "0",
                      Patterns::Integer(0, 1000),
                      "How many 'FEM region N' sections the scene has: "
                      "finite element solids beside the MPM bodies.");
    for (unsigned int r = 1; r <= shape.n_fem_regions; ++r)
      {
        prm.enter_subsection("FEM region " + std::to_string(r));
        FemRegionSettings<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
    declare_effect_parameters<dim>(prm);
    TimeStepping::declare_parameters(prm);
    MethodSettings::declare_parameters(prm);
    CheckSettings::declare_parameters(prm);
    OutputSettings::declare_parameters(prm);
    LoadBalanceSettings::declare_parameters(prm);
    CheckpointSettings::declare_parameters(prm);
    AdaptivitySettings<dim>::declare_parameters(prm);
  }

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
    , output_writer(run_settings.output, comm)
  {
    SceneReader reader(prm, scene_file, overrides);
    read_scene(reader, shape);
    scene_entry_list = scene_entries(prm);
    std::optional<CheckpointInfo> saved;
    if (resume)
      saved = find_saved_run(
        reader, resume->empty() ? run_settings.checkpoint.directory : *resume);
    const CheckpointInfo *saved_run = saved ? &*saved : nullptr;
    build_grid(reader, saved_run);
    create_particles(reader, saved_run);
    if (adaptivity.enabled())
      start_adaptivity(reader);
    if (run_settings.load_balance.enabled)
      {
        particle_weights =
          connect_particle_weights(grid.triangulation,
                                   particles->handler,
                                   run_settings.load_balance.particle_weight);
        // The cells were shared by count (a compact body sat on few ranks),
        // or a saved run's were shared among another number of ranks.
        if (!saved || saved->n_ranks != Utilities::MPI::n_mpi_processes(comm))
          repartition();
      }
    for (unsigned int e = 0; e < effects.size(); ++e)
      {
        for (const FieldDescription &field :
             effects[e]->nodal_fields_per_body())
          nodal.request_per_body(field);
        if (effects[e]->needs_body_fields())
          {
            check_body_fields(reader, effect_names[e]);
            nodal.request_body_fields();
            for (unsigned int other = 0; other < effects.size(); ++other)
              if (effects[other]->changes_core_velocity())
                reader.fail("Effects",
                            "'" + effect_names[e] + "' without '" +
                              effect_names[other] +
                              "': it acts on the grid's common velocity, "
                              "which each body's own does not see yet");
          }
      }
    nodal.reinit(grid.partitioner, bodies.size());
    create_fem_regions(reader, shape);
    if (total_lagrangian())
      check_total_lagrangian(reader);
    else if (run_settings.method.split_mixed_cells)
      {
        mixed_cells = std::make_unique<MixedCellSplit<dim>>(materials);
        if (!mixed_cells->needed())
          mixed_cells.reset();
      }
    stages = stages_of<dim>(run_settings.method.scheme,
                            mixed_cells != nullptr,
                            run_settings.method.formulation,
                            run_settings.method.particle_update.newmark,
                            !regions.empty());

    particle_check =
      check_particles(grid, materials, *particles, total_lagrangian());
    max_signal_rate =
      std::max(Utilities::MPI::max(particle_check.max_signal_rate, comm),
               fem_signal_rate());
    if (saved)
      restore_saved_run(*saved);
    computing_timer = std::make_unique<TimerOutput>(comm,
                                                    pcout,
                                                    TimerOutput::never,
                                                    TimerOutput::wall_times);
  }

  template <int dim>
  void
  Simulation<dim>::read_scene(SceneReader &reader, const SceneShape &shape)
  {
    run_settings.time         = TimeStepping::read(reader);
    run_settings.method       = MethodSettings::read(reader);
    run_settings.checks       = CheckSettings::read(reader);
    run_settings.output       = OutputSettings::read(reader);
    run_settings.load_balance = LoadBalanceSettings::read(reader);
    run_settings.checkpoint =
      CheckpointSettings::read(reader, run_settings.output.directory);
    adaptivity = AdaptivitySettings<dim>::read(reader);
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
  Simulation<dim>::build_grid(SceneReader &reader, const CheckpointInfo *saved)
  {
    SavedGrid saved_grid;
    if (saved != nullptr)
      saved_grid = {resumed_checkpoint + "/grid", saved->coarse_grid};
    grid.create(
      reader,
      [&](const GridSize<dim> &size) {
        memory = check_memory(reader.file_name(),
                              estimate_memory(size, bodies),
                              run_settings.checks.memory_limit,
                              comm);
      },
      saved != nullptr ? &saved_grid : nullptr);
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
    for (unsigned int e = 0; e < effects.size(); ++e)
      {
        SectionScope section(reader, section_title(effect_names[e]));
        effects[e]->setup({grid,
                           boundary_conditions,
                           static_cast<unsigned int>(bodies.size()),
                           bodies},
                          reader);
        if (effects[e]->wants_pic() && run_settings.method.flip_fraction > 0 &&
            !run_settings.method.apic)
          pcout << "warning: " << reader.file_name() << ": '" << effect_names[e]
                << "' is reliable only when the particles take the grid's "
                   "velocity: set 'MPM/Velocity update = PIC' (under FLIP "
                   "the particles' own velocities ring, and friction that "
                   "should hold lets bodies creep; see README, Effects)"
                << std::endl;
      }
  }

  template <int dim>
  void
  Simulation<dim>::create_particles(SceneReader          &reader,
                                    const CheckpointInfo *saved)
  {
    std::vector<std::vector<FieldDescription>> internal;
    for (const auto &m : materials)
      internal.push_back(m->internal_variables());
    std::vector<FieldDescription> method_fields = kernel.particle_fields();
    if (run_settings.method.apic)
      method_fields.push_back({"apic_B", dim * dim});
    if (run_settings.method.particle_update.newmark)
      method_fields.push_back({"acceleration", dim});
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
    if (saved != nullptr)
      {
        // Each particle's doubles are read back as they were written.
        if (saved->particle_layout != layout_description(particles->layout))
          throw InputError(
            resumed_checkpoint +
            ": the particles' properties differ from this run's (the "
            "checkpoint was written by another version of dealmpm)");
        particles->handler.deserialize();
        return;
      }

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
        // Total Lagrangian keeps each particle in the cell of its reference
        // position, where an effect's initial state may have moved it.
        if (!total_lagrangian())
          particles->handler.sort_particles_into_subdomains_and_cells();
      }
    start_geostatic_bodies(reader);
    const Statistics s = statistics();
    mass_threshold =
      run_settings.method.relative_mass_threshold * s.mass / s.n_particles;
  }

  template <int dim>
  Statistics
  Simulation<dim>::statistics() const
  {
    Statistics s =
      compute_statistics(*particles, materials, effects, loop.time, comm);
    add_fem_statistics(s);
    return s;
  }

  template <int dim>
  double
  Simulation<dim>::external_work() const
  {
    double work = 0;
    for (const auto &effect : effects)
      work += effect->work_done();
    return Utilities::MPI::sum(work + fem_external_work(), comm);
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
    state.mixed_cells = mixed_cells.get();
    if (!regions.empty())
      state.fem_regions = &regions;
    state.previous_dt = loop.last_dt;
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
      if (!regions.empty())
        max_signal_rate = std::max(max_signal_rate, fem_signal_rate());
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
    loop.last_dt = dt;
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
    const double held = hold_particles_at_walls(*particles,
                                                *grid.mapping,
                                                boundary_conditions.walls());
    lost_this_step.clear();
    particles->handler.sort_particles_into_subdomains_and_cells();
    const double local[2] = {held, double(lost_this_step.size())};
    double       counts[2];
    Utilities::MPI::sum(ArrayView<const double>(local, 2),
                        comm,
                        ArrayView<double>(counts, 2));
    loop.held_particles += counts[0];
    const double n_lost = counts[1];
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
  void
  Simulation<dim>::change_grid(
    const std::function<void(Triangulation<dim> &)> &set_flags)
  {
    const auto t = timed("grid change");
    if (total_lagrangian())
      throw RunError(step_and_time(loop.step, loop.time) +
                     ": the grid cannot change under 'MPM/Formulation = total "
                     "Lagrangian': its stencil belongs to the reference grid");
    set_flags(grid.triangulation);
    grid.triangulation.prepare_coarsening_and_refinement();
    particles->handler.prepare_for_coarsening_and_refinement();
    grid.triangulation.execute_coarsening_and_refinement();
    particles->handler.unpack_after_coarsening_and_refinement();
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
    if (total_lagrangian() && stencil.reference)
      throw RunError(step_and_time(loop.step, loop.time) +
                     ": the grid cannot be repartitioned under 'MPM/"
                     "Formulation = total Lagrangian' once its reference "
                     "stencil is made");
    particles->handler.prepare_for_coarsening_and_refinement();
    grid.triangulation.repartition();
    particles->handler.unpack_after_coarsening_and_refinement();
    rebuild_after_grid_change();
    ++loop.repartitions;
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
    for (FemRegion<dim> &region : regions)
      {
        if (region.bonded)
          region.bonded->grid_changed(grid);
        if (region.contact)
          region.contact->grid_changed(grid);
      }
    nodal.reinit(grid.partitioner, bodies.size());
    // Smaller cells, smaller stable step.
    particle_check =
      check_particles(grid, materials, *particles, total_lagrangian());
    max_signal_rate =
      std::max(Utilities::MPI::max(particle_check.max_signal_rate, comm),
               fem_signal_rate());
  }

  template <int dim>
  void
  Simulation<dim>::start_geostatic_bodies(SceneReader &reader)
  {
    // The uniform force per unit mass of the effects with a potential.
    Tensor<1, dim> g;
    for (const auto &effect : effects)
      for (unsigned int d = 0; d < dim; ++d)
        g[d] -= effect->potential_energy(1., Point<dim>::unit_vector(d)) -
                effect->potential_energy(1., Point<dim>());
    const CoreFields &f = particles->fields;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        if (!bodies[b].geostatic)
          continue;
        SectionScope section(reader, "Body " + std::to_string(b + 1));
        if (!(g.norm() > 0))
          reader.fail("Initial stress",
                      "'none' in a scene without gravity (no listed effect "
                      "has a uniform force field at t = 0; a gravity ramp "
                      "starts from none)");
        // Total Lagrangian's stencil is taken where F = I; a body filled
        // at rest under stress has no such configuration on record.
        if (total_lagrangian())
          reader.fail("Initial stress",
                      "'none' under 'MPM/Formulation = total Lagrangian' "
                      "(its reference configuration is the stress-free one)");
        const Tensor<1, dim> n = g / g.norm();
        // Depths from the top of the body's bounding box.
        const BoundingBox<dim> box = bodies[b].shape->bounding_box();
        double                 top = -std::numeric_limits<double>::max();
        for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
          top = std::max(top, -(n * box.vertex(v)));
        const unsigned int   m        = bodies[b].material;
        const Material<dim> &material = *materials[m];
        const double         K0 =
          bodies[b].K0 >= 0 ?
                    bodies[b].K0 :
                    confined_stress_ratio(material, particles->n_internal[m], n);
        std::string failure;
        for (auto &p : particles->handler)
          {
            const auto props = p.get_properties();
            if (static_cast<unsigned int>(props[f.body]) != b)
              continue;
            const double                  depth = top + n * p.get_location();
            const SymmetricTensor<2, dim> target =
              geostatic_stress(-material.density * g.norm() * depth, n, K0);
            Tensor<2, dim>          F;
            SymmetricTensor<2, dim> stress;
            if (!start_at_stress(material,
                                 target,
                                 F,
                                 stress,
                                 ArrayView<double>(
                                   props.data() + particles->internal_offset[m],
                                   particles->n_internal[m])))
              {
                if (failure.empty())
                  failure =
                    "'Material " + std::to_string(m + 1) +
                    "' cannot rest under the geostatic stress at depth " +
                    short_number(depth) + " (particle " +
                    std::to_string(p.get_id()) + ")";
                continue;
              }
            write_tensor<dim>(&props[f.deformation_gradient], F);
            write_symmetric<dim>(&props[f.stress], stress);
            // The particle fills its place at that stretch: its volume and
            // (cpGIMP, CPDI) its domain are those it was filled with.
            props[f.initial_volume] /= determinant(F);
            if (f.domain_half_length != numbers::invalid_unsigned_int)
              for (unsigned int d = 0; d < dim; ++d)
                props[f.domain_half_length + d] /= F[d][d];
          }
        failure = first_message(failure, comm);
        if (!failure.empty())
          reader.fail("K0",
                      "a K0 whose stress the material carries at rest "
                      "(inside its yield surface; 1 for a fluid): " +
                        failure + ", with K0 = " + short_number(K0));
      }
  }

  template <int dim>
  void
  Simulation<dim>::check_body_fields(SceneReader       &reader,
                                     const std::string &effect) const
  {
    SectionScope      mpm(reader, "MPM");
    const std::string why =
      " with '" + effect + "', which gives each body its own nodal fields";
    if (total_lagrangian())
      reader.fail("Formulation",
                  "'updated Lagrangian'" + why +
                    " (total Lagrangian keeps bodies bonded where they "
                    "share grid nodes)");
    if (run_settings.method.particle_update.newmark)
      reader.fail("Particle update", "'explicit'" + why);
  }

  template <int dim>
  void
  Simulation<dim>::check_total_lagrangian(SceneReader &reader)
  {
    SectionScope mpm(reader, "MPM");
    for (unsigned int m = 0; m < materials.size(); ++m)
      if (materials[m]->resets_deformation())
        reader.fail(
          "Formulation",
          "'updated Lagrangian' for a scene with a fluid ('Material " +
            std::to_string(m + 1) + "' is a '" + material_models[m] +
            "', whose particles flow past their neighbours; total "
            "Lagrangian keeps every particle's neighbours)");
    compute_reference_stencil(
      grid, kernel, *particles, run_settings.method.apic, stencil);
    if (Utilities::MPI::logical_or(stencil.failed, comm))
      reader.fail("Shape function",
                  "a shape function whose stencil can be made at the "
                  "reference positions (" +
                    first_message(stencil.failure, comm) + ")");
    const auto apart = bodies_apart(grid, *particles, stencil, bodies.size());
    if (apart.first != apart.second)
      reader.fail(
        "Formulation",
        "'updated Lagrangian' for bodies that start apart: bodies " +
          std::to_string(apart.first + 1) + " and " +
          std::to_string(apart.second + 1) +
          " share no grid node, and total Lagrangian has no contact between "
          "them (they would pass through each other)");
    particle_to_grid(grid, *particles, stencil, nodal.core, true, false);
    const std::set<types::boundary_id> untouched =
      boundary_conditions.walls_without_mass(grid,
                                             nodal.core.mass,
                                             mass_threshold);
    if (!untouched.empty())
      {
        std::string ids;
        for (const types::boundary_id id : untouched)
          ids += (ids.empty() ? "" : ", ") + std::to_string(id);
        pcout << "warning: " << reader.file_name()
              << ": no body touches the wall(s) of boundary id(s) " << ids
              << " at the start; under 'MPM/Formulation = total Lagrangian' a "
                 "wall holds only the material that starts on it, and a body "
                 "reaching it would pass through"
              << std::endl;
      }
  }

  template class Simulation<2>;
  template class Simulation<3>;
} // namespace dealmpm
