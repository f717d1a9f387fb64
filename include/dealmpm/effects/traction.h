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
   * - on the surface particles of listed bodies: the faces of a selected
   *   particle that the load takes (particles/surface_area.h: those facing
   *   the given face normal, or those on the side the selection covers),
   *   found once at the start, with their area s0 (particle field
   *   "surface_size") and outward area vector A0 ("surface_area"), carry
   *   the force f_p = factor (s0 t - p a), a = A0 (dead load) or, for a
   *   follower
   *   pressure, the deformed area J F^-T A0 (Nanson), acting at the
   *   faces' centre x_p + F d0 (d0 stored as "surface_offset"): spread to
   *   the nodes with N_i(x_p) + grad N_i(x_p) . F d0, so that the loads'
   *   first moment, and with it the body's mean stress, is the faces' own
   *   rather than one biased by half a particle spacing;
   * - on the nodes of free grid boundaries: f_i = factor (|A_i| t - p A_i)
   *   with A_i the node's area vector, where material touches the node.
   *
   * The loads' work, f . (v + v*) / 2 dt summed over the nodes with the
   * step's final v* (after walls, friction and rigid bodies), counts in
   * the energy balance (column traction_work): a constant load on a body
   * held at rest does none.
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
      /** Zero: every face if all_faces, else inferred (see
       * loaded_face_normal). */
      Tensor<1, dim> face_normal;
      bool           all_faces = false;
      /** The entry as the scene gave it, for a later error. */
      std::string face_normal_entry;
      std::string pressure = "0";
      bool        follower = false;
      LoadCurve   curve;
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

    /** Each listed body's surface particles get their loaded faces; rank 0
     * says how much area is loaded, and facing where. */
    void
    initialize_particles(ParticleSet<dim> &particles) const override;

    void
    add_nodal_forces(const EffectContext<dim> &state,
                     NodalFields<dim>         &fields) override;

    void
    count_work(const EffectContext<dim> &state,
               const NodalFields<dim>   &fields) override;

    double
    load_magnitude() const override
    {
      return largest_load;
    }

  private:
    /** The face normal the loads take (zero: every surface face of the
     * selection): the one given; else none when the selection holds every
     * surface particle of its bodies (a closed surface) or its faces all
     * face one way; else an InputError naming the directions they face. */
    Tensor<1, dim>
    loaded_face_normal(const ParticleSet<dim> &particles) const;

    /** factor (s t(x) - p(x) a), at the expressions' time. */
    Tensor<1, dim>
    load(const Point<dim>     &x,
         const double          factor,
         const double          size,
         const Tensor<1, dim> &a) const;

    Settings                       settings;
    FunctionParser<dim>            selection;
    FunctionParser<dim>            traction;
    FunctionParser<dim>            pressure;
    const std::vector<Body<dim>>  *bodies = nullptr;
    const BackgroundGrid<dim>     *grid   = nullptr;
    std::vector<BoundaryNode<dim>> nodes;
    std::array<NodalVector, dim>   nodal_load;
    double                         largest_load = 0;
  };

  /** Register "traction" in the effect table: its parameters (section
   * Traction), their reading and checks. */
  template <int dim>
  void
  add_traction_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
