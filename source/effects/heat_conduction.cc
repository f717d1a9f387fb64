#include <dealmpm/effects/dissipates_at_nodes.h>
#include <dealmpm/effects/expressions.h>
#include <dealmpm/effects/heat_conduction.h>
#include <dealmpm/materials/damaged_material.h>
#include <dealmpm/materials/johnson_cook.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dealmpm
{
  template <int dim>
  HeatConduction<dim>::HeatConduction(const Settings    &settings,
                                      const SceneReader &reader)
    : settings(settings)
  {
    parse_expressions(initial,
                      {settings.initial_temperature},
                      false,
                      reader,
                      "Initial temperature",
                      "an expression of " + coordinate_names(dim, false) +
                        " (muparser), in K");
    has_source = settings.heat_source != "0";
    if (has_source)
      parse_expressions(source,
                        {settings.heat_source},
                        true,
                        reader,
                        "Heat source",
                        "an expression of " + coordinate_names(dim, true) +
                          " (muparser), in W/m^3");
  }

  template <int dim>
  void
  HeatConduction<dim>::wrap_materials(MaterialSections<dim> &sections,
                                      SceneReader           &reader)
  {
    const unsigned int         n     = sections.materials.size();
    const std::vector<double> &alpha = settings.thermal_expansion;
    if (alpha.size() != 1 && alpha.size() < n)
      reader.fail("Thermal expansion",
                  "one value for every material, or one per material (" +
                    std::to_string(n) + ")");
    expanding.assign(n, nullptr);
    working.assign(n, nullptr);
    johnson_cook_temperature.assign(n, -1);
    for (unsigned int m = 0; m < n; ++m)
      {
        const Material<dim> *model = sections.materials[m].get();
        if (settings.taylor_quinney > 0 && model->dissipates())
          working[m] = model;
        heats_by_work = heats_by_work || working[m] != nullptr;
        // Johnson-Cook (also damaged) keeps its temperature after the
        // shared variables: its own adiabatic heating gives way to ours.
        if (const auto *damaged =
              dynamic_cast<const DamagedMaterial<dim> *>(model))
          model = &damaged->inner_model();
        if (dynamic_cast<const JohnsonCook<dim> *>(model) != nullptr)
          johnson_cook_temperature[m] = JohnsonCook<dim>::model_index;
      }
    std::vector<std::string> models;
    for (unsigned int m = 0; m < n; ++m)
      {
        if (of_material(alpha, m) == 0.)
          continue;
        if (dim == 2 && !initial_elastic_constants(*sections.materials[m]))
          reader.fail("Thermal expansion",
                      "0 for material " + std::to_string(m + 1) + " ('" +
                        sections.models[m] +
                        "', with no elastic response from its initial "
                        "state): in plane strain the expansion needs its "
                        "Poisson's ratio; run it in 3D");
        // Each expanding model keeps its own block of internal variables.
        const std::string model = sections.models[m] + " expanding";
        const auto known    = std::find(models.begin(), models.end(), model);
        const std::size_t k = known - models.begin();
        if (known == models.end())
          models.push_back(model);
        auto wrapped = std::make_unique<ThermallyExpanding<dim>>(
          std::move(sections.materials[m]),
          of_material(alpha, m),
          k == 0 ? "" : "_" + std::to_string(k + 1));
        expanding[m]          = wrapped.get();
        sections.materials[m] = std::move(wrapped);
        sections.models[m]    = model;
      }
  }

  template <int dim>
  void
  HeatConduction<dim>::setup(const EffectSetup<dim> &setup, SceneReader &reader)
  {
    for (const auto &[entry, values] :
         {std::make_pair("Fixed temperatures", &settings.fixed_temperatures),
          std::make_pair("Heat fluxes", &settings.heat_fluxes),
          std::make_pair("Convection", &settings.convection)})
      {
        std::map<unsigned int, std::string> listed;
        for (const auto &[id, value] : *values)
          listed[id] = std::to_string(value);
        check_grid_has_ids(reader,
                           entry,
                           listed,
                           setup.grid.triangulation.get_boundary_ids());
      }
    unsigned int needed = 0;
    for (const Body<dim> &body : setup.bodies)
      needed = std::max(needed, body.material + 1);
    for (const auto &[entry, values] :
         {std::make_pair("Conductivity", &settings.conductivity),
          std::make_pair("Specific heat", &settings.specific_heat)})
      if (values->size() != 1 && values->size() < needed)
        reader.fail(entry,
                    "one value for every material, or one per material (" +
                      std::to_string(needed) + " or more)");
    grid_changed(setup.grid);
  }

  template <int dim>
  void
  HeatConduction<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    h_min = std::numeric_limits<double>::max();
    for (const GridCell<dim> &cell : grid.cells)
      h_min = std::min(h_min, cell.h);
    capacity.reinit(grid.partitioner);
    temperature.reinit(grid.partitioner);
    increment.reinit(grid.partitioner);
    std::map<unsigned int, double> held;
    for (const auto &[id, value] : settings.fixed_temperatures)
      for (const BoundaryNode<dim> &node : boundary_nodes(grid, {id}))
        held[node.local_index] = value;
    fixed_nodes.assign(held.begin(), held.end());
    // A node's area on each boundary, times the boundary's q or h.
    for (auto [values, nodes] :
         {std::make_pair(&settings.heat_fluxes, &flux_nodes),
          std::make_pair(&settings.convection, &convection_nodes)})
      {
        std::map<unsigned int, double> sum;
        for (const auto &[id, value] : *values)
          for (const BoundaryNode<dim> &node : boundary_nodes(grid, {id}))
            if (held.count(node.local_index) == 0) // held: moot
              sum[node.local_index] += value * node.area.norm();
        nodes->assign(sum.begin(), sum.end());
      }
  }

  template <int dim>
  void
  HeatConduction<dim>::initialize_particles(ParticleSet<dim> &particles) const
  {
    const unsigned int T = particles.layout.offset("temperature");
    for (auto &p : particles.handler)
      {
        const auto         props    = p.get_properties();
        const unsigned int m        = particles.material_of(props);
        props[T]                    = initial.value(p.get_location());
        const unsigned int internal = particles.internal_offset[m];
        if (working.empty()) // no materials were offered to wrap
          continue;
        if (johnson_cook_temperature[m] >= 0)
          props[internal + johnson_cook_temperature[m]] = props[T];
        if (working[m] != nullptr)
          props[particles.layout.offset("heated_work")] =
            working[m]->dissipated_energy_density(
              ArrayView<const double>(&props[internal],
                                      particles.n_internal[m]));
      }
    stored = heat_of(particles);
  }

  template <int dim>
  double
  HeatConduction<dim>::heat_of(const ParticleSet<dim> &particles) const
  {
    const unsigned int T   = particles.layout.offset("temperature");
    double             sum = 0;
    for (const auto &p : particles.handler)
      {
        const auto props = p.get_properties();
        sum +=
          props[particles.fields.mass] *
          of_material(settings.specific_heat, particles.material_of(props)) *
          props[T];
      }
    return sum;
  }

  template <int dim>
  void
  HeatConduction<dim>::map_temperature(const EffectContext<dim> &state)
  {
    const ParticleSet<dim> &particles = state.particles;
    const Stencil<dim>     &stencil   = state.stencil;
    const unsigned int      T         = particles.layout.offset("temperature");
    const unsigned int      G = particles.layout.offset("temperature_gradient");
    const std::vector<Point<dim>> &x = state.grid.node_positions;
    capacity                         = 0;
    temperature                      = 0;
    for_each_particle_in_stencil_order(
      state.grid, particles, [&](const std::size_t k, const auto &p, auto &) {
        const auto   props = p.get_properties();
        const double mc =
          props[particles.fields.mass] *
          of_material(settings.specific_heat, particles.material_of(props));
        // Each node takes T_p + g_p . (x_i - x_c), x_c = sum N_i x_i: a
        // linear field maps exactly, also at a wall, and sum C_i T_i =
        // sum m c T_p.
        const Tensor<1, dim> g = read_vector<dim>(&props[G]);
        Point<dim>           centre;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          centre += stencil.N[e] * x[stencil.node[e]];
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          {
            const unsigned int i = stencil.node[e];
            capacity.local_element(i) += stencil.N[e] * mc;
            temperature.local_element(i) +=
              stencil.N[e] * mc * (props[T] + g * (x[i] - centre));
          }
      });
    for (const HeatPartner<dim> *partner : partners)
      partner->add_capacity(capacity, temperature);
    capacity.compress(VectorOperation::add);
    temperature.compress(VectorOperation::add);
    const unsigned int n = capacity.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double C = capacity.local_element(i);
        temperature.local_element(i) =
          C > 0 ? temperature.local_element(i) / C : 0.;
      }
    mapped_at_fixed.resize(fixed_nodes.size());
    for (unsigned int j = 0; j < fixed_nodes.size(); ++j)
      {
        double &T_i        = temperature.local_element(fixed_nodes[j].first);
        mapped_at_fixed[j] = T_i;
        T_i                = held_factor * fixed_nodes[j].second;
      }
    temperature.update_ghost_values();
  }

  template <int dim>
  void
  HeatConduction<dim>::after_grid_update(const EffectContext<dim> &state,
                                         NodalFields<dim> & /*fields*/)
  {
    held_factor = settings.temperature_curve(state.time + state.dt);
    ambient     = settings.ambient_temperature *
              settings.ambient_curve(state.time + state.dt);
    map_temperature(state);
    const ParticleSet<dim> &particles = state.particles;
    const Stencil<dim>     &stencil   = state.stencil;
    // The conducted heat Q_i, gathered in 'increment' first.
    increment = 0;
    for_each_particle_in_stencil_order(
      state.grid, particles, [&](const std::size_t k, const auto &p, auto &) {
        const auto     props = p.get_properties();
        Tensor<1, dim> gradient;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          gradient +=
            temperature.local_element(stencil.node[e]) * stencil.grad_N[e];
        const double Vk =
          current_volume<dim>(&props[0], particles.fields) *
          of_material(settings.conductivity, particles.material_of(props));
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          increment.local_element(stencil.node[e]) -=
            Vk * (gradient * stencil.grad_N[e]);
      });
    if (has_source)
      add_source(state);
    for (const HeatPartner<dim> *partner : partners)
      partner->add_power(increment);
    increment.compress(VectorOperation::add);
    add_fluxes(state.time, state.dt);
    advance_nodes(state.dt);
    for (HeatPartner<dim> *partner : partners)
      {
        const auto flows =
          partner->advance(increment, temperature, state.grid.comm, state.dt);
        heat_in += flows.given;
        generated += flows.generated;
      }
  }

  template <int dim>
  void
  HeatConduction<dim>::add_fluxes(const double time, const double dt)
  {
    const double factor = settings.flux_curve(time + 0.5 * dt);
    for (const auto &[i, qA] : flux_nodes)
      if (capacity.local_element(i) > 0)
        {
          increment.local_element(i) += factor * qA;
          heat_in += dt * factor * qA;
        }
  }

  template <int dim>
  void
  HeatConduction<dim>::advance_nodes(const double dt)
  {
    // Fixed nodes: what they give the particles beside them and conduct to
    // the free nodes next to them (-dt Q_i) comes from beyond.
    for (unsigned int j = 0; j < fixed_nodes.size(); ++j)
      {
        const unsigned int i = fixed_nodes[j].first;
        heat_in +=
          capacity.local_element(i) *
            (held_factor * fixed_nodes[j].second - mapped_at_fixed[j]) -
          dt * increment.local_element(i);
      }
    // Convection at the node's new temperature (backward Euler): stable
    // at any step however little material a wall node holds, and at a
    // steady state exactly h A (T_a - T_i).
    for (const auto &[i, hA] : convection_nodes)
      {
        const double C = capacity.local_element(i);
        if (!(C > 0))
          continue;
        const double to_ambient = ambient - temperature.local_element(i);
        const double dT =
          dt * (increment.local_element(i) + hA * to_ambient) / (C + dt * hA);
        heat_in += dt * hA * (to_ambient - dT);
        increment.local_element(i) = C * dT / dt; // as a power, divided below
      }
    const unsigned int n = increment.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double C = capacity.local_element(i);
        increment.local_element(i) =
          C > 0 ? dt * increment.local_element(i) / C : 0.;
      }
    for (unsigned int j = 0; j < fixed_nodes.size(); ++j)
      increment.local_element(fixed_nodes[j].first) =
        held_factor * fixed_nodes[j].second - mapped_at_fixed[j];
    increment.update_ghost_values();
    // The nodes' new temperature, whose gradient the particles take.
    for (unsigned int i = 0; i < n; ++i)
      temperature.local_element(i) += increment.local_element(i);
    for (unsigned int j = 0; j < fixed_nodes.size(); ++j)
      temperature.local_element(fixed_nodes[j].first) =
        held_factor * fixed_nodes[j].second;
    temperature.update_ghost_values();
  }

  template <int dim>
  void
  HeatConduction<dim>::add_source(const EffectContext<dim> &state)
  {
    const ParticleSet<dim> &particles = state.particles;
    const Stencil<dim>     &stencil   = state.stencil;
    source.set_time(state.time);
    for_each_particle_in_stencil_order(
      state.grid, particles, [&](const std::size_t k, const auto &p, auto &) {
        const double power =
          current_volume<dim>(&p.get_properties()[0], particles.fields) *
          source.value(p.get_location());
        generated += state.dt * power;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          increment.local_element(stencil.node[e]) += stencil.N[e] * power;
      });
  }

  template <int dim>
  void
  HeatConduction<dim>::after_g2p(const EffectContext<dim> &state,
                                 ParticleSet<dim>         &particles)
  {
    add_friction_heat(state);
    largest_diffusivity         = 0;
    const Stencil<dim> &stencil = state.stencil;
    const unsigned int  T       = particles.layout.offset("temperature");
    const unsigned int  G = particles.layout.offset("temperature_gradient");
    stored                = 0;
    for_each_particle_in_stencil_order(
      state.grid, particles, [&](const std::size_t k, auto &p, auto &) {
        auto           props = p.get_properties();
        double         dT    = 0;
        Tensor<1, dim> g;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          {
            dT += stencil.N[e] * increment.local_element(stencil.node[e]);
            g += stencil.grad_N[e] * temperature.local_element(stencil.node[e]);
          }
        const unsigned int m = particles.material_of(props);
        if (heats_by_work && working[m] != nullptr)
          dT += heat_by_work(props, particles, m);
        props[T] += dT;
        write_vector<dim>(&props[G], g);
        if (!johnson_cook_temperature.empty() &&
            johnson_cook_temperature[m] >= 0)
          props[particles.internal_offset[m] + johnson_cook_temperature[m]] =
            props[T];
        if (!expanding.empty() && expanding[m] != nullptr)
          props[particles.internal_offset[m] + expanding[m]->stretch_index()] +=
            expanding[m]->stretch_per_kelvin() * dT;
        stored += props[particles.fields.mass] *
                  of_material(settings.specific_heat, m) * props[T];
        largest_diffusivity =
          std::max(largest_diffusivity, diffusivity_of(props, particles, m));
      });
    for (const HeatPartner<dim> *partner : partners)
      stored += partner->stored_heat();
  }

  template <int dim>
  void
  HeatConduction<dim>::add_friction_heat(const EffectContext<dim> &state)
  {
    std::vector<const DissipatesAtNodes *> sources;
    for (const auto &effect : state.effects)
      if (const auto *source =
            dynamic_cast<const DissipatesAtNodes *>(effect.get()))
        sources.push_back(source);
    for (const HeatPartner<dim> *partner : partners)
      if (const auto *source = partner->friction_source())
        sources.push_back(source);
    for (const DissipatesAtNodes *source : sources)
      for (const auto &[i, work] : source->dissipated_at_nodes())
        {
          const double C = capacity.local_element(i);
          if (!(C > 0))
            continue;
          const double heat = settings.friction_heat * work;
          increment.local_element(i) += heat / C;
          temperature.local_element(i) += heat / C;
          generated += heat;
        }
    // The same effects and partners on every rank: all of them
    // exchange, or none.
    if (!sources.empty())
      {
        increment.update_ghost_values();
        temperature.update_ghost_values();
      }
  }

  template <int dim>
  double
  HeatConduction<dim>::heat_by_work(const ArrayView<double> &props,
                                    const ParticleSet<dim>  &particles,
                                    const unsigned int       m)
  {
    double      &counted = props[particles.layout.offset("heated_work")];
    const double work    = working[m]->dissipated_energy_density(
      ArrayView<const double>(&props[particles.internal_offset[m]],
                              particles.n_internal[m]));
    const double heat = settings.taylor_quinney * (work - counted) *
                        props[particles.fields.initial_volume];
    counted = work;
    generated += heat;
    return heat / (props[particles.fields.mass] *
                   of_material(settings.specific_heat, m));
  }

  template <int dim>
  double
  HeatConduction<dim>::diffusivity_of(const ArrayView<const double> &props,
                                      const ParticleSet<dim>        &particles,
                                      const unsigned int             m) const
  {
    return of_material(settings.conductivity, m) *
           current_volume<dim>(&props[0], particles.fields) /
           (props[particles.fields.mass] *
            of_material(settings.specific_heat, m));
  }

  template <int dim>
  double
  HeatConduction<dim>::signal_rate(const ParticleSet<dim> &particles,
                                   const BackgroundGrid<dim> & /*grid*/) const
  {
    // After a step, after_g2p has found the largest diffusivity.
    if (largest_diffusivity < 0)
      {
        largest_diffusivity = 0;
        for (const auto &p : particles.handler)
          largest_diffusivity =
            std::max(largest_diffusivity,
                     diffusivity_of(p.get_properties(),
                                    particles,
                                    particles.material_of(p.get_properties())));
      }
    double rate = 2 * dim * largest_diffusivity / (h_min * h_min);
    for (const HeatPartner<dim> *partner : partners)
      rate = std::max(rate, partner->signal_rate());
    return rate;
  }

  template class HeatConduction<2>;
  template class HeatConduction<3>;

  namespace
  {
    /** Section Heat conduction's entries for the grid's boundaries. */
    void
    declare_boundary_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Fixed temperatures",
                        "",
                        Patterns::Anything(),
                        "Temperature (K) held on grid boundary ids, e.g. "
                        "'0: 373.15, 1: 293.15'.");
      prm.declare_entry("Heat fluxes",
                        "",
                        Patterns::Anything(),
                        "Heat flux into the material (W/m^2, < 0: out) "
                        "on grid boundary ids, e.g. '2: 1e4', times the "
                        "Flux curve; where material touches the face.");
      prm.declare_entry("Flux curve",
                        "",
                        Patterns::Anything(),
                        "Factor on the heat fluxes (the FEM regions' "
                        "too) against time, 't0: f0, t1: f1, ...' "
                        "(piecewise linear); empty: 1.");
      prm.declare_entry("Convection",
                        "",
                        Patterns::Anything(),
                        "Convection coefficient h (W/m^2/K) on grid "
                        "boundary ids, e.g. '3: 25': the face gives h "
                        "(T_ambient - T) per unit area.");
      prm.declare_entry("Ambient temperature",
                        "293.15",
                        Patterns::Double(),
                        "T_ambient (K) of the convection (the FEM "
                        "regions' too), times the Ambient curve.");
      prm.declare_entry("Temperature curve",
                        "",
                        Patterns::Anything(),
                        "Factor on the Fixed temperatures (the grid's and "
                        "the FEM regions') against time, 't0: f0, t1: "
                        "f1, ...' (piecewise linear), at each step's end; "
                        "e.g. '0: 1, 10: 1.5' takes 300 K to 450 K over "
                        "10 s; empty: 1.");
      prm.declare_entry("Ambient curve",
                        "",
                        Patterns::Anything(),
                        "Factor on the Ambient temperature against time, "
                        "like the Temperature curve; empty: 1.");
    }

    /** The entries of section Heat conduction. */
    void
    declare_heat_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Initial temperature",
                        "293.15",
                        Patterns::Anything(),
                        "The particles' temperature at the start (K), an "
                        "expression of x, y (, z).");
      prm.declare_entry("Conductivity",
                        "0",
                        Patterns::List(Patterns::Double(0)),
                        "k (W/m/K): one value for every material, or one "
                        "per material in their order.");
      prm.declare_entry("Specific heat",
                        "0",
                        Patterns::List(Patterns::Double(0)),
                        "c (J/kg/K), the heat capacity per unit mass: one "
                        "value for every material, or one per material.");
      prm.declare_entry(
        "Thermal expansion",
        "0",
        Patterns::List(Patterns::Double(0)),
        "alpha (1/K), the linear thermal expansion coefficient: one value "
        "for every material, or one per material. A body is stress-free "
        "at its initial temperature; the stress update divides the "
        "thermal stretch 1 + alpha (T - T_0) out of F. In 2D (plane "
        "strain) the held out-of-plane expansion makes it (1 + nu) alpha "
        "in the plane and lowers sigma_zz by E alpha (T - T_0), nu and E "
        "of the model's response to a small strain from its initial "
        "state.");
      prm.declare_entry("Heat source",
                        "0",
                        Patterns::Anything(),
                        "Heat generated per unit volume (W/m^3), an "
                        "expression of x, y (, z) and t; 0: none. It "
                        "heats the FEM regions too (per current "
                        "volume).");
      prm.declare_entry(
        "Taylor-Quinney coefficient",
        "0.9",
        Patterns::Double(0, 1),
        "The fraction of the work a material dissipates (plastic, "
        "viscous) that heats it, in [0, 1]. Johnson-Cook then takes its "
        "temperature from here (its own heating constants go unused).");
      prm.declare_entry(
        "Friction heat fraction",
        "1",
        Patterns::Double(0, 1),
        "The share of the work friction dissipates (the effects 'boundary "
        "friction' and 'frictional contact', an FEM region's 'Contact "
        "boundaries') that heats the material at the nodes where it "
        "slides (the MPM material's, also against a region), in [0, 1]; "
        "the rest leaves through the walls or the region, which keeps "
        "none of it.");
      declare_boundary_entries(prm);
    }

    /** The section's settings, checked (one-line failures). */
    template <typename HeatSettings>
    HeatSettings
    read_heat_settings(SceneReader &reader)
    {
      HeatSettings s;
      s.initial_temperature = reader.handler().get("Initial temperature");
      s.conductivity        = reader.get_doubles("Conductivity");
      s.specific_heat       = reader.get_doubles("Specific heat");
      s.thermal_expansion   = reader.get_doubles("Thermal expansion");
      s.heat_source         = reader.handler().get("Heat source");
      s.taylor_quinney      = reader.get_double("Taylor-Quinney coefficient");
      s.friction_heat       = reader.get_double("Friction heat fraction");
      if (s.thermal_expansion.empty())
        reader.fail("Thermal expansion", "one value or one per material");
      for (const double c : s.specific_heat)
        if (!(c > 0))
          reader.fail("Specific heat", "values > 0");
      if (s.conductivity.empty())
        reader.fail("Conductivity", "one value or one per material");
      if (s.specific_heat.empty())
        reader.fail("Specific heat", "one value or one per material");
      for (const auto &[id, T] :
           reader.get_id_nonnegatives("Fixed temperatures"))
        s.fixed_temperatures[static_cast<types::boundary_id>(id)] = T;
      for (const auto &[id, q] : reader.get_id_numbers("Heat fluxes", "W/m^2"))
        s.heat_fluxes[static_cast<types::boundary_id>(id)] = q;
      s.flux_curve = LoadCurve::read(reader, "Flux curve");
      for (const auto &[id, h] : reader.get_id_nonnegatives("Convection"))
        s.convection[static_cast<types::boundary_id>(id)] = h;
      s.ambient_temperature = reader.get_double("Ambient temperature");
      s.temperature_curve   = LoadCurve::read(reader, "Temperature curve");
      s.ambient_curve       = LoadCurve::read(reader, "Ambient curve");
      return s;
    }
  } // namespace

  template <int dim>
  void
  add_heat_conduction_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "heat conduction",
      "temperature carried by the particles and conducted through the "
      "grid (section Heat conduction: Initial temperature, Conductivity, "
      "Specific heat, Thermal expansion, Heat source, Fixed "
      "temperatures, Temperature curve, Heat fluxes, Flux curve, "
      "Convection, Ambient temperature, Ambient curve).",
      declare_heat_parameters,
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        return std::make_unique<HeatConduction<dim>>(
          read_heat_settings<typename HeatConduction<dim>::Settings>(reader),
          reader);
      });
  }

  template void
  add_heat_conduction_effect(Registry<Effect<2>> &);
  template void
  add_heat_conduction_effect(Registry<Effect<3>> &);
} // namespace dealmpm
