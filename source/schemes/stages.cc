#include <dealmpm/base/run_messages.h>
#include <dealmpm/grid/grid_update.h>
#include <dealmpm/materials/linear_elastic.h>
#include <dealmpm/schemes/stages.h>
#include <dealmpm/transfer/f_bar.h>
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/newmark_update.h>
#include <dealmpm/transfer/particle_to_grid.h>
#include <dealmpm/transfer/reference_stencil.h>

#include <algorithm>
#include <functional>
#include <type_traits>

namespace dealmpm
{
  namespace
  {
    /** The stages of a scheme without FEM regions. */
    template <int dim>
    std::vector<Stage<dim>>
    scheme_stages(const UpdateScheme scheme,
                  const bool         split_mixed_cells,
                  const Formulation  formulation,
                  const bool         newmark)
    {
      using namespace stages;
      // Before the sweep that deforms the particles, from the velocity it
      // reads.
      const auto split = [&](std::vector<Stage<dim>> &list) {
        if (split_mixed_cells)
          list.push_back({"mixed-cell split", &mixed_cell_split<dim>});
      };
      const Stage<dim> first[] = {
        {"stencil",
         formulation == Formulation::total_lagrangian ?
           &reference_stencil<dim> :
           &stencil<dim>}};
      const Stage<dim> p2g_and_forces[] = {
        {"P2G", &p2g<dim>},
        {"effects after P2G", &effect_forces<dim>},
        {"grid update", &grid_update<dim>},
        {"effects after the grid update", &effects_after_grid_update<dim>}};
      std::vector<Stage<dim>> list(std::begin(first), std::end(first));
      if (newmark)
        {
          // MUSL's order, with the particles' displacement velocity re-mapped
          // in place of their momentum (MethodSettings requires MUSL).
          list.push_back({"P2G", &p2g<dim>});
          list.insert(list.end(),
                      std::begin(p2g_and_forces) + 1,
                      std::end(p2g_and_forces));
          list.push_back({"Newmark G2P", &newmark_predictor<dim>});
          list.push_back({"P2G", &p2g_mass_momentum<dim>});
          list.push_back({"grid update", &velocity_from_momentum<dim>});
          split(list);
          list.push_back(
            {"Newmark motion and stress update", &newmark_motion<dim>});
          list.push_back({"effects after G2P", &effects_after_g2p<dim>});
          return list;
        }
      switch (scheme)
        {
          case UpdateScheme::USL:
            // G2P and the stress update share one sweep: both use v*.
            list.insert(list.end(),
                        std::begin(p2g_and_forces),
                        std::end(p2g_and_forces));
            split(list);
            list.push_back(
              {"G2P and stress update", &g2p_and_stress_update<dim>});
            break;
          case UpdateScheme::USF:
            list.push_back({"P2G", &p2g_mass_momentum<dim>});
            list.push_back({"grid update", &velocity_from_momentum<dim>});
            split(list);
            list.push_back({"stress update", &stress_update<dim>});
            list.push_back({"P2G", &p2g_force<dim>});
            list.insert(list.end(),
                        std::begin(p2g_and_forces) + 1,
                        std::end(p2g_and_forces));
            list.push_back({"G2P", &g2p<dim>});
            break;
          case UpdateScheme::MUSL:
            // Re-mapping the updated particle momentum smooths v* where nodes
            // have little mass (a stressed particle entering an empty cell).
            list.insert(list.end(),
                        std::begin(p2g_and_forces),
                        std::end(p2g_and_forces));
            list.push_back({"G2P", &g2p<dim>});
            list.push_back({"P2G", &p2g_mass_momentum<dim>});
            list.push_back({"grid update", &velocity_from_momentum<dim>});
            split(list);
            list.push_back({"stress update", &stress_update<dim>});
            break;
        }
      list.push_back({"effects after G2P", &effects_after_g2p<dim>});
      return list;
    }
  } // namespace

