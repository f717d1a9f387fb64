#pragma once

#include <deal.II/base/function_parser.h>

#include <dealmpm/base/load_curve.h>
#include <dealmpm/effects/effect.h>

#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * The region a rigid body fills at its start: signed distance (< 0
   * inside) and outward normal at any point.
   */
  template <int dim>
  struct RigidShape
  {
    enum class Kind
    {
      box,
      cylinder, ///< a disk in 2D; along z in 3D
      half_space
    };
    Kind           kind = Kind::box;
    Point<dim>     lower, upper; ///< box
    Point<dim>     centre;       ///< cylinder; a point of a half-space's face
    double         radius = 0;   ///< cylinder
    Tensor<1, dim> face_normal;  ///< half-space: outward, unit

    /** Signed distance of @p x to the surface, < 0 inside. */
    double
    distance(const Point<dim> &x) const;

    /** Outward unit normal of the surface nearest to @p x. */
    Tensor<1, dim>
    normal(const Point<dim> &x) const;

    /** Whether the surface point nearest to @p x lies on a face, not on
     * a box's edge or corner (always, for a cylinder or a half-space):
     * only there does the surface run level with what lies beneath. */
    bool
    under_a_face(const Point<dim> &x) const;

    /** Its outline moved by @p shift, for the output: a box as one cell,
     * a cylinder as 64 triangles (2D) or wedges (3D, as long as
     * @p grid_box is high), a half-space as a slab behind its face, as
     * wide as @p grid_box's diagonal and a tenth of it deep. */
    DrawnBody<dim>
    drawn(const Tensor<1, dim> &shift, const BoundingBox<dim> &grid_box) const;
  };

  /**
   * A rigid body moving with a prescribed velocity (a piston, a moving
   * wall, a punch, a fixed obstacle of any shape): grid nodes inside it
   * (at the end of the step) that move into it lose that normal velocity
   * relative to it, and Coulomb friction acts on their slip; components
   * outside the direction mask are left alone. So do the nodes just
   * outside under a face, as far as the particles that reach the face
   * extend (half their size): without them it would let go of the
   * material for half a particle spacing before each row of nodes, where
   * the particles it presses weigh nothing on the nodes inside it. Its position
   * is the integral of its velocity, V(t) = curve(t) v(t) with v expressions of
   * t.
   *
   * The force the material exerts on it, -sum_i m_i dv_i / dt over the
   * corrected nodes, is the statistics' rigid_force_x, _y (, _z) (that of
   * the last step), beside its displacement; the work it does on the
   * material, sum_i m_i dv_i . v_i, counts in the energy balance
   * (rigid_body_work). Under USF and MUSL it also holds the re-mapped
   * velocity that the stress update reads, at the nodes it pressed in the
   * last grid update (MUSL: the step's; USF, which re-maps first: the
   * last step's).
   */
  template <int dim>
  class RigidBody : public Effect<dim>
  {
  public:
    struct Settings
    {
      RigidShape<dim>          shape;
      std::vector<std::string> velocity; ///< dim expressions of t
      LoadCurve                curve;
      std::array<bool, dim>    mask;
      double                   friction = 0;
      /** Act only on the nodes of particles that reach it. */
      bool touch_check = false;
    };

    RigidBody(const Settings &settings, const SceneReader &reader);

    void
    setup(const EffectSetup<dim> &setup, SceneReader &) override
    {
      grid_changed(setup.grid);
    }

    void
    grid_changed(const BackgroundGrid<dim> &grid) override;

    /** Find how far the particles that reach it extend at their nodes;
     * with the touch check, mark those nodes. */
    void
    add_nodal_forces(const EffectContext<dim> &state,
                     NodalFields<dim>         &fields) override;

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

    bool
    wants_pic() const override
    {
      return settings.friction > 0;
    }

    double
    work_done() const override
    {
      return work;
    }

    std::vector<std::pair<std::string, double>>
    statistics_columns() const override;

    std::vector<double>
    saved_state() const override;
    /** The travel is the same on every rank, the work a share. */
    std::vector<bool>
    state_shared_by_ranks() const override
    {
      std::vector<bool> shared(dim, true);
      shared.push_back(false);
      return shared;
    }

    void
    restore_state(const std::vector<double> &state) override;

    /** Its outline at the end of the last step, and that step's
     * velocity. */
    std::vector<DrawnBody<dim>>
    drawn_bodies(const BoundingBox<dim> &grid_box) const override
    {
      DrawnBody<dim> body = settings.shape.drawn(moved, grid_box);
      body.velocity       = V_now;
      return {body};
    }

    /** How far it has moved. */
    const Tensor<1, dim> &
    displacement() const
    {
      return moved;
    }

  private:
    /** Its velocity at time @p t: the expressions times the load curve. */
    Tensor<1, dim>
    velocity_at(double t);

    /** Hold the nodes inside it and those within reach under a face;
     * returns the momentum given to them. */
    Tensor<1, dim>
    hold(const EffectContext<dim> &state,
         NodalFields<dim>         &fields,
         const Tensor<1, dim>     &V,
         const bool                count_work);

    Settings            settings;
    FunctionParser<dim> velocity;
    Tensor<1, dim>      moved;
    Tensor<1, dim>      V_now; ///< its velocity in the current step
    Tensor<1, dim>      force; ///< of the last step, this rank's share
    /** With the touch check: > 0 at the nodes of particles that reach it. */
    NodalVector touched;
    /** The largest half size of the particles that reach it, at their
     * stencils' nodes (0 elsewhere). */
    NodalVector reach;
    /** The locally owned nodes it pressed in the last grid update, which
     * the re-map holds again (MUSL: this step's, USF: the last step's);
     * empty after a grid change. */
    std::vector<bool> pressed_in_update;
    double            work = 0;
  };

  /** Register "rigid body" in the effect table: its parameters (section
   * Rigid body), their reading and checks. */
  template <int dim>
  void
  add_rigid_body_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
