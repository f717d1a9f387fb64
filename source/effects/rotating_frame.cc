#include <deal.II/base/tensor.h>

#include <dealmpm/effects/rotating_frame.h>

namespace dealmpm
{
  namespace
  {
    template <int dim>
    Tensor<1, 3>
    lift(const Tensor<1, dim> &a)
    {
      Tensor<1, 3> b;
      for (unsigned int d = 0; d < dim; ++d)
        b[d] = a[d];
      return b;
    }
  } // namespace

  template <int dim>
  Tensor<1, dim>
  RotatingFrame<dim>::acceleration(const Tensor<1, 3>   &w,
                                   const Tensor<1, 3>   &w_dot,
                                   const Point<dim>     &axis_point,
                                   const Point<dim>     &x,
                                   const Tensor<1, dim> &v)
  {
    const Tensor<1, 3> r = lift<dim>(x - axis_point);
    const Tensor<1, 3> b = -cross_product_3d(w, cross_product_3d(w, r)) -
                           2. * cross_product_3d(w, lift<dim>(v)) -
                           cross_product_3d(w_dot, r);
    Tensor<1, dim> a;
    for (unsigned int d = 0; d < dim; ++d)
      a[d] = b[d];
    return a;
  }

  template <int dim>
  std::pair<Tensor<1, 3>, Tensor<1, 3>>
  RotatingFrame<dim>::rotation_at(const double t) const
  {
    const bool ramping = ramp_time > 0 && t < ramp_time;
    return {ramping ? t / ramp_time * omega : omega,
            ramping ? omega / ramp_time : Tensor<1, 3>()};
  }

  template <int dim>
  Tensor<1, dim>
  RotatingFrame<dim>::body_acceleration(const Point<dim> &,
                                        const Point<dim>     &x,
                                        const Tensor<1, dim> &v,
                                        const double          t) const
  {
    const auto [w, w_dot] = rotation_at(t);
    return acceleration(w, w_dot, axis_point, x, v);
  }

  template <int dim>
  void
  RotatingFrame<dim>::add_nodal_forces(const EffectContext<dim> &state,
                                       NodalFields<dim>         &fields)
  {
    // omega and its rate at mid-step.
    const auto [w, w_dot] = rotation_at(state.time + 0.5 * state.dt);
    this->work +=
      state.dt *
      add_particle_body_force(state,
                              fields,
                              [&](const Point<dim> &,
                                  const Point<dim>     &x,
                                  const Tensor<1, dim> &v) {
                                return acceleration(w, w_dot, axis_point, x, v);
                              });
  }

  template class RotatingFrame<2>;
  template class RotatingFrame<3>;

  template <int dim>
  void
  add_rotating_frame_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "rotating frame",
      "the scene in a frame turning about an axis (a centrifuge): "
      "centrifugal, Coriolis and, while it ramps up, Euler accelerations "
      "(section Rotating frame: Angular velocity, Axis point, Ramp "
      "time).",
      [](ParameterHandler &prm) {
        if (dim == 2)
          prm.declare_entry("Angular velocity",
                            "0",
                            Patterns::Double(),
                            "Omega (rad/s) about the z axis, "
                            "counter-clockwise positive.");
        else
          prm.declare_entry("Angular velocity",
                            "0, 0, 0",
                            Patterns::List(Patterns::Double(), 3, 3),
                            "The angular velocity vector omega (rad/s): "
                            "the axis's direction times the rate.");
        prm.declare_entry("Axis point",
                          dim == 2 ? "0, 0" : "0, 0, 0",
                          Patterns::List(Patterns::Double(), dim, dim),
                          "A point on the axis of rotation.");
        prm.declare_entry("Ramp time",
                          "0",
                          Patterns::Double(0),
                          "0: full rotation from t = 0. T > 0: omega "
                          "grows linearly from 0 over [0, T] (s), as a "
                          "centrifuge spins up.");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        Tensor<1, 3> omega;
        if (dim == 2)
          omega[2] = reader.get_double("Angular velocity");
        else
          omega = reader.get_vector<3>("Angular velocity");
        if (omega.norm() == 0.)
          reader.fail("Angular velocity",
                      "a rotation that is not zero (without one, leave "
                      "'rotating frame' out of 'Effects')");
        return std::make_unique<RotatingFrame<dim>>(
          omega,
          reader.get_point<dim>("Axis point"),
          reader.get_nonnegative("Ramp time"));
      });
  }

  template void
  add_rotating_frame_effect(Registry<Effect<2>> &);
  template void
  add_rotating_frame_effect(Registry<Effect<3>> &);
} // namespace dealmpm