  template <int dim>
  std::vector<Stage<dim>>
  stages_of(const UpdateScheme scheme,
            const bool         split_mixed_cells,
            const Formulation  formulation,
            const bool         newmark,
            const bool         fem_regions)
  {
    std::vector<Stage<dim>> list =
      scheme_stages<dim>(scheme, split_mixed_cells, formulation, newmark);
    if (!fem_regions)
      return list;
    // After the first of each named stage.
    const auto insert_after = [&](const std::string &name,
                                  const Stage<dim>  &stage) {
      const auto at =
        std::find_if(list.begin(), list.end(), [&](const auto &s) {
          return s.name == name;
        });
      AssertThrow(at != list.end(), ExcInternalError());
      list.insert(at + 1, stage);
    };
    insert_after("effects after P2G", {"FEM forces", &stages::fem_forces<dim>});
    insert_after("effects after the grid update",
                 {"FEM update", &stages::fem_update<dim>});
    return list;
  }


  namespace stages
  {
    /** Stop the run naming the particle whose stencil failed, if any. */
    template <int dim>
    void
    stop_on_failed_stencil(const StepState<dim> &s)
    {
      if (Utilities::MPI::logical_or(s.stencil.failed, s.grid.comm))
        stop_on_particle(s.stencil.failed,
                         s.stencil.failed_particle,
                         s.stencil.failed_location,
                         s.stencil.failure,
                         s.step,
                         s.time + s.dt,
                         s.grid.comm);
    }

    template <int dim>
    void
    stencil(StepState<dim> &s, const std::string &timer_section)
    {
      // P2G and G2P compute the weights (LinearWeights, WindowWeights):
      // no timer row.
      if (s.stencil.where_used)
        return;
      {
        TimerOutput::Scope t(s.timer, timer_section);
        s.kernel.compute_stencil(s.grid, s.particles, s.stencil);
        if (s.method.apic)
          record_positions(s.grid, s.particles, s.stencil);
      }
      // A failed stencil (CPDI) keeps finite entries, so the step can
      // finish: the run stops at the step's reduction (Simulation::
      // finish_step), without a collective of its own.
    }

    template <int dim>
    void
    reference_stencil(StepState<dim> &s, const std::string &timer_section)
    {
      if (s.stencil.reference)
        return;
      {
        TimerOutput::Scope t(s.timer, timer_section);
        compute_reference_stencil(
          s.grid, s.kernel, s.particles, s.method.apic, s.stencil);
      }
      stop_on_failed_stencil(s);
    }

    /** P2G into the core fields, or into each body's (contact) and
     * their sums. */
    template <int dim>
    void
    map_to_grid(StepState<dim> &s,
                const bool      mass_and_momentum,
                const bool      internal_force,
                const double    predictor_offset = 0)
    {
      if (s.field_set.has_body_fields())
        particle_to_body_grids(s.grid,
                               s.particles,
                               s.stencil,
                               s.field_set,
                               mass_and_momentum,
                               internal_force,
                               s.method.formulation,
                               predictor_offset);
      else
        particle_to_grid(s.grid,
                         s.particles,
                         s.stencil,
                         s.fields,
                         mass_and_momentum,
                         internal_force,
                         s.method.formulation,
                         predictor_offset);
    }

    template <int dim>
    void
    p2g(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope    t(s.timer, timer_section);
      const ParticleUpdate &update = s.method.particle_update;
      map_to_grid(s,
                  true,
                  true,
                  update.newmark ?
                    NewmarkStep(update, s.dt, s.previous_dt).predictor_offset :
                    0.);
    }

    /** MUSL's G2P re-maps mass and momentum in its sweep (RemapInSweep;
     * the 2D column: 574 -> 563 instructions per particle-step) unless the
     * re-map needs more than the updated velocity and the sweep's weights:
     * each body's fields (contact), or APIC's x_p in total Lagrangian
     * (the stencil's reference positions). */
    template <int dim>
    bool
    remaps_in_g2p(const StepState<dim> &s)
    {
      // Newmark runs MUSL's stages with its own G2P, not g2p(): its
      // re-map stays a P2G.
      return s.method.scheme == UpdateScheme::MUSL &&
             !s.method.particle_update.newmark &&
             !s.field_set.has_body_fields() &&
             !(s.method.apic &&
               s.method.formulation == Formulation::total_lagrangian);
    }

