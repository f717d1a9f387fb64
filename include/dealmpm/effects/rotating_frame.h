#pragma once

#include <dealmpm/effects/effect_with_work.h>

#include <utility>

namespace dealmpm
{
  /**
   * The scene seen from a frame that turns with angular velocity omega
   * about an axis through a point c (a centrifuge, as Vaango's rotating
   * frame): each particle feels the centrifugal, Coriolis and (while the
   * rotation ramps up) Euler accelerations,
   *   b = -omega x (omega x r) - 2 omega x v - omega' x r,   r = x - c,
   * with v its velocity relative to the frame (acceleration()). In 2D the
   * axis is z and omega a number. The forces go to the nodes through the
   * particles' shape functions (add_particle_body_force). Their work,
   * dt sum_p m_p b . v_p per step (the Coriolis part does none), counts in
   * the energy balance.
   *
   * The Coriolis term is explicit: per step it turns v by 2 omega dt, and
   * the forward step lengthens it by a factor 1 + 2 (omega dt)^2, which
   * the CFL step of any elastic body keeps negligible (omega dt = 6e-4 in
   * the test of the free block).
   */
  template <int dim>
  class RotatingFrame : public EffectWithWork<dim>
  {
  public:
    /** @p omega in 3D components (2D: only z counts), @p ramp_time 0: at
     * once; T > 0: omega grows linearly from 0 over [0, T]. */
    RotatingFrame(const Tensor<1, 3> &omega,
                  const Point<dim>   &axis_point,
                  const double        ramp_time)
      : EffectWithWork<dim>("rotating_frame_work")
      , omega(omega)
      , axis_point(axis_point)
      , ramp_time(ramp_time)
    {}

    /** b at position @p x with velocity @p v relative to the frame, for
     * angular velocity @p w and its rate @p w_dot. */
    static Tensor<1, dim>
    acceleration(const Tensor<1, 3>   &w,
                 const Tensor<1, 3>   &w_dot,
                 const Point<dim>     &axis_point,
                 const Point<dim>     &x,
                 const Tensor<1, dim> &v);

    void
    add_nodal_forces(const EffectContext<dim> &state,
                     NodalFields<dim>         &fields) override;

    Tensor<1, dim>
    body_acceleration(const Point<dim>     &X,
                      const Point<dim>     &x,
                      const Tensor<1, dim> &v,
                      const double          t) const override;

  private:
    /** omega and its rate at time t. */
    std::pair<Tensor<1, 3>, Tensor<1, 3>>
    rotation_at(const double t) const;

    Tensor<1, 3> omega;
    Point<dim>   axis_point;
    double       ramp_time;
  };

  /** Register "rotating frame" in the effect table: its parameters (section
   * Rotating frame), their reading and checks. */
  template <int dim>
  void
  add_rotating_frame_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
