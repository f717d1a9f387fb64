#pragma once

#include <dealmpm/base/base_motion.h>
#include <dealmpm/effects/effect_with_work.h>
#include <dealmpm/grid/boundary_nodes.h>

#include <optional>
#include <set>
#include <vector>

namespace dealmpm
{
  /**
   * Earthquake input at the base of the grid (free boundary ids).
   *
   * A rigid base sets the velocity of its nodes (all components) to the
   * record's after the grid update and again after MUSL's and USF's
   * re-map: a base motion given as forces would be undone by the re-map.
   *
   * A compliant base is the absorbing boundary's dashpots driven by the
   * incoming wave v_in (Joyner and Chen 1975): the traction rho c (2 v_in
   * - v) per component, rho c_p normal and rho c_s tangential, the record
   * being the outcrop motion w = 2 v_in (what a station on rock records).
   * Implicit as the absorbing boundary: v_n <- (v_n + a_p w_n) / (1 + a_p),
   * a_p = dt rho c_p |A| / m, likewise tangentially; waves going down
   * leave. A compliant base does not carry weight: the column's
   * geostatic reaction belongs on the same ids as a 'traction'.
   *
   * The work m (v* - v) . v* of the base on the nodes is the column
   * base_work; base_force_x, _y (_z) are the base's force on the
   * material in the last step, sum m (v* - v) / dt.
   */
  template <int dim>
  class BaseShaking : public EffectWithWork<dim>
  {
  public:
    explicit BaseShaking(const BaseMotion<dim> &motion)
      : EffectWithWork<dim>("base_work")
      , motion(motion)
    {}

    /** The record and the ground beyond the base (FEM regions' 'Shaken
     * boundaries' move with it too). */
    const BaseMotion<dim> &
    base_motion() const
    {
      return motion;
    }

    bool
    reads_stencil() const override
    {
      return false;
    }

    bool
    changes_core_velocity() const override
    {
      return true;
    }

    /** The ids must be on the grid and free of velocity conditions. */
    void
    setup(const EffectSetup<dim> &setup, SceneReader &reader) override;

    void
    grid_changed(const BackgroundGrid<dim> &grid) override
    {
      nodes = boundary_nodes(grid, motion.ids);
      set_velocity.clear();
    }

    void
    after_grid_update(const EffectContext<dim> &state,
                      NodalFields<dim>         &fields) override;

    void
    after_remap(const EffectContext<dim> &state,
                NodalFields<dim>         &fields) override;

    std::vector<std::pair<std::string, double>>
    statistics_columns() const override;

  private:
    BaseMotion<dim>                motion;
    const BoundaryConditions<dim> *conditions = nullptr;
    std::vector<BoundaryNode<dim>> nodes;
    Tensor<1, dim>                 force; ///< this rank's, of the last step
    /** Per node, the velocity the base gave it in the last grid update,
     * none for a node too light (after_remap() sets it again). */
    std::vector<std::optional<Tensor<1, dim>>> set_velocity;
  };

  /** Register "base shaking" in the effect table: its parameters (section
   * Base shaking), their reading and checks. */
  template <int dim>
  void
  add_base_shaking_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