    /** @p sweep(remap) with the re-map MUSL's G2P makes (remaps_in_g2p();
     * with APIC's affine part compiled in only where the particles carry
     * it: a run-time switch in the box cells cost MUSL's 2D column 616
     * against 568 instructions per particle-step), or with NoRemap. The
     * re-map keeps P2G's mass unless bonded FE regions added theirs (the
     * re-map has the particles' alone). */
    template <int dim, typename Sweep>
    void
    with_remap(StepState<dim> &s, const Sweep &sweep)
    {
      NoRemap none;
      if (!remaps_in_g2p(s))
        return sweep(none);
      const auto run = [&](auto &&remap) {
        sweep(remap);
        remap.finish();
      };
      // Compiled in: chosen at run time (the mass summed in the box cells
      // but not added) it saved a third as much.
      const bool keep_mass = s.fem_regions == nullptr || s.fem_regions->empty();
      if (s.method.apic && keep_mass)
        run(RemapInSweep<dim, true, true>(s.fields, s.grid));
      else if (s.method.apic)
        run(RemapInSweep<dim, true>(s.fields, s.grid));
      else if (keep_mass)
        run(RemapInSweep<dim, false, true>(s.fields, s.grid));
      else
        run(RemapInSweep<dim>(s.fields, s.grid));
    }

    template <int dim>
    void
    p2g_mass_momentum(StepState<dim> &s, const std::string &timer_section)
    {
      // MUSL's G2P made the re-map (remaps_in_g2p()): no timer row.
      if (remaps_in_g2p(s))
        return;
      TimerOutput::Scope t(s.timer, timer_section);
      map_to_grid(s, true, false);
    }

    template <int dim>
    void
    p2g_force(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope t(s.timer, timer_section);
      map_to_grid(s, false, true);
    }

    /** Call @p hook on every effect, each in its own timer section. */
    template <int dim, typename Hook>
    void
    for_each_effect(StepState<dim> &s, const Hook &hook)
    {
      for (unsigned int e = 0; e < s.effects.size(); ++e)
        {
          TimerOutput::Scope t(s.timer, "effect: " + s.effect_names[e]);
          hook(*s.effects[e]);
        }
    }

    template <int dim>
    void
    effect_forces(StepState<dim> &s, const std::string &)
    {
      const EffectContext<dim> context = s.effect_context();
      for_each_effect(s, [&](Effect<dim> &effect) {
        effect.add_nodal_forces(context, s.fields);
      });
      // Damping-like effects act on the total force.
      for_each_effect(s, [&](Effect<dim> &effect) {
        effect.adjust_nodal_forces(s.fields);
      });
    }

    template <int dim>
    void
    grid_update(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope t(s.timer, timer_section);
      update_nodal_velocity(
        s.fields, s.dt, s.mass_threshold, s.boundary_conditions, s.stable_mass);
    }

    template <int dim>
    void
    effects_after_grid_update(StepState<dim> &s, const std::string &)
    {
      const EffectContext<dim> context = s.effect_context();
      for_each_effect(s, [&](Effect<dim> &effect) {
        effect.after_grid_update(context, s.fields);
      });
      for_each_effect(s, [&](Effect<dim> &effect) {
        effect.count_work(context, s.fields);
      });
    }

    template <int dim>
    void
    velocity_from_momentum(StepState<dim> &s, const std::string &timer_section)
    {
      {
        TimerOutput::Scope t(s.timer, timer_section);
        dealmpm::velocity_from_momentum(s.fields,
                                        s.mass_threshold,
                                        s.boundary_conditions);
      }
      const EffectContext<dim> context = s.effect_context();
      for_each_effect(s, [&](Effect<dim> &effect) {
        effect.after_remap(context, s.fields);
      });
    }

    template <int dim>
    void
    mixed_cell_split(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope t(s.timer, timer_section);
      s.mixed_cells->prepare(s.grid, s.particles, s.stencil, s.fields, s.dt);
    }

    /** The formulations as types, for the sweeps' template argument. */
    using UpdatedLagrangian =
      std::integral_constant<Formulation, Formulation::updated_lagrangian>;
    using TotalLagrangian =
      std::integral_constant<Formulation, Formulation::total_lagrangian>;

