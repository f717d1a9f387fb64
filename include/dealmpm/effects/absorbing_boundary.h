#pragma once

#include <dealmpm/effects/effect_with_work.h>
#include <dealmpm/grid/boundary_nodes.h>

#include <optional>
#include <set>
#include <vector>

namespace dealmpm
{
  /**
   * Viscous dashpots on free grid boundaries (Lysmer and Kuhlemeyer 1969),
   * so that waves leave the grid instead of coming back: a traction
   * -rho (c_p v_n n + c_s v_t) on the faces of the listed ids, rho c_p and
   * rho c_s the impedances of the ground beyond them. A plane wave that
   * meets the boundary head-on is taken whole.
   *
   * On each boundary node of area vector A the dashpot acts on v* after
   * the grid update, implicitly (backward Euler: v_n <- v_n / (1 + dt rho
   * c_p |A| / m), v_t likewise with c_s), so that it stays stable however
   * light the node; the FLIP increment changes alike. Its work, the
   * dashpots' force on the velocity they leave, counts in the energy
   * balance (column absorbed_work). USF's and MUSL's re-map makes the
   * nodal velocity again from the particles' momentum: the dashpots'
   * velocity is set again there (after_remap()), as the base shaking's
   * is, or the stress update would read a boundary without them (a
   * pulse left 1.7 % of its energy under MUSL).
   */
  template <int dim>
  class AbsorbingBoundary : public EffectWithWork<dim>
  {
  public:
    bool
    reads_stencil() const override
    {
      return false;
    }

    AbsorbingBoundary(const std::set<types::boundary_id> &ids,
                      const double                        density,
                      const double                        p_wave_speed,
                      const double                        s_wave_speed)
      : EffectWithWork<dim>("absorbed_work")
      , ids(ids)
      , density(density)
      , p_wave_speed(p_wave_speed)
      , s_wave_speed(s_wave_speed)
    {}

    /** The ids must be on the grid and free of velocity conditions. */
    void
    setup(const EffectSetup<dim> &setup, SceneReader &reader) override;

    void
    grid_changed(const BackgroundGrid<dim> &grid) override
    {
      nodes = boundary_nodes(grid, ids);
      set_velocity.clear();
    }

    void
    after_grid_update(const EffectContext<dim> &state,
                      NodalFields<dim>         &fields) override;

    void
    after_remap(const EffectContext<dim> &state,
                NodalFields<dim>         &fields) override;

    bool
    changes_core_velocity() const override
    {
      return true;
    }

  private:
    std::set<types::boundary_id>   ids;
    double                         density;
    double                         p_wave_speed;
    double                         s_wave_speed;
    std::vector<BoundaryNode<dim>> nodes;
    const BoundaryConditions<dim> *conditions = nullptr;
    /** Per node, the velocity the dashpots left in the last grid update,
     * none for a node too light. */
    std::vector<std::optional<Tensor<1, dim>>> set_velocity;
  };

  /** Register "absorbing boundary" in the effect table: its parameters (section
   * Absorbing boundary), their reading and checks. */
  template <int dim>
  void
  add_absorbing_boundary_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
