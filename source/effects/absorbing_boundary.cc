#include <dealmpm/effects/absorbing_boundary.h>
#include <dealmpm/grid/nodal_exchange.h>


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
    conditions = &setup.conditions;
    grid_changed(setup.grid);
  }

  template <int dim>
  void
  AbsorbingBoundary<dim>::after_grid_update(const EffectContext<dim> &state,
                                            NodalFields<dim>         &fields)
  {
    set_velocity.assign(nodes.size(), std::nullopt);
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const BoundaryNode<dim> &node = nodes[j];
        const unsigned int       i    = node.local_index;
        const double             m    = fields.mass.local_element(i);
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
        set_velocity[j] = v_new;
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields.velocity[d].local_element(i) = v_new[d];
            fields.velocity_increment[d].local_element(i) += v_new[d] - v[d];
          }
      }
    NodalExchange()
      .add(fields.velocity)
      .add(fields.velocity_increment)
      .copy_owners_to_ghosts();
  }

  template <int dim>
  void
  AbsorbingBoundary<dim>::after_remap(const EffectContext<dim> &state,
                                      NodalFields<dim>         &fields)
  {
    // The dashpots' velocity of the last grid update again where the
    // re-map made another (MUSL: this step's; USF: the last step's, the
    // velocity the step starts from), as the walls are applied again.
    if (set_velocity.size() != nodes.size())
      return; // the first step, or the grid changed
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const unsigned int i = nodes[j].local_index;
        if (!(fields.mass.local_element(i) > state.mass_threshold) ||
            !set_velocity[j])
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          fields.velocity[d].local_element(i) = (*set_velocity[j])[d];
      }
    conditions->project(fields.velocity);
    NodalExchange().add(fields.velocity).copy_owners_to_ghosts();
  }

  template class AbsorbingBoundary<2>;
  template class AbsorbingBoundary<3>;

  template <int dim>
  void
  add_absorbing_boundary_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "absorbing boundary",
      "viscous dashpots on free grid boundaries that let waves leave "
      "the grid (section Absorbing boundary: Boundary ids, Density, "
      "P-wave speed, S-wave speed).",
      [](ParameterHandler &prm) {
        prm.declare_entry("Boundary ids",
                          "",
                          Patterns::List(Patterns::Integer(0)),
                          "The free boundaries (ids without a condition "
                          "in 'Grid/Boundary conditions') that absorb, "
                          "e.g. '1, 2'.");
        prm.declare_entry("Density",
                          "0",
                          Patterns::Double(0),
                          "Density rho (kg/m^3) of the ground beyond the "
                          "boundary, usually the body's next to it.");
        prm.declare_entry("P-wave speed",
                          "0",
                          Patterns::Double(0),
                          "c_p (m/s) of the ground beyond, sqrt((lambda "
                          "+ 2 mu) / rho) for an elastic one: the normal "
                          "dashpot is rho c_p per unit area.");
        prm.declare_entry("S-wave speed",
                          "0",
                          Patterns::Double(0),
                          "c_s (m/s), sqrt(mu / rho): the tangential "
                          "dashpot is rho c_s per unit area.");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        std::set<types::boundary_id> ids;
        for (const double id : reader.get_doubles("Boundary ids"))
          ids.insert(static_cast<types::boundary_id>(id));
        if (ids.empty())
          reader.fail("Boundary ids", "at least one boundary id");
        return std::make_unique<AbsorbingBoundary<dim>>(
          ids,
          reader.get_positive("Density"),
          reader.get_positive("P-wave speed"),
          reader.get_nonnegative("S-wave speed"));
      });
  }

  template void
  add_absorbing_boundary_effect(Registry<Effect<2>> &);
  template void
  add_absorbing_boundary_effect(Registry<Effect<3>> &);
} // namespace dealmpm