    /** Run @p sweep(formulation, adjust, increment) with the scene's
     * formulation (a std::integral_constant), the step's velocity-gradient
     * adjustment (the mixed-cell split if the scene has one, else none) and
     * F increment (first order unless the scene chose another), so that a
     * scene runs a sweep compiled with only what it chose. */
    template <int dim, typename Sweep>
    void
    with_deformation_choices(StepState<dim> &s, const Sweep &sweep)
    {
      const DeformationUpdate &update         = s.method.deformation_update;
      const auto               with_increment = [&](const auto  formulation,
                                      const auto &adjust) {
        if (update.variant == DeformationUpdate::Variant::first_order)
          sweep(formulation, adjust, FirstOrderIncrement());
        else
          sweep(formulation, adjust, ChosenIncrement{update});
      };
      // Total Lagrangian builds no mixed-cell split: no particle changes
      // cell.
      if (s.method.formulation == Formulation::total_lagrangian)
        with_increment(TotalLagrangian(), NoGradientAdjustment());
      else if (s.mixed_cells)
        with_increment(UpdatedLagrangian(), *s.mixed_cells);
      else
        with_increment(UpdatedLagrangian(), NoGradientAdjustment());
    }

    /** Run @p sweep(velocities) with the nodal velocities the particles
     * read: the core fields, or each particle its body's (contact); with
     * @p light (USL) the core fields' light-node weights when this step has
     * any (update_nodal_velocity()). */
    template <bool light = false, int dim, typename Sweep>
    void
    with_nodal_velocity(StepState<dim> &s, const Sweep &sweep)
    {
      if (s.field_set.has_body_fields())
        sweep(BodyVelocities<dim>(s.field_set, s.particles));
      else if (light && s.fields.has_light_nodes)
        sweep(WithLightNodes<dim>{s.fields});
      else
        sweep(s.fields);
    }

    /** The deforming G2P sweep @p what with the stress update in it: the
     * lean one (StressUpdate::Of, no virtual call per particle) when every
     * material is linear elastic and the sweep is the plain one (updated
     * Lagrangian, no mixed-cell split, first-order F increment, one set of
     * nodal velocities), so that only those sweeps are compiled twice; the
     * general one otherwise. Returns whether a particle left its cell. */
    template <G2P what,
              int dim,
              typename Velocities,
              typename FormulationType,
              typename Adjust,
              typename Increment>
    bool
    deform_and_update_stress(StepState<dim>       &s,
                             const Velocities     &velocities,
                             const FormulationType formulation,
                             const Adjust         &adjust,
                             const Increment      &increment)
    {
      const auto sweep = [&](auto      &&after_deformation,
                             const auto &adjust_gradient) {
        return grid_to_particle<what, decltype(formulation)::value>(
          s.grid,
          s.stencil,
          velocities,
          s.dt,
          s.method.flip_fraction,
          s.particles,
          after_deformation,
          adjust_gradient,
          increment);
      };
      if constexpr (FormulationType::value == Formulation::updated_lagrangian)
        if (s.method.anti_locking == AntiLocking::f_bar)
          {
            FBar<dim, StressUpdate<dim>, Increment> f_bar(s.stress_update,
                                                          increment,
                                                          s.dt,
                                                          s.particles);
            const bool left = sweep(f_bar, f_bar.adjusting(adjust));
            f_bar.flush();
            return left;
          }
      constexpr bool plain =
        FormulationType::value == Formulation::updated_lagrangian &&
        std::is_same_v<Adjust, NoGradientAdjustment> &&
        std::is_same_v<Increment, FirstOrderIncrement> &&
        !std::is_same_v<Velocities, BodyVelocities<dim>>;
      using Elastic = LinearElastic<dim>;
      if constexpr (plain)
        if (s.stress_update.template all_materials_are<Elastic>())
          return sweep(
            typename StressUpdate<dim>::template Of<Elastic>{s.stress_update},
            adjust);
      return sweep(s.stress_update, adjust);
    }

    template <int dim>
    void
    g2p_and_stress_update(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope t(s.timer, timer_section);
      with_nodal_velocity<true>(s, [&](const auto &velocities) {
        with_deformation_choices(
          s,
          [&](const auto  formulation,
              const auto &adjust,
              const auto &increment) {
            s.left_cell = deform_and_update_stress<G2P::motion_and_deformation>(
              s, velocities, formulation, adjust, increment);
          });
      });
    }

