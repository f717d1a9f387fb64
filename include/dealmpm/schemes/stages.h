#pragma once

#include <dealmpm/schemes/step_state.h>
#include <dealmpm/schemes/update_scheme.h>

#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * One stage of an explicit step: a name, which is also its timer section,
   * and the function that runs it on the step's state. Each scheme is a
   * list of stages (stages_of()); Simulation::advance() runs the list.
   */
  template <int dim>
  struct Stage
  {
    std::string name;
    void (*run)(StepState<dim> &state, const std::string &timer_section);
  };

  /** The stages of one step of @p scheme, in order. Every list starts with
   * the stencil and ends with the particles moved and their stress updated;
   * relocation into new cells follows the list. With @p split_mixed_cells,
   * the mixed-cell split (MixedCellSplit) comes before the sweep that
   * deforms the particles, and that sweep applies it. With @p formulation
   * total Lagrangian, the stencil is the reference one, made in the first
   * step and kept; the other stages are the same. With @p newmark
   * (ParticleUpdate; the scheme is MUSL), the particles advance by
   * Newmark's formulas: P2G of the predicted velocity, the acceleration
   * and displacement velocity on the particles, its re-map, then one sweep
   * that moves, deforms and reports the velocity. With @p fem_regions,
   * the regions' forces and their bonded nodes' P2G follow the effects
   * after P2G, and their update (bonded nodes from v*) the effects after
   * the grid update. */
  template <int dim>
  std::vector<Stage<dim>>
  stages_of(const UpdateScheme scheme,
            const bool         split_mixed_cells = false,
            const Formulation  formulation = Formulation::updated_lagrangian,
            const bool         newmark     = false,
            const bool         fem_regions = false);

  /** The stages, each a function of the step's state. */
  namespace stages
  {
    /** Shape functions of every particle (and APIC's recorded positions);
     * stops the run naming the particle when one cannot be placed. */
    template <int dim>
    void
    stencil(StepState<dim> &state, const std::string &timer_section);

    /** Total Lagrangian's stencil, at the particles' reference positions:
     * made in the first step (compute_reference_stencil()), kept after. */
    template <int dim>
    void
    reference_stencil(StepState<dim> &state, const std::string &timer_section);

    /** P2G of mass, momentum (Newmark's predicted momentum when the scene
     * chose it) and internal force. */
    template <int dim>
    void
    p2g(StepState<dim> &state, const std::string &timer_section);

    /** P2G of mass and momentum (USF's and MUSL's re-map). */
    template <int dim>
    void
    p2g_mass_momentum(StepState<dim> &state, const std::string &timer_section);

    /** P2G of the internal force of the current stress (USF). */
    template <int dim>
    void
    p2g_force(StepState<dim> &state, const std::string &timer_section);

    /** Effects after P2G: external forces, then adjustments of the total
     * force; each effect timed as "effect: name". */
    template <int dim>
    void
    effect_forces(StepState<dim> &state, const std::string &timer_section);

    /** v* = v + dt f / m, boundary conditions, the FLIP increment. */
    template <int dim>
    void
    grid_update(StepState<dim> &state, const std::string &timer_section);

    /** Effects after the grid update (contact and coupling act on v*). */
    template <int dim>
    void
    effects_after_grid_update(StepState<dim>    &state,
                              const std::string &timer_section);

    /** The mixed-cell split's corrections from the grid velocity that the
     * next deforming sweep reads. */
    template <int dim>
    void
    mixed_cell_split(StepState<dim> &state, const std::string &timer_section);

    /** v = p / m with boundary conditions (USF, MUSL). */
    template <int dim>
    void
    velocity_from_momentum(StepState<dim>    &state,
                           const std::string &timer_section);

    /** One sweep: particle velocity, position, F and stress from v* (USL). */
    template <int dim>
    void
    g2p_and_stress_update(StepState<dim>    &state,
                          const std::string &timer_section);

    /** Particle velocity and position from v*. */
    template <int dim>
    void
    g2p(StepState<dim> &state, const std::string &timer_section);

    /** F and stress from the nodal velocity (USF: at the start of the
     * step; MUSL: re-mapped). */
    template <int dim>
    void
    stress_update(StepState<dim> &state, const std::string &timer_section);

    /** Newmark's acceleration and displacement velocity on the particles
     * (newmark_predict()). */
    template <int dim>
    void
    newmark_predictor(StepState<dim> &state, const std::string &timer_section);

    /** Newmark's move, F and stress from the re-mapped displacement
     * velocity, and the particle velocity (ReportNewmarkVelocity). */
    template <int dim>
    void
    newmark_motion(StepState<dim> &state, const std::string &timer_section);

    /** Each FEM region's forces (internal, tractions, the effects' body
     * forces), then its bonded nodes' mass, momentum and force to the
     * grid. */
    template <int dim>
    void
    fem_forces(StepState<dim> &state, const std::string &timer_section);

    /** Each FEM region's bonded nodes take v* back, then the region
     * advances. */
    template <int dim>
    void
    fem_update(StepState<dim> &state, const std::string &timer_section);

    /** Effects after G2P. */
    template <int dim>
    void
    effects_after_g2p(StepState<dim> &state, const std::string &timer_section);
  } // namespace stages
} // namespace dealmpm
