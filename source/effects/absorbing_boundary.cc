#include <dealmpm/effects/absorbing_boundary.h>


namespace dealmpm
{
  template <int dim>
  void
  AbsorbingBoundary<dim>::setup(const EffectSetup<dim> &setup,
                                SceneReader            &reader)
  {
    setup.conditions.require(reader,
                             "Boundary ids",
                             ids,
                             setup.grid,
                             "free",
                             "the dashpots stand for the ground beyond a "
                             "free face");
    grid_changed(setup.grid);
  }

  template <int dim>
  void
  AbsorbingBoundary<dim>::after_grid_update(const EffectContext<dim> &state,
                                            NodalFields<dim>         &fields)
  {
    for (const BoundaryNode<dim> &node : nodes)
      {
        const unsigned int i = node.local_index;
        const double       m = fields.mass.local_element(i);
        if (!(m > state.mass_threshold))
          continue;
        const Tensor<1, dim> n    = node.normal();
        const double         load = state.dt * density * node.area.norm() / m;
        Tensor<1, dim>       v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = fields.velocity[d].local_element(i);
        const Tensor<1, dim> v_n   = (v * n) * n;
        const Tensor<1, dim> v_new = v_n / (1 + load * p_wave_speed) +
                                     (v - v_n) / (1 + load * s_wave_speed);
        this->work += m * ((v_new - v) * v_new);
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields.velocity[d].local_element(i) = v_new[d];
            fields.velocity_increment[d].local_element(i) += v_new[d] - v[d];
          }
      }
    for (unsigned int d = 0; d < dim; ++d)
      {
        fields.velocity[d].update_ghost_values();
        fields.velocity_increment[d].update_ghost_values();
      }
  }

  template class AbsorbingBoundary<2>;
  template class AbsorbingBoundary<3>;
} // namespace dealmpm
