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
} // namespace dealmpm
