#pragma once

#include <deal.II/base/function_parser.h>

#include <dealmpm/base/load_curve.h>
#include <dealmpm/effects/effect_with_work.h>
#include <dealmpm/grid/boundary_nodes.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * Surface loads: a traction t (force per unit area, fixed directions) and
   * a pressure p (pushing along the inward normal), expressions of the
   * current position and time, times a load curve. They act
   *
   * - on the surface particles of listed bodies: each particle's outward
   *   area vector A0 (particles/surface_area.h, found once at the start,
   *   stored as the particle field "surface_area") carries the force
   *   f_p = factor (|A0| t - p a), a = A0 (dead load) or, for a follower
   *   pressure, the deformed area J F^-T A0 (Nanson), acting at the
   *   faces' centre x_p + F d0 (d0 stored as "surface_offset"): spread to
   *   the nodes with N_i(x_p) + grad N_i(x_p) . F d0, so that the loads'
   *   first moment, and with it the body's mean stress, is the faces' own
   *   rather than one biased by half a particle spacing;
   * - on the nodes of free grid boundaries: f_i = factor (|A_i| t - p A_i)
   *   with A_i the node's area vector, where material touches the node.
   *
   * The loads' work, f . (v + v*) / 2 summed over the nodes, counts in the
   * energy balance (column traction_work).
   */
  template <int dim>
  class Traction : public EffectWithWork<dim>
  {
  public:
    struct Settings
    {
      std::set<unsigned int>       bodies; ///< 0-based
      std::string                  selection = "1";
      std::set<types::boundary_id> boundary_ids;
      std::vector<std::string>     traction; ///< dim expressions
      std::string                  pressure = "0";
      bool                         follower = false;
      LoadCurve                    curve;
    };

    /** Parses the expressions; the reader fails on a bad one. */
    Traction(const Settings &settings, const SceneReader &reader);

    std::vector<FieldDescription>
    particle_fields() const override;

    /** The ids must be on the grid and free; the bodies must exist. */
    void
    setup(const EffectSetup<dim> &setup, SceneReader &reader) override;

    void
    grid_changed(const BackgroundGrid<dim> &grid) override;

    /** Each listed body's surface particles get their area vectors. */
    void
    initialize_particles(ParticleSet<dim> &particles) const override;

    void
    add_nodal_forces(const EffectContext<dim> &state,
                     NodalFields<dim>         &fields) override;

    void
    after_grid_update(const EffectContext<dim> &state,
                      NodalFields<dim>         &fields) override;

  private:
    /** factor (|A| t(x) - p(x) a), at the expressions' time. */
    Tensor<1, dim>
    load(const Point<dim>     &x,
         const double          factor,
         const double          area,
         const Tensor<1, dim> &a) const;

    Settings                       settings;
    FunctionParser<dim>            selection;
    FunctionParser<dim>            traction;
    FunctionParser<dim>            pressure;
    const std::vector<Body<dim>>  *bodies = nullptr;
    const BackgroundGrid<dim>     *grid   = nullptr;
    std::vector<BoundaryNode<dim>> nodes;
    std::array<NodalVector, dim>   nodal_load;
  };

  /** Register "traction" in the effect table: its parameters (section
   * Traction), their reading and checks. */
  template <int dim>
  void
  add_traction_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
