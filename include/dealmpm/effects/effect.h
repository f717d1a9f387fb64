#pragma once

#include <deal.II/base/point.h>

#include <dealmpm/base/registry.h>
#include <dealmpm/effects/drawn_body.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/boundary_conditions.h>
#include <dealmpm/grid/nodal_exchange.h>
#include <dealmpm/grid/nodal_field_set.h>
#include <dealmpm/materials/material_sections.h>
#include <dealmpm/particles/body.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealmpm
{
  template <int dim>
  class Effect;

  /** What an effect sees of the step it acts in. */
  template <int dim>
  struct EffectContext
  {
    const BackgroundGrid<dim> &grid;
    const ParticleSet<dim>    &particles;
    const Stencil<dim>        &stencil;
    double                     time; ///< at the start of the step
    double                     dt;
    /** Every nodal field, the per-body ones included. */
    NodalFieldSet<dim> &field_set;
    /** Nodes lighter than this are inactive. */
    double mass_threshold;
    /** The scene's effects, for the potential energy of a mass. */
    const std::vector<std::unique_ptr<Effect<dim>>> &effects;
    /** USL's stable nodal mass (stable_nodal_mass()), 0 in other
     * schemes. */
    double stable_mass = 0;

    /** Potential energy of a mass @p m at @p x in every effect's field
     * (gravity's), as the statistics count it. */
    double
    potential_energy(const double m, const Point<dim> &x) const;
  };

  /** What an effect may check and find at set-up. */
  template <int dim>
  struct EffectSetup
  {
    const BackgroundGrid<dim>     &grid;
    const BoundaryConditions<dim> &conditions;
    unsigned int                   n_bodies;
    /** The scene's bodies (shapes, particle patterns), alive for the run. */
    const std::vector<Body<dim>> &bodies;
  };

  /**
   * Optional physics a scene lists under "Effects". An effect that is not
   * listed is never constructed: it allocates nothing, runs no loop and has
   * no timer section. Effects act at named points of the step (the stages
   * in schemes/stages.h call them), on the locally owned nodes: after P2G
   * (external forces, then adjustments of the total force), after the grid
   * update and its boundary conditions (contact, rigid bodies, dashpots act
   * on v*), after USF's and MUSL's re-map, and at the end of the step
   * (erosion). Before any of that an effect may replace materials
   * (wrap_materials). The hooks may change the effect's own state (its
   * accumulators).
   */
  template <int dim>
  class Effect
  {
  public:
    virtual ~Effect() = default;

    /** Per-particle fields the effect stores (name, components): added to
     * the property layout only when the effect is listed; find them with
     * particles.layout.offset(name). */
    virtual std::vector<FieldDescription>
    particle_fields() const
    {
      return {};
    }

    /** Nodal fields the effect needs once per body (name, components), in
     * the nodal field set only when the effect is listed: accumulators of
     * its own (tests/scenes/extension_test.cc). Each body's mass,
     * momentum, force and velocity, which P2G and G2P use, come with
     * needs_body_fields(). */
    virtual std::vector<FieldDescription>
    nodal_fields_per_body() const
    {
      return {};
    }

    /** Right after the effect is made, before any particle: replace
     * some of the scene's materials by models of its own (damage wraps
     * them); a replaced material needs a model name of its own, for its
     * block of internal variables. */
    virtual void
    wrap_materials(MaterialSections<dim> & /*materials*/,
                   SceneReader & /*reader*/)
    {}

    /** Once the grid and its boundary conditions exist, before any
     * particle: check what the effect needs of the scene (@p reader is in
     * the effect's section, for one-line failures) and find its nodes. */
    virtual void
    setup(const EffectSetup<dim> & /*setup*/, SceneReader & /*reader*/)
    {}

    /** Whether each body needs nodal fields of its own (contact): P2G then
     * maps each body to its fields (NodalFieldSet::body), the core fields
     * being their sums, and G2P reads each particle's body's fields. */
    virtual bool
    needs_body_fields() const
    {
      return false;
    }

    /** The grid changed (refined, repartitioned): find the nodes again. */
    virtual void
    grid_changed(const BackgroundGrid<dim> & /*grid*/)
    {}

    /** Set initial particle state (a velocity field, a pre-deformed state),
     * once, after the bodies are made; particles may be moved (they are
     * sorted into their cells afterwards). */
    virtual void
    initialize_particles(ParticleSet<dim> & /*particles*/) const
    {}

    /** After P2G: add external nodal forces (body forces, tractions). An
     * effect that writes ghost entries compresses the force vectors itself. */
    virtual void
    add_nodal_forces(const EffectContext<dim> & /*state*/,
                     NodalFields<dim> & /*fields*/)
    {}

    /** After every effect's forces: change the total nodal forces
     * (damping). */
    virtual void
    adjust_nodal_forces(NodalFields<dim> & /*fields*/)
    {}

    /** Whether the effect changes the core fields' v* after the grid
     * update (wall friction, dashpots): contact, which moves each body
     * with its own fields, does not combine with such effects yet, and
     * the scene is refused. */
    virtual bool
    changes_core_velocity() const
    {
      return false;
    }

    /** Whether the effect reads the stored particle-node weights
     * (EffectContext::stencil). An effect that does not says so: then a
     * scene with linear or quadratic B-spline shape functions computes the
     * weights where P2G and G2P use them and stores none
     * (Stencil::where_used). */
    virtual bool
    reads_stencil() const
    {
      return true;
    }

    /** Whether the effect is reliable only when the particles take the
     * grid's velocity (PIC): the run warns under FLIP. */
    virtual bool
    wants_pic() const
    {
      return false;
    }

    /** After the grid update and its boundary conditions: act on v* and the
     * increment (contact, coupling). */
    virtual void
    after_grid_update(const EffectContext<dim> & /*state*/,
                      NodalFields<dim> & /*fields*/)
    {}

    /** After every effect's after_grid_update, when v* is final (walls,
     * friction, contact and rigid bodies have acted): count the work of
     * the effect's forces over the step, f . (v + v*) / 2 dt with v = p /
     * m, which vanishes at a node that stays at rest however the step
     * got there. */
    virtual void
    count_work(const EffectContext<dim> & /*state*/,
               const NodalFields<dim> & /*fields*/)
    {}

    /** After USF's and MUSL's re-map made the nodal velocity v = p / m
     * (with its boundary conditions) that the stress update reads: act on
     * it (contact). */
    virtual void
    after_remap(const EffectContext<dim> & /*state*/,
                NodalFields<dim> & /*fields*/)
    {}

    /** At the end of the step, after G2P and the stress update (erosion). */
    virtual void
    after_g2p(const EffectContext<dim> & /*state*/,
              ParticleSet<dim> & /*particles*/)
    {}

    /** Work done so far on this rank's particles by the effect's forces,
     * for forces without a potential (the energy balance counts it). */
    virtual double
    work_done() const
    {
      return 0;
    }

    /** The largest total magnitude of the effect's loads, sum |f_i| over
     * its nodes, in any step so far (this rank's share): times the cell
     * size, a scale of the energy the loads can put in that does not
     * vanish when a loaded body rests (the energy guard's floor). */
    virtual double
    load_magnitude() const
    {
      return 0;
    }

    /** Mass and momentum the effect took out of the run on purpose
     * (erosion) so far, on this rank: the mass and momentum checks count
     * them as kept. */
    virtual double
    removed_mass() const
    {
      return 0;
    }

    virtual Tensor<1, dim>
    removed_momentum() const
    {
      return {};
    }

    /** Whether the effect's forces leave the total momentum as it was
     * (contact between bodies; erosion, whose momentum counts as removed):
     * then the accuracy line still checks momentum. No by default. */
    virtual bool
    conserves_momentum() const
    {
      return false;
    }

    /** Columns of statistics.csv that the effect adds (name, this rank's
     * value; the values are summed over the ranks), the same names in
     * every call: friction work, a rigid body's reaction force. */
    virtual std::vector<std::pair<std::string, double>>
    statistics_columns() const
    {
      return {};
    }

    /** The effect's accumulators, for a saved run (core/run_state.h). */
    virtual std::vector<double>
    saved_state() const
    {
      return {};
    }

    /** Which entries of saved_state() are the same on every rank (a
     * ramp's factor, a rigid body's travel): true; the others are this
     * rank's share of a sum over the ranks (work, eroded mass), which a
     * run resumed on another number of ranks gives, summed, to one rank.
     * Empty: all are shares. */
    virtual std::vector<bool>
    state_shared_by_ranks() const
    {
      return {};
    }

    /** Take back what saved_state() gave. */
    virtual void
    restore_state(const std::vector<double> & /*state*/)
    {}

    /** The solids the effect moves, as the output draws them (a rigid
     * body's outline, each written as its own series), at the end of
     * the last step; @p grid_box is the grid's extent. None by default. */
    virtual std::vector<DrawnBody<dim>>
    drawn_bodies(const BoundingBox<dim> & /*grid_box*/) const
    {
      return {};
    }

    /** The body force per unit mass at reference position X, position x
     * and velocity v at time t (gravity, a rotating frame's), which FEM
     * regions take at their nodes; zero for effects without one. */
    virtual Tensor<1, dim>
    body_acceleration(const Point<dim> & /*X*/,
                      const Point<dim> & /*x*/,
                      const Tensor<1, dim> & /*v*/,
                      const double /*t*/) const
    {
      return {};
    }

    /** True when body_acceleration() depends on t alone (the same at
     * every X, x and v, as gravity's): FEM regions then take it once a
     * step instead of at every node. The default, false, is always
     * right. */
    virtual bool
    body_acceleration_is_uniform() const
    {
      return false;
    }

    /** The largest rate (1/s) of this rank's particles that bounds the step
     * as a wave speed over the cell size does (dt = CFL / rate): heat
     * conduction's 2 dim k / (rho c h^2). Asked once a step, at set-up
     * and after a grid change; 0 by default. */
    virtual double
    signal_rate(const ParticleSet<dim> & /*particles*/,
                const BackgroundGrid<dim> & /*grid*/) const
    {
      return 0;
    }

    /** Potential energy of a mass at x, for the statistics. */
    virtual double
    potential_energy(const double /*mass*/, const Point<dim> & /*x*/) const
    {
      return 0;
    }

    /** Whether potential_energy() at a fixed x keeps, at every time from
     * @p t on, the value it has at t (no ramp, or one that has ended).
     * FEM regions count a change of their nodes' potential in time as
     * work, and skip that sum over their nodes in steps where every
     * effect's potential is steady. The default, false, is always right. */
    virtual bool
    potential_steady_from(const double /*t*/) const
    {
      return false;
    }

    /** Effects that bring an exact solution (manufactured solutions): the
     * statistics then report the displacement error against it. */
    virtual bool
    has_exact_solution() const
    {
      return false;
    }

    /** Exact displacement of the material point at reference position X. */
    virtual Tensor<1, dim>
    exact_displacement(const Point<dim> & /*X*/, const double /*t*/) const
    {
      return {};
    }
  };

  /** Potential energy of a mass @p m at @p x in the fields of all
   * @p effects. */
  template <int dim>
  double
  potential_energy(const std::vector<std::unique_ptr<Effect<dim>>> &effects,
                   const double                                     m,
                   const Point<dim>                                &x)
  {
    double sum = 0;
    for (const auto &effect : effects)
      sum += effect->potential_energy(m, x);
    return sum;
  }

  template <int dim>
  double
  EffectContext<dim>::potential_energy(const double      m,
                                       const Point<dim> &x) const
  {
    return dealmpm::potential_energy(effects, m, x);
  }

  /**
   * f_i += sum_p N_ip m_p b(X_p, x_p, v_p) for a body force per unit mass
   * given at the particles' reference positions X_p, current positions
   * x_p and velocities v_p: a sweep over the particles of its own, so only
   * scenes with such an effect pay for it. Returns the force's power on
   * this rank's particles, sum_p m_p b . v_p.
   */
  template <int dim, typename BodyForce>
  double
  add_particle_body_force(const EffectContext<dim> &state,
                          NodalFields<dim>         &fields,
                          const BodyForce          &body_force)
  {
    const CoreFields &f = state.particles.fields;
    double           *force[dim];
    for (unsigned int d = 0; d < dim; ++d)
      {
        fields.force[d].zero_out_ghost_values();
        force[d] = fields.force[d].begin();
      }
    double power = 0;
    for_each_particle_in_stencil_order(
      state.grid,
      state.particles,
      [&](const std::size_t k, const auto &p, const GridCell<dim> &)
        DEAL_II_ALWAYS_INLINE {
          const auto           props = p.get_properties();
          const Point<dim>     x     = p.get_location();
          const Point<dim>     X = x - read_vector<dim>(&props[f.displacement]);
          const Tensor<1, dim> v = read_vector<dim>(&props[f.velocity]);
          const Tensor<1, dim> mb = props[f.mass] * body_force(X, x, v);
          power += mb * v;
          for (unsigned int e = state.stencil.begin[k];
               e < state.stencil.begin[k + 1];
               ++e)
            for (unsigned int d = 0; d < dim; ++d)
              force[d][state.stencil.node[e]] += state.stencil.N[e] * mb[d];
        });
    NodalExchange().add(fields.force).sum_ghosts_into_owners();
    return power;
  }

  /**
   * Registered effects. Each reads its parameters from a subsection titled
   * after it ("Gravity" for "gravity").
   */
  template <int dim>
  Registry<Effect<dim>> &
  effect_registry();

  /** "local damping" -> "Local damping". */
  std::string
  section_title(const std::string &name);
  /** The largest signal_rate() of @p effects on this rank. */
  template <int dim>
  double
  effects_signal_rate(const std::vector<std::unique_ptr<Effect<dim>>> &effects,
                      const ParticleSet<dim>    &particles,
                      const BackgroundGrid<dim> &grid)
  {
    double rate = 0;
    for (const auto &effect : effects)
      rate = std::max(rate, effect->signal_rate(particles, grid));
    return rate;
  }
} // namespace dealmpm
