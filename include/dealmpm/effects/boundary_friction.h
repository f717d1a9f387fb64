#pragma once

#include <dealmpm/effects/dissipates_at_nodes.h>
#include <dealmpm/effects/effect_with_work.h>
#include <dealmpm/grid/boundary_nodes.h>

#include <map>
#include <vector>

namespace dealmpm
{
  /**
   * Coulomb friction on slip walls (section Boundary friction,
   * 'Coefficients = id: mu, ...'). After the grid update, on each wall node
   * the slip condition pushed (its removed normal velocity, from p + dt f
   * against v*), the tangential velocity loses at most mu times what the
   * wall took off the normal one (coulomb_change()); v* and the FLIP
   * increment change alike, so FLIP and PIC particles feel it. The nodes'
   * kinetic energy lost is the friction's (negative) work.
   *
   * The slip condition is two-sided: it also holds back nodes that leave
   * the wall, and under FLIP a body's bottom rings undamped, so that its
   * nodes push and pull in turn (a block sliding on an incline: the
   * pushes sum to 2.5 times its weight, the pulls to 1.5 times). A real
   * wall does not pull, and Coulomb's law knows only pushes: each wall id's
   * pulls are charged against its pushes (all ranks), every push scaled
   * by net / pushes, so that the friction acts on the net normal force.
   *
   * Under FLIP the friction is not reliable: the particles keep
   * velocities of their own, which the nodes' friction reaches only in
   * part, and their differences grow into a vibration that friction pumps
   * (a block on an incline slides at the Coulomb rate under PIC at h =
   * 1/40, 1/80 and 1/160, and under FLIP only at 1/40, 10 % slow; it
   * stalls at 1/80). A scene with it under FLIP gets a warning
   * (wants_pic()).
   */
  template <int dim>
  class BoundaryFriction : public EffectWithWork<dim>, public DissipatesAtNodes
  {
  public:
    bool
    reads_stencil() const override
    {
      return false;
    }

    explicit BoundaryFriction(
      const std::map<types::boundary_id, double> &coefficients)
      : EffectWithWork<dim>("boundary_friction_work")
      , coefficients(coefficients)
    {}

    /** Every id must be on the grid and carry a slip condition. */
    void
    setup(const EffectSetup<dim> &setup, SceneReader &reader) override;

    void
    grid_changed(const BackgroundGrid<dim> &grid) override;

    void
    after_grid_update(const EffectContext<dim> &state,
                      NodalFields<dim>         &fields) override;

    bool
    changes_core_velocity() const override
    {
      return true;
    }

    /** FLIP particles pump the wall's friction into a vibration. */
    bool
    wants_pic() const override
    {
      return true;
    }

  private:
    std::map<types::boundary_id, double> coefficients;
    std::vector<BoundaryNode<dim>>       nodes;
    std::vector<double>                  pressed; ///< per node, this step
  };

  /** Register "boundary friction" in the effect table: its parameters (section
   * Boundary friction), their reading and checks. */
  template <int dim>
  void
  add_boundary_friction_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
