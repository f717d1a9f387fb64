#pragma once

#include <deal.II/base/point.h>

#include <dealmpm/core/registry.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/stencil.h>

#include <string>

namespace dealmpm
{
  /**
   * Optional physics a scene lists under "Effects". An effect that is not
   * listed is never constructed: it allocates nothing, runs no loop and has
   * no timer section. Effects act on the summed nodal fields between P2G and
   * the grid update, on the locally owned nodes.
   */
  /** What an effect may read during a step. */
  template <int dim>
  struct StepState
  {
    const BackgroundGrid<dim> &grid;
    const ParticleSet<dim>    &particles;
    const Stencil<dim>        &stencil;
    double                     time; ///< at the start of the step
  };

  template <int dim>
  class Effect
  {
  public:
    virtual ~Effect() = default;

    /** Set initial particle state (a velocity field, a pre-deformed state),
     * once, after the bodies are made; particles may be moved (they are
     * sorted into their cells afterwards). */
    virtual void
    initialize_particles(ParticleSet<dim> & /*particles*/) const
    {}

    /** Add external nodal forces (body forces, tractions). An effect that
     * writes ghost entries compresses the force vectors itself. */
    virtual void
    add_nodal_forces(const StepState<dim> & /*state*/,
                     NodalFields<dim> & /*fields*/) const
    {}

    /** Change the total nodal forces once all are in (damping). */
    virtual void
    adjust_nodal_forces(NodalFields<dim> & /*fields*/) const
    {}

    /** Potential energy of a mass at x, for the statistics. */
    virtual double
    potential_energy(const double /*mass*/, const Point<dim> & /*x*/) const
    {
      return 0;
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
} // namespace dealmpm
