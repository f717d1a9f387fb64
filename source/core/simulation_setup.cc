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
#include <dealmpm/materials/cell_size_dependent.h>
#include <dealmpm/materials/geostatic_start.h>
#include <dealmpm/particles/fill_bodies.h>
#include <dealmpm/particles/hold_at_walls.h>
#include <dealmpm/schemes/compatibility.h>
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/particle_to_grid.h>
#include <dealmpm/transfer/reference_stencil.h>
#include <dealmpm/transfer/stress_update.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <limits>
#include <sstream>

// Building a run from its scene: the entries, the settings and parts read,
// the grid, the particles and the step's stages. The constructor that
// calls these, and the step, are in simulation.cc.
namespace dealmpm
{
  namespace
  {
    /** Whether every particle is still where it was made: at the point of
     * its listed cell that its reference location maps to (the set-up
     * makes each particle's location from its reference location by
     * GridCell::real_point, so an untouched particle matches bit for bit).
     * A false answer (a particle an effect moved, or one made otherwise)
     * costs a sort. No copy of the locations is needed to compare. */
    template <int dim>
    bool
    where_made(const BackgroundGrid<dim>             &grid,
               const Particles::ParticleHandler<dim> &handler)
    {
      for (const GridCell<dim> &c : grid.cells)
        for (const auto &p : handler.particles_in_cell(c.cell))
          if (p.get_location() != c.real_point(p.get_reference_location()))
            return false;
      return true;
    }

    /** Give the models that scale with the cell size (a regularised
     * softening) the grid's smallest cell edge: a band forms one cell
     * wide, and first where the cells are smallest. */
    template <int dim>
    void
    set_cell_sizes(const std::vector<std::unique_ptr<Material<dim>>> &materials,
                   const BackgroundGrid<dim>                         &grid,
                   const MPI_Comm                                     comm)
    {
      double h = std::numeric_limits<double>::max();
      for (const GridCell<dim> &c : grid.cells)
        h = std::min(h, c.h);
      h = Utilities::MPI::min(h, comm);
      for (const auto &material : materials)
        if (CellSizeDependent *dependent = needing_cell_size(*material))
          dependent->set_cell_size(h);
    }
  } // namespace

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
    FemRegions<dim>::declare_parameters(prm, shape.n_fem_regions);
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
  void
  Simulation<dim>::start_load_balance(const CheckpointInfo *saved)
  {
    if (!run_settings.load_balance.enabled)
      return;
    particle_weights =
      connect_particle_weights(grid.triangulation,
                               particles->handler,
                               run_settings.load_balance.particle_weight);
    // A saved run's cells were shared among another number of ranks; a
    // new run's by the bodies' expected particles if the grid was refined
    // (build_grid), else by count (a compact body sat on few ranks).
    if (saved != nullptr ?
          saved->n_ranks != Utilities::MPI::n_mpi_processes(comm) :
          weight_imbalance(grid.triangulation,
                           particles->handler,
                           run_settings.load_balance.particle_weight) >
            start_imbalance_tolerance)
      repartition();
  }