    /** MUSL's re-map and stress update compute their weights where they
     * use them from the reference location at the step's start: its G2P
     * leaves it, the stress update sets it. */
    template <int dim>
    bool
    defers_reference_location(const StepState<dim> &s)
    {
      return s.stencil.where_used && s.method.scheme == UpdateScheme::MUSL;
    }

    template <int dim>
    void
    g2p(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope t(s.timer, timer_section);
      with_nodal_velocity(s, [&](const auto &velocities) {
        with_remap(s, [&](auto &remap) {
          const auto motion = [&](const auto formulation, const auto what) {
            s.left_cell = grid_to_particle<decltype(what)::value,
                                           decltype(formulation)::value>(
              s.grid,
              s.stencil,
              velocities,
              s.dt,
              s.method.flip_fraction,
              s.particles,
              NoAfterDeformation(),
              NoGradientAdjustment(),
              FirstOrderIncrement(),
              remap);
          };
          using Motion = std::integral_constant<G2P, G2P::motion>;
          if (s.method.formulation == Formulation::total_lagrangian)
            motion(TotalLagrangian(), Motion());
          else if (defers_reference_location(s))
            motion(
              UpdatedLagrangian(),
              std::integral_constant<G2P, G2P::motion_keeping_reference>());
          else
            motion(UpdatedLagrangian(), Motion());
        });
      });
    }

    template <int dim>
    void
    stress_update(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope t(s.timer, timer_section);
      with_nodal_velocity(s, [&](const auto &velocities) {
        with_deformation_choices(
          s,
          [&](const auto  formulation,
              const auto &adjust,
              const auto &increment) {
            if constexpr (decltype(formulation)::value ==
                          Formulation::updated_lagrangian)
              if (defers_reference_location(s))
                {
                  deform_and_update_stress<G2P::deformation_then_reference>(
                    s, velocities, formulation, adjust, increment);
                  return;
                }
            deform_and_update_stress<G2P::deformation>(
              s, velocities, formulation, adjust, increment);
          });
      });
    }

    template <int dim>
    void
    newmark_predictor(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope t(s.timer, timer_section);
      newmark_predict(s.grid,
                      s.stencil,
                      s.fields,
                      NewmarkStep(s.method.particle_update,
                                  s.dt,
                                  s.previous_dt),
                      s.dt,
                      s.particles);
    }

    template <int dim>
    void
    newmark_motion(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope                       t(s.timer, timer_section);
      const CoreFields                        &f = s.particles.fields;
      ReportNewmarkVelocity<StressUpdate<dim>> report{
        NewmarkStep(s.method.particle_update, s.dt, s.previous_dt).reported,
        f.velocity,
        f.acceleration,
        s.stress_update};
      with_deformation_choices(
        s,
        [&](const auto formulation, const auto &adjust, const auto &increment) {
          s.left_cell = grid_to_particle<G2P::position_and_deformation,
                                         decltype(formulation)::value>(
            s.grid,
            s.stencil,
            s.fields,
            s.dt,
            s.method.flip_fraction,
            s.particles,
            report,
            adjust,
            increment);
        });
    }

    template <int dim>
    void
    fem_forces(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope t(s.timer, timer_section);
      s.fem_regions->compute_forces(s.time, s.dt, s.grid, s.field_set);
    }

    template <int dim>
    void
    fem_update(StepState<dim> &s, const std::string &timer_section)
    {
      TimerOutput::Scope t(s.timer, timer_section);
      s.fem_regions->update(s.time,
                            s.dt,
                            s.mass_threshold,
                            s.grid,
                            s.field_set,
                            s.particles,
                            s.stencil);
    }

    template <int dim>
    void
    effects_after_g2p(StepState<dim> &s, const std::string &)
    {
      const EffectContext<dim> context = s.effect_context();
      for_each_effect(s, [&](Effect<dim> &effect) {
        effect.after_g2p(context, s.particles);
      });
    }
  } // namespace stages

#define DEALMPM_INSTANTIATE(dim)              \
  template std::vector<Stage<dim>> stages_of( \
    UpdateScheme, bool, Formulation, bool, bool);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
