#include <deal.II/base/mpi.h>

#include <dealmpm/effects/base_shaking.h>
#include <dealmpm/grid/nodal_exchange.h>

namespace dealmpm
{
  template <int dim>
  void
  BaseShaking<dim>::setup(const EffectSetup<dim> &setup, SceneReader &reader)
  {
    setup.conditions.require(reader,
                             "Boundary ids",
                             motion.ids,
                             setup.grid,
                             "free",
                             "the base sets the velocity there itself");
    conditions = &setup.conditions;
    grid_changed(setup.grid);
  }

  template <int dim>
  void
  BaseShaking<dim>::after_grid_update(const EffectContext<dim> &state,
                                      NodalFields<dim>         &fields)
  {
    const Tensor<1, dim> w = motion.velocity(state.time + 0.5 * state.dt);
    force                  = Tensor<1, dim>();
    set_velocity.assign(nodes.size(), std::nullopt);
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const BoundaryNode<dim> &node = nodes[j];
        const unsigned int       i    = node.local_index;
        const double             m    = fields.mass.local_element(i);
        if (!(m > state.mass_threshold))
          continue;
        Tensor<1, dim> v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = fields.velocity[d].local_element(i);
        const Tensor<1, dim> v_new =
          motion.base_velocity(node.area, m, v, w, state.dt);
        this->work += m * ((v_new - v) * v_new);
        force += m * (v_new - v) / state.dt;
        set_velocity[j] = v_new;
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields.velocity[d].local_element(i) = v_new[d];
            fields.velocity_increment[d].local_element(i) += v_new[d] - v[d];
          }
      }
    // The walls keep their say at the corners they share with the base.
    conditions->project_with_increment(fields.velocity,
                                       fields.velocity_increment);
    NodalExchange()
      .add(fields.velocity)
      .add(fields.velocity_increment)
      .copy_owners_to_ghosts();
  }

  template <int dim>
  void
  BaseShaking<dim>::after_remap(const EffectContext<dim> &state,
                                NodalFields<dim>         &fields)
  {
    // The base's velocity again where the re-map made another, as the
    // walls are applied again: the record's (rigid) or, compliant, the
    // dashpots' of the last grid update (MUSL: this step's; USF: the
    // last step's, the velocity the step starts from).
    const bool           rigid = motion.rigid;
    const Tensor<1, dim> w     = motion.velocity(state.time + 0.5 * state.dt);
    if (!rigid && set_velocity.size() != nodes.size())
      return; // the first step, or the grid changed
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const unsigned int i = nodes[j].local_index;
        if (!(fields.mass.local_element(i) > state.mass_threshold) ||
            (!rigid && !set_velocity[j]))
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          fields.velocity[d].local_element(i) =
            rigid ? w[d] : (*set_velocity[j])[d];
      }
    conditions->project(fields.velocity);
    NodalExchange().add(fields.velocity).copy_owners_to_ghosts();
  }

  template <int dim>
  std::vector<std::pair<std::string, double>>
  BaseShaking<dim>::statistics_columns() const
  {
    std::vector<std::pair<std::string, double>> columns =
      EffectWithWork<dim>::statistics_columns();
    const char *axes[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      columns.emplace_back(std::string("base_force_") + axes[d], force[d]);
    return columns;
  }

  template class BaseShaking<2>;
  template class BaseShaking<3>;

  namespace
  {
    template <int dim>
    void
    declare_base_shaking_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0)),
                        "The free grid boundaries (ids without a condition "
                        "in 'Grid/Boundary conditions') that are the base, "
                        "e.g. '2'; empty when only FEM regions are shaken "
                        "(their 'Shaken boundaries').");
      prm.declare_entry(
        "Base",
        "rigid",
        Patterns::Selection("rigid|compliant"),
        "'rigid': the base nodes move with the record (waves coming down "
        "reflect: a base on much stiffer rock). 'compliant': dashpots of "
        "the rock below (Density, P-wave speed, S-wave speed) driven by the "
        "incoming wave, so that waves coming down leave; the record is then "
        "the outcrop motion (twice the incoming wave), and the base does "
        "not carry weight (add the geostatic reaction as a 'traction' on "
        "the same ids).");
      prm.declare_entry("Motion",
                        "acceleration",
                        Patterns::Selection("acceleration|velocity"),
                        "What the record is: an acceleration, integrated "
                        "exactly from t = 0 (a record that does not "
                        "integrate to zero leaves the base moving), or a "
                        "velocity.");
      prm.declare_entry("Amplitude",
                        repeat_value<dim>("0"),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "The motion's vector per unit of the record, in any "
                        "direction: m/s^2 (acceleration) or m/s, e.g. '9.81, "
                        "0' for a horizontal record in g.");
      prm.declare_entry("Load curve",
                        "",
                        Patterns::Anything(),
                        "The record, 't0: f0, t1: f1, ...' piecewise linear, "
                        "constant outside (a long record can continue over "
                        "lines ending in a backslash).");
      prm.declare_entry("Density",
                        "0",
                        Patterns::Double(0),
                        "Compliant base: density (kg/m^3) of the rock below.");
      prm.declare_entry("P-wave speed",
                        "0",
                        Patterns::Double(0),
                        "Compliant base: c_p (m/s) of the rock below.");
      prm.declare_entry("S-wave speed",
                        "0",
                        Patterns::Double(0),
                        "Compliant base: c_s (m/s) of the rock below.");
    }

    template <int dim>
    BaseMotion<dim>
    read_base_motion(SceneReader &reader)
    {
      BaseMotion<dim> motion;
      for (const double id : reader.get_doubles("Boundary ids"))
        motion.ids.insert(static_cast<types::boundary_id>(id));
      motion.rigid        = reader.get("Base") == "rigid";
      motion.acceleration = reader.get("Motion") == "acceleration";
      motion.amplitude    = reader.get_vector<dim>("Amplitude");
      if (reader.get("Load curve").empty())
        reader.fail("Load curve", "the record, 't0: f0, t1: f1, ...'");
      motion.record = LoadCurve::read(reader, "Load curve");
      if (!motion.rigid)
        {
          motion.density      = reader.get_positive("Density");
          motion.p_wave_speed = reader.get_positive("P-wave speed");
          motion.s_wave_speed = reader.get_positive("S-wave speed");
        }
      return motion;
    }
  } // namespace

  template <int dim>
  void
  add_base_shaking_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "base shaking",
      "earthquake input at the base: a rigid base moving with an "
      "acceleration or velocity record, or a compliant one (dashpots with "
      "the incoming wave) that lets waves leave (section Base shaking: "
      "Boundary ids, Base, Motion, Amplitude, Load curve, Density, P-wave "
      "speed, S-wave speed).",
      declare_base_shaking_parameters<dim>,
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        return std::make_unique<BaseShaking<dim>>(
          read_base_motion<dim>(reader));
      });
  }

  template void
  add_base_shaking_effect(Registry<Effect<2>> &);
  template void
  add_base_shaking_effect(Registry<Effect<3>> &);
} // namespace dealmpm