  template <int dim>
  void
  Simulation<dim>::choose_stages()
  {
    if (!run_settings.method.total_lagrangian() &&
        run_settings.method.split_mixed_cells)
      {
        mixed_cells = std::make_unique<MixedCellSplit<dim>>(materials);
        if (!mixed_cells->needed())
          mixed_cells.reset();
      }
    choose_weights();
    stages         = stages_of<dim>(run_settings.method.scheme,
                            mixed_cells != nullptr,
                            run_settings.method.formulation,
                            run_settings.method.particle_update.newmark,
                            !regions.empty());
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

  template <int dim>
  bool
  Simulation<dim>::weights_where_used() const
  {
    // The sweeps compute a particle's weights from its reference location
    // in its listed cell, which G2P's move changes after the sweeps of the
    // step that read them (MUSL's G2P leaves it to the stress update). The
    // other readers read stored weights: Newmark's predictor, the
    // mixed-cell split, FEM regions' contact, total Lagrangian's reference
    // stencil, most effects. APIC needs none (affine_transfer.h).
    const MethodSettings &method = run_settings.method;
    // GIMP's windows need every domain within half a cell, which splitting
    // and merging particles as the grid adapts would have to keep. APIC
    // with weights computed where used takes the weights' centroid for the
    // particle's position in P2G: that of a GIMP domain clipped at the
    // grid's edge is the clipped part's centre, not the particle's.
    // cpGIMP's windows only with USL: USF's force P2G follows its stress
    // update, which stretches the domains (the stored weights are the
    // step's start's), and under MUSL, whose three sweeps each compute
    // them, they cost 16 % (2D) and 30 % (3D) more instructions than a
    // stored stencil (doc/lean-step.md).
    const bool gimp_windows =
      kernel.gimp_lattice() != nullptr && !adaptivity.enabled() &&
      !method.apic &&
      !(gimp_follows_deformation() && method.scheme != UpdateScheme::USL);
    const bool computable = kernel.name() == "linear" ||
                            kernel.spline_grid() != nullptr || gimp_windows;
    if (!computable || method.particle_update.newmark ||
        method.total_lagrangian() || mixed_cells || !regions.empty() ||
        std::any_of(effects.begin(), effects.end(), [](const auto &effect) {
          return effect->reads_stencil();
        }))
      return false;
    return !gimp_windows ||
           domains_fit_windows(grid, *particles, gimp_follows_deformation());
  }

  template <int dim>
  bool
  Simulation<dim>::gimp_follows_deformation() const
  {
    return kernel.name() == "cpGIMP";
  }

  template <int dim>
  void
  Simulation<dim>::choose_weights()
  {
    stencil.where_used   = weights_where_used();
    stencil.spline       = stencil.where_used ? kernel.spline_grid() : nullptr;
    stencil.gimp_lattice = stencil.where_used ? kernel.gimp_lattice() : nullptr;
    stencil.gimp_half_length = particles->fields.domain_half_length;
    // cpGIMP's domains stretch: each step checks whether the next may keep
    // the windows (finish_step()). A scene that starts with a domain past
    // half a cell stores its weights for the run.
    stencil.gimp_follows_deformation =
      stencil.gimp_lattice != nullptr && gimp_follows_deformation();
    if (stencil.gimp_follows_deformation)
      stencil.gimp_stretch_limit = gimp_stretch_limit(grid);
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
    choose_anti_locking(run_settings.method,
                        materials,
                        material_models,
                        bodies);
    check_compatibility<dim>(reader,
                             {run_settings.method,
                              adaptivity,
                              materials,
                              material_models,
                              effects,
                              effect_names,
                              bodies,
                              shape.n_fem_regions});
  }

  template <int dim>
  unsigned int
  Simulation<dim>::expected_particles(const Point<dim> &p) const
  {
    // The last body there: a later body's particles replace earlier ones.
    for (auto body = bodies.rbegin(); body != bodies.rend(); ++body)
      if (body->shape->contains(p))
        return Utilities::fixed_power<dim>(body->particles_per_direction);
    return 0;
  }

  template <int dim>
  void
  Simulation<dim>::build_grid(SceneReader &reader, const CheckpointInfo *saved)
  {
    SavedGrid saved_grid;
    if (saved != nullptr)
      saved_grid = {resumed_checkpoint + "/grid", saved->coarse_grid};
    boost::signals2::scoped_connection expected_weights;
    if (saved == nullptr && run_settings.load_balance.enabled)
      expected_weights = connect_expected_weights<dim>(
        grid.triangulation,
        [this](const Point<dim> &p) { return expected_particles(p); },
        run_settings.load_balance.particle_weight);
    grid.create(
      reader,
      [&](const GridSize<dim> &size) {
        const StartRefinement start{
          adaptivity.enabled() ? adaptivity.min_level : 0u,
          adaptivity.level_of_particle_cells(),
          adaptivity.enabled() ? adaptivity.max_cells : 0.};
        memory = check_memory(reader.file_name(),
                              estimate_memory(size, bodies, start),
                              run_settings.checks.memory_limit,
                              comm);
      },
      saved != nullptr ? &saved_grid : nullptr,
      adaptivity.enabled());
    const std::string problem =
      kernel.setup(run_settings.method.shape_function, grid);
    if (!problem.empty())
      {
        SectionScope mpm(reader, "MPM");
        reader.fail("Shape function", problem);
      }
    set_cell_sizes(materials, grid, comm);
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
          warn("friction under FLIP",
               reader.file_name() + ": '" + effect_names[e] +
                 "' is reliable only when the particles take the grid's "
                 "velocity: set 'MPM/Velocity update = PIC' (under FLIP "
                 "the particles' own velocities ring, and friction that "
                 "should hold lets bodies creep; see doc/guide/limits.md)");
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
    std::vector<unsigned int> body_materials;
    for (const Body<dim> &body : bodies)
      body_materials.push_back(body.material);
    particles = std::make_unique<ParticleSet<dim>>(grid.triangulation,
                                                   *grid.mapping,
                                                   body_materials,
                                                   material_models,
                                                   internal,
                                                   method_fields,
                                                   effect_fields);
    particles->handler.signals.particle_lost.connect(
      [this](const typename Particles::ParticleIterator<dim> &p,
             const typename Triangulation<dim>::active_cell_iterator &) {
        lost_this_step.emplace_back(p->get_id(), p->get_location());
        lost_mass_this_step += p->get_properties()[FixedCore<dim>::mass];
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
        particles->changed();
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
        // Sort only if an effect moved a particle: a sort copies the whole
        // particle pool, which was the set-up's peak memory (and so was a
        // copy of the locations to compare with, which where_made avoids).
        if (!run_settings.method.total_lagrangian() &&
            Utilities::MPI::logical_or(!where_made(grid, particles->handler),
                                       comm))
          particles->sort();
      }
    start_geostatic_bodies(reader,
                           bodies,
                           materials,
                           uniform_acceleration(effects),
                           *particles,
                           comm);
    const Statistics s = statistics();
    mean_particle_mass = s.mass / s.n_particles;
    mass_threshold =
      run_settings.method.relative_mass_threshold * mean_particle_mass;
  }

  template <int dim>
  void
  Simulation<dim>::make_reference_stencil(SceneReader &reader)
  {
    SectionScope mpm(reader, "MPM");
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
        warn("walls no body touches",
             reader.file_name() +
               ": no body touches the wall(s) of boundary id(s) " + ids +
               " at the start; under 'MPM/Formulation = total Lagrangian' a "
               "wall holds only the material that starts on it, and a body "
               "reaching it would pass through");
      }
  }

#define DEALMPM_INSTANTIATE(dim)                                             \
  template void Simulation<dim>::declare_parameters(ParameterHandler &,      \
                                                    const SceneShape &);     \
  template void Simulation<dim>::start_load_balance(const CheckpointInfo *); \
  template void Simulation<dim>::choose_stages();                            \
  template bool Simulation<dim>::weights_where_used() const;                 \
  template void Simulation<dim>::choose_weights();                           \
  template bool Simulation<dim>::gimp_follows_deformation() const;           \
  template void Simulation<dim>::read_scene(SceneReader &,                   \
                                            const SceneShape &);             \
  template unsigned int Simulation<dim>::expected_particles(                 \
    const Point<dim> &) const;                                               \
  template void Simulation<dim>::build_grid(SceneReader &,                   \
                                            const CheckpointInfo *);         \
  template void Simulation<dim>::create_particles(SceneReader &,             \
                                                  const CheckpointInfo *);   \
  template void Simulation<dim>::make_reference_stencil(SceneReader &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
