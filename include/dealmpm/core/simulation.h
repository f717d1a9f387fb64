#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <dealmpm/adaptivity/adaptivity.h>
#include <dealmpm/adaptivity/load_balance.h>
#include <dealmpm/base/errors.h>
#include <dealmpm/base/parameter_file.h>
#include <dealmpm/core/run_report.h>
#include <dealmpm/core/run_state.h>
#include <dealmpm/diagnostics/accuracy_report.h>
#include <dealmpm/diagnostics/check_settings.h>
#include <dealmpm/diagnostics/memory_estimate.h>
#include <dealmpm/diagnostics/statistics.h>
#include <dealmpm/effects/effect.h>
#include <dealmpm/effects/effect_list.h>
#include <dealmpm/fem/fem_regions.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/boundary_conditions.h>
#include <dealmpm/grid/nodal_field_set.h>
#include <dealmpm/io/checkpoint.h>
#include <dealmpm/io/output_settings.h>
#include <dealmpm/io/output_writer.h>
#include <dealmpm/io/progress.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/materials/material_sections.h>
#include <dealmpm/particles/body.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/schemes/method_settings.h>
#include <dealmpm/schemes/stages.h>
#include <dealmpm/schemes/time_stepping.h>
#include <dealmpm/schemes/update_scheme.h>
#include <dealmpm/transfer/kernel.h>
#include <dealmpm/transfer/mixed_cell_split.h>
#include <dealmpm/transfer/stress_update.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace dealmpm
{
  /** A run's settings, each section read by the part it belongs to. */
  struct RunSettings
  {
    TimeStepping        time;
    MethodSettings      method;
    CheckSettings       checks;
    OutputSettings      output;
    LoadBalanceSettings load_balance;
    CheckpointSettings  checkpoint;
  };

  /**
   * One MPM run: owns the grid, particles, materials and effects and runs
   * the explicit USL loop with output. Construction reads and checks every
   * parameter and builds the initial state; it throws InputError and writes
   * nothing on bad input.
   */
  template <int dim>
  class Simulation
  {
  public:
    /** Declare every entry of a scene of this shape. */
    static void
    declare_parameters(ParameterHandler &prm, const SceneShape &shape);

    /** @p overrides: the command line's "Section/Entry=value" items
     * (already applied to @p prm), for messages. With @p resume the run
     * starts from a checkpoint instead of the scene's initial state: the
     * one in that folder (see find_checkpoint()), or with "" in the
     * scene's 'Checkpoint/Directory'; a checkpoint that does not fit the
     * scene is refused with InputError. */
    Simulation(ParameterHandler                 &prm,
               const std::string                &scene_file,
               const SceneShape                 &shape,
               const MPI_Comm                    comm,
               const std::vector<std::string>   &overrides = {},
               const std::optional<std::string> &resume    = std::nullopt);

    /** The whole run: output at t = 0, every interval and at the end, a
     * progress line, the timing table. SIGTERM or SIGINT end it after the
     * current step with a last output (see stop_signal_received()); throws
     * OutputError when a file cannot be written. */
    void
    run();

    /** The signal (SIGTERM, SIGINT) that stopped run() early, or 0. */
    int
    stop_signal_received() const
    {
      return stopped_by_signal;
    }

    /** One USL step of size dt. */
    void
    advance(const double dt);

    /**
     * Change the grid between steps: @p set_flags marks cells of the
     * triangulation for refinement or coarsening. The particles move to the
     * new cells (none lost, none duplicated) and every part that keeps grid
     * data rebuilds, in this order: the grid (nodes, hanging-node
     * constraints, cell data; the mapping is kept), the shape function's
     * tables, the boundary conditions' nodes, the nodal fields; the stable
     * step is found again. Collective.
     */
    void
    change_grid(const std::function<void(Triangulation<dim> &)> &set_flags);

    /** Adapt the grid to the scene's 'Adaptivity' criteria (see
     * adaptivity/adaptivity.h), then split the particles too large for their
     * new cells. Returns whether any cell was flagged. Collective. */
    bool
    adapt_grid();

    /** Share the cells among the ranks by their particle weights (see
     * LoadBalanceSettings), the particles going with their cells, and
     * rebuild what change_grid() rebuilds. Collective; nothing changes on
     * one rank. */
    void
    repartition();

    /** Save the run as a checkpoint in 'Checkpoint/Directory' (see
     * io/checkpoint.h) and return its folder. Collective. */
    std::string
    write_checkpoint();


    /** The CFL time step of the current state (or the fixed one). */
    double
    time_step() const;

    Statistics
    statistics() const;

    double
    time() const
    {
      return loop.time;
    }
    unsigned int
    step_number() const
    {
      return loop.step;
    }
    /** The loop's state with each effect's accumulators, as it would be
     * saved. */
    RunState
    run_state() const;
    ParticleSet<dim> &
    particle_set()
    {
      return *particles;
    }
    const BackgroundGrid<dim> &
    background_grid() const
    {
      return grid;
    }
    const AdaptivitySettings<dim> &
    adaptivity_settings() const
    {
      return adaptivity;
    }
    const NodalFields<dim> &
    nodal_fields() const
    {
      return nodal.core;
    }
    /** Every nodal field, the per-body ones included. */
    const NodalFieldSet<dim> &
    nodal_field_set() const
    {
      return nodal;
    }
    /** The material of index m (0-based, "Material m+1"). */
    const Material<dim> &
    material(const unsigned int m) const
    {
      return *materials[m];
    }
    /** Drifts, smallest J, largest CFL number and errors so far. */
    const AccuracyReport &
    accuracy_report() const
    {
      return loop.accuracy.report();
    }
    /** Work done so far by effects without a potential (all ranks). */
    double
    external_work() const;
    /** The scene's FEM regions ("FEM region N"). */
    const std::vector<FemRegion<dim>> &
    fem_regions() const
    {
      return regions.list();
    }
    /** The scene's shape function, set up for the grid. */
    const Kernel<dim> &
    get_kernel() const
    {
      return kernel;
    }
    TimerOutput &
    timer()
    {
      return *computing_timer;
    }

  private:
    /** Pass two over the scene: settings, materials, effects, bodies. */
    void
    read_scene(SceneReader &reader, const SceneShape &shape);
    /** The grid (after the memory check), the shape function's grid data
     * and the boundary conditions. */
    void
    build_grid(SceneReader &reader, const CheckpointInfo *saved);
    /** The particles per cell the bodies put at @p p (0 outside them): the
     * cells' weights while build_grid() refines. */
    unsigned int
    expected_particles(const Point<dim> &p) const;
    /** The particle set: filled from the bodies, or loaded from the
     * @p saved run's checkpoint (after the grid was). */
    void
    create_particles(SceneReader &reader, const CheckpointInfo *saved);
    /** The checkpoint to resume from, checked against the scene. */
    CheckpointInfo
    find_saved_run(SceneReader &reader, const std::string &where);
    /** Take the loop's state, the effects' and the numbers of @p saved
     * from the checkpoint. */
    void
    restore_saved_run(const CheckpointInfo &saved);
    /** The output folder opened for a new or a resumed run; rank 0's
     * count of the earlier run's files removed. */
    unsigned int
    open_output(const Statistics &initial);
    /** Total Lagrangian's stencil at the reference positions; refuses
     * bodies that start apart. */
    void
    make_reference_stencil(SceneReader &reader);
    /** Connect the cells' particle weights and share the cells by them,
     * unless they are shared well already: by a checkpoint on as many
     * ranks, or by the bodies' expected particles in the grid's
     * refinement (to within start_imbalance_tolerance). */
    void
    start_load_balance(const CheckpointInfo *saved);
    /** The step's stages for the scene's method, and the first stable
     * step. */
    void
    choose_stages();
    /** Whether linear, quadratic B-spline or GIMP weights may be computed
     * where P2G and G2P use them instead of stored (Stencil::where_used):
     * nothing else reads them, and the B-spline's and GIMP's fit their
     * windows on this grid. Collective. */
    bool
    weights_where_used() const;
    /** Whether the shape function is cpGIMP, whose domains stretch with F
     * (Stencil::gimp_follows_deformation). */
    bool
    gimp_follows_deformation() const;
    /** Set the stencil's kind (weights_where_used()): at the start and
     * after each grid change, which may make GIMP's windows fit or not
     * (cpGIMP's are checked again every step: finish_step()). */
    void
    choose_weights();
    /** The step's one reduction and what it decides: the next step's
     * size, stops, relocation and the couplings' publication. */
    void
    finish_step(const ParticleCheck<dim> &step_check,
                const bool                left_cell,
                const double              dt);
    /** What this rank's half of a relocation found: 0 if it looked at
     * no particle, else 1 + ParticleSet::plan_relocation(); the particles
     * it held at walls. */
    struct RelocationPlan
    {
      int          local = 0;
      unsigned int held  = 0;
    };
    /** Relocation's first half, before the step's reduction so that the
     * ranks agree on the second there. */
    RelocationPlan
    plan_relocation(const bool left_cell, const bool failed);
    /** Relocation's second half, given the largest plan over the ranks:
     * then the held and lost particles are counted (a sum over the ranks
     * only where deal.II sorted or @p held_anywhere), and a lost particle
     * stops the run or is reported. */
    void
    finish_relocation(const int          everywhere,
                      const bool         held_anywhere,
                      const unsigned int held);
    /** After the cells changed (refinement or repartition): rebuild every
     * part that keeps grid data, in change_grid()'s order. */
    void
    rebuild_after_grid_change();
    /** Adapt the grid to the initial particles, a level per round, filling
     * the bodies again on each new grid. */
    void
    start_adaptivity(SceneReader &reader);
    /** Flag the cells by the criteria and change the grid if any cell
     * changes; returns whether one did. Collective. */
    bool
    change_grid_to_criteria();
    /** In the loop: repartition when the cell weight imbalance passes
     * the limit (checked every few steps). */
    void
    balance_load();
    /** One step of the loop with its checks and, when due, an output. */
    void
    take_step(const double dt, Progress &progress);
    /** A run stopped by a signal: with 'On stop signal', a checkpoint,
     * then its last output (unless its step had one); returns where the
     * checkpoint is ("" without). */
    std::string
    save_stopped_run(const double dt, const Progress &progress);
    /** Whether nothing acts on the scene from outside (no walls, no FEM
     * regions, only effects that conserve momentum): the accuracy line
     * checks momentum only then. */
    bool
    conserves_momentum() const;
    /** The output of the current state (statistics @p now, work @p work
     * of the effects), through the output writer; collective. */
    void
    write_output(const double      dt,
                 const Statistics &now,
                 const double      work,
                 const Progress   &progress);
    /** P2G of the initial state, so that the first grid output shows it. */
    void
    map_particles_for_grid_output();
    /** Stop on an unstable fixed step, warn once on a large one. */
    void
    guard_fixed_time_step(const double dt);
    /** The opening lines of a run: its size and where its output goes. */
    void
    print_start(const Statistics &initial, const unsigned int n_removed) const;

    /** Steps between energy checks besides the outputs: a statistics sweep
     * costs about a fifth of a step. */
    static constexpr unsigned int energy_check_interval = 50;

    /** First, so that it times the whole construction. */
    SetupClock         setup_clock;
    MPI_Comm           comm;
    ConditionalOStream pcout;
    std::string        scene_file;
    /** The command line that continues this run from its checkpoint (the
     * program as started, the scene, its -s overrides, --resume). */
    std::string                                 resume_command;
    RunSettings                                 run_settings;
    AdaptivitySettings<dim>                     adaptivity;
    bool                                        cell_limit_warned = false;
    BackgroundGrid<dim>                         grid;
    BoundaryConditions<dim>                     boundary_conditions;
    std::vector<std::unique_ptr<Material<dim>>> materials;
    std::vector<std::string>                    material_models;
    std::vector<std::unique_ptr<Effect<dim>>>   effects;
    std::vector<std::string>                    effect_names;
    std::vector<Body<dim>>                      bodies;
    std::unique_ptr<ParticleSet<dim>>           particles;
    FemRegions<dim>                             regions;
    /** The cells' particle weights on the triangulation's weight signal;
     * after particles, so that it is disconnected before they go. */
    boost::signals2::scoped_connection particle_weights;
    /** The weight imbalance the last repartition reached (1 until one
     * did): the loop's check allows the limit times that. */
    double                  balanced_imbalance = 1;
    NodalFieldSet<dim>      nodal;
    Kernel<dim>             kernel;
    MemoryEstimate          memory;
    Stencil<dim>            stencil;
    std::vector<Stage<dim>> stages;
    /** Only when the scene's materials differ in stiffness. */
    std::unique_ptr<MixedCellSplit<dim>> mixed_cells;
    double                               mass_threshold = 0;
    /** At the start, for USL's stable nodal mass (stable_nodal_mass()). */
    double mean_particle_mass = 0;
    /** This rank's step sections (no collectives), made last in the
     * constructor (the set-up is setup_clock's). */
    std::unique_ptr<TimerOutput> computing_timer;

    RunState loop; ///< time, step, outputs, monitor: what a resume needs
    double   max_signal_rate = 0;      ///< of the last stress update
    ParticleCheck<dim> particle_check; ///< this rank's, of the last step
    bool               cfl_warned = false;
    std::vector<std::pair<types::particle_index, Point<dim>>> lost_this_step;
    double            lost_mass_this_step = 0; ///< of lost_this_step, this rank
    int               stopped_by_signal   = 0;
    OutputWriter<dim> output_writer;
    /** The scene's entries a resume must keep (scene_entries()). */
    std::vector<std::string>              scene_entry_list;
    std::string                           resumed_checkpoint;
    std::string                           resume_warning;
    long long                             last_checkpoint_step = -1;
    std::chrono::steady_clock::time_point last_checkpoint_time;
  };

} // namespace dealmpm
