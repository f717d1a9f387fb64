#pragma once

#include <deal.II/base/point.h>

#include <dealmpm/core/registry.h>
#include <dealmpm/grid/nodal_fields.h>

#include <string>

namespace dealmpm
{
  /**
   * Optional physics a scene lists under "Effects". An effect that is not
   * listed is never constructed: it allocates nothing, runs no loop and has
   * no timer section. Effects act on the summed nodal fields between P2G and
   * the grid update, on the locally owned nodes.
   */
  template <int dim>
  class Effect
  {
  public:
    virtual ~Effect() = default;

    /** Add external nodal forces (body forces, tractions). */
    virtual void
    add_nodal_forces(NodalFields<dim> & /*fields*/) const
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
