#include <deal.II/base/mpi.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/run_messages.h>
#include <dealmpm/effects/expressions.h>
#include <dealmpm/effects/traction.h>
#include <dealmpm/grid/nodal_exchange.h>
#include <dealmpm/particles/surface_area.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>

namespace dealmpm
{

  template <int dim>
  Traction<dim>::Traction(const Settings &settings, const SceneReader &reader)
    : EffectWithWork<dim>("traction_work")
    , settings(settings)
    , selection(1)
    , traction(dim)
    , pressure(1)
  {
    const std::string of = " of " + coordinate_names(dim, true) + " (muparser)";
    parse_expressions(selection,
                      {settings.selection},
                      false,
                      reader,
                      "Surface selection",
                      "an expression of " + coordinate_names(dim, false) +
                        " (muparser), nonzero where the surface is loaded");
    if (settings.traction.size() != dim)
      reader.fail("Traction",
                  std::to_string(dim) + " expressions separated by ';'" + of);
    parse_expressions(traction,
                      settings.traction,
                      true,
                      reader,
                      "Traction",
                      std::to_string(dim) + " expressions separated by ';'" +
                        of);
    parse_expressions(pressure,
                      {settings.pressure},
                      true,
                      reader,
                      "Pressure",
                      "an expression" + of);
  }

  template <int dim>
  std::vector<FieldDescription>
  Traction<dim>::particle_fields() const
  {
    if (settings.bodies.empty())
      return {};
    return {{"surface_area", dim},
            {"surface_size", 1},
            {"surface_offset", dim}};
  }

  template <int dim>
  void
  Traction<dim>::setup(const EffectSetup<dim> &setup, SceneReader &reader)
  {
    for (const unsigned int b : settings.bodies)
      if (b >= setup.n_bodies)
        reader.fail("Bodies",
                    "body numbers from 1 to the scene's 'Number of bodies' (" +
                      std::to_string(setup.n_bodies) + "), not " +
                      std::to_string(b + 1));
    setup.conditions.require(reader,
                             "Boundary ids",
                             settings.boundary_ids,
                             setup.grid,
                             "free",
                             "a wall that prescribes the velocity takes any "
                             "load itself");
    bodies = &setup.bodies;
    grid_changed(setup.grid);
  }

  template <int dim>
  void
  Traction<dim>::grid_changed(const BackgroundGrid<dim> &new_grid)
  {
    grid  = &new_grid;
    nodes = boundary_nodes(new_grid, settings.boundary_ids);
    for (unsigned int d = 0; d < dim; ++d)
      nodal_load[d].reinit(new_grid.partitioner);
  }

  template <int dim>
  Tensor<1, dim>
  Traction<dim>::loaded_face_normal(const ParticleSet<dim> &particles) const
  {
    if (settings.all_faces || settings.face_normal.norm() > 0.)
      return settings.face_normal;
    const CoreFields &f = particles.fields;
    // The selection's faces by direction, and the surface particles it
    // leaves out.
    std::array<double, 2 * dim + 1> areas{};
    for (const GridCell<dim> &c : grid->cells)
      for (const auto &p : particles.handler.particles_in_cell(c.cell))
        {
          const auto         props = p.get_properties();
          const unsigned int body  = particles.body_of(props);
          if (settings.bodies.count(body) == 0)
            continue;
          const SurfaceFaces<dim> faces =
            surface_faces(c,
                          p.get_reference_location(),
                          (*bodies)[body].particles_per_direction,
                          *(*bodies)[body].shape,
                          props[f.initial_volume],
                          Tensor<1, dim>());
          if (selection.value(p.get_location()) == 0.)
            areas[2 * dim] += faces.size;
          else
            for (unsigned int k = 0; k < 2 * dim; ++k)
              areas[k] += faces.by_direction[k];
        }
    Utilities::MPI::sum(ArrayView<const double>(areas.data(), areas.size()),
                        grid->comm,
                        ArrayView<double>(areas.data(), areas.size()));
    std::string  facing;
    unsigned int n_directions = 0;
    for (unsigned int k = 0; k < 2 * dim; ++k)
      if (areas[k] > 0.)
        {
          facing += std::string(n_directions++ > 0 ? ", " : "") +
                    (k % 2 == 0 ? "-" : "+") + "xyz"[k / 2] + " (" +
                    short_number(areas[k]) + ")";
        }
    if (n_directions == 0)
      throw InputError(settings.face_normal_entry +
                       ": the 'Surface selection' holds no surface "
                       "particle of the loaded bodies");
    if (n_directions > 1 && areas[2 * dim] > 0.)
      throw InputError(
        settings.face_normal_entry +
        ": expected the outward normal of the loaded face, e.g. '0, 1' "
        "for a top face, or 'all': the selected surface particles have "
        "faces facing " +
        facing + ", and a corner particle's side faces would be loaded too");
    return Tensor<1, dim>();
  }

  template <int dim>
  void
  Traction<dim>::initialize_particles(ParticleSet<dim> &particles) const
  {
    if (settings.bodies.empty())
      return;
    const Tensor<1, dim> normal = loaded_face_normal(particles);
    const CoreFields    &f      = particles.fields;
    const unsigned int   area   = particles.layout.offset("surface_area");
    const unsigned int   size   = particles.layout.offset("surface_size");
    const unsigned int   offset = particles.layout.offset("surface_offset");
    std::array<double, dim + 1> loaded{}; // area vector, area
    for (const GridCell<dim> &c : grid->cells)
      for (auto &p : particles.handler.particles_in_cell(c.cell))
        {
          const auto         props = p.get_properties();
          const unsigned int body  = particles.body_of(props);
          SurfaceFaces<dim>  faces;
          if (settings.bodies.count(body) > 0 &&
              selection.value(p.get_location()) != 0.)
            faces = surface_faces(c,
                                  p.get_reference_location(),
                                  (*bodies)[body].particles_per_direction,
                                  *(*bodies)[body].shape,
                                  props[f.initial_volume],
                                  normal);
          write_vector<dim>(&props[area], faces.area);
          props[size] = faces.size;
          write_vector<dim>(&props[offset], faces.offset);
          for (unsigned int d = 0; d < dim; ++d)
            loaded[d] += faces.area[d];
          loaded[dim] += faces.size;
        }
    Utilities::MPI::sum(ArrayView<const double>(loaded.data(), loaded.size()),
                        grid->comm,
                        ArrayView<double>(loaded.data(), loaded.size()));
    if (Utilities::MPI::this_mpi_process(grid->comm) == 0)
      {
        std::cout << "dealmpm: traction loads surface faces of area "
                  << short_number(loaded[dim]) << ", outward area vector (";
        for (unsigned int d = 0; d < dim; ++d)
          std::cout << (d > 0 ? ", " : "") << short_number(loaded[d]);
        std::cout << ")" << std::endl;
      }
  }

  template <int dim>
  Tensor<1, dim>
  Traction<dim>::load(const Point<dim>     &x,
                      const double          factor,
                      const double          size,
                      const Tensor<1, dim> &a) const
  {
    Tensor<1, dim> t;
    for (unsigned int d = 0; d < dim; ++d)
      t[d] = traction.value(x, d);
    return factor * (size * t - pressure.value(x) * a);
  }

  template <int dim>
  void
  Traction<dim>::add_nodal_forces(const EffectContext<dim> &state,
                                  NodalFields<dim>         &fields)
  {
    const double t      = state.time + 0.5 * state.dt;
    const double factor = settings.curve(t);
    traction.set_time(t);
    pressure.set_time(t);
    for (unsigned int d = 0; d < dim; ++d)
      nodal_load[d] = 0.;

    for (const BoundaryNode<dim> &node : nodes)
      if (fields.mass.local_element(node.local_index) > state.mass_threshold)
        {
          const Tensor<1, dim> f =
            load(state.grid.node_positions[node.local_index],
                 factor,
                 node.area.norm(),
                 node.area);
          for (unsigned int d = 0; d < dim; ++d)
            nodal_load[d].local_element(node.local_index) += f[d];
        }

    if (!settings.bodies.empty())
      {
        const CoreFields  &cf   = state.particles.fields;
        const unsigned int area = state.particles.layout.offset("surface_area");
        const unsigned int size = state.particles.layout.offset("surface_size");
        const unsigned int offset =
          state.particles.layout.offset("surface_offset");
        double *target[dim];
        for (unsigned int d = 0; d < dim; ++d)
          target[d] = nodal_load[d].begin();
        for_each_particle_in_stencil_order(
          state.grid,
          state.particles,
          [&](const std::size_t k, const auto &p, const GridCell<dim> &) {
            const auto   props = p.get_properties();
            const double s0    = props[size];
            if (s0 == 0.)
              return;
            const Tensor<1, dim> A0 = read_vector<dim>(&props[area]);
            const Tensor<2, dim> F =
              read_tensor<dim>(&props[cf.deformation_gradient]);
            const Tensor<1, dim> a = settings.follower ? cofactor(F) * A0 : A0;
            // The faces' centre, where the load acts, moves with F (a
            // reference stencil's gradients are in the initial frame).
            const Tensor<1, dim> offset0 = read_vector<dim>(&props[offset]);
            const Tensor<1, dim> delta =
              state.stencil.reference ? offset0 : F * offset0;
            const Tensor<1, dim> f =
              load(p.get_location() + delta, factor, s0, a);
            // N_i(x_p + delta) to first order: the loads' first moment,
            // sum_i x_i (x) f_i, is then the faces' own, and a uniform
            // pressure gives a mean stress of exactly -p.
            for (unsigned int e = state.stencil.begin[k];
                 e < state.stencil.begin[k + 1];
                 ++e)
              {
                const double w =
                  state.stencil.N[e] + state.stencil.grad_N[e] * delta;
                for (unsigned int d = 0; d < dim; ++d)
                  target[d][state.stencil.node[e]] += w * f[d];
              }
          });
      }
    NodalExchange().add(nodal_load).sum_ghosts_into_owners();
    for (unsigned int d = 0; d < dim; ++d)
      fields.force[d].add(1., nodal_load[d]);
    double total = 0;
    for (unsigned int i = 0; i < nodal_load[0].locally_owned_size(); ++i)
      {
        double f2 = 0;
        for (unsigned int d = 0; d < dim; ++d)
          f2 += std::pow(nodal_load[d].local_element(i), 2);
        total += std::sqrt(f2);
      }
    largest_load = std::max(largest_load, total);
  }

  template <int dim>
  void
  Traction<dim>::count_work(const EffectContext<dim> &state,
                            const NodalFields<dim>   &fields)
  {
    const unsigned int n = fields.mass.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double m = fields.mass.local_element(i);
        if (!(m > state.mass_threshold))
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          this->work += 0.5 * state.dt * nodal_load[d].local_element(i) *
                        (fields.momentum[d].local_element(i) / m +
                         fields.velocity[d].local_element(i));
      }
  }

  template class Traction<2>;
  template class Traction<3>;

  namespace
  {
    template <int dim>
    void
    declare_traction_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Bodies",
                        "",
                        Patterns::List(Patterns::Integer(1)),
                        "Bodies (numbers from 1) whose surface "
                        "particles carry the load, e.g. '1, 3'.");
      prm.declare_entry("Surface selection",
                        "1",
                        Patterns::Anything(),
                        "Which of their surface particles: an "
                        "expression of the initial position (x, y, z) "
                        "that is nonzero where the load acts, e.g. "
                        "'y > 0.99' for a top face.");
      prm.declare_entry("Face normal",
                        "",
                        Patterns::Anything(),
                        "Which surface faces of the selected particles "
                        "carry the load. The outward normal of the "
                        "loaded face, e.g. '1, 0' for a bar's end at the "
                        "largest x: only the faces facing it, each by "
                        "its projection on it (a flat face of any "
                        "orientation gets its own area). 'all': every "
                        "surface face of the selected particles (for a "
                        "curved part of a surface). Empty: all of them "
                        "when the selection holds the whole surface of "
                        "its bodies or its faces all face one way; "
                        "otherwise the run stops and asks (a corner "
                        "particle's side faces would be loaded too).");
      prm.declare_entry("Boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0)),
                        "Free grid boundaries (ids without a condition "
                        "in 'Grid/Boundary conditions') loaded where "
                        "material touches them.");
      prm.declare_entry("Traction",
                        dim == 2 ? "0; 0" : "0; 0; 0",
                        Patterns::Anything(),
                        "Force per unit area (Pa), one expression of "
                        "x, y, (z,) t per direction separated by ';', "
                        "per unit initial area on particles.");
      prm.declare_entry("Pressure",
                        "0",
                        Patterns::Anything(),
                        "Pressure (Pa) pushing into the body, an "
                        "expression of x, y, (z,) t.");
      prm.declare_entry("Follower pressure",
                        "false",
                        Patterns::Bool(),
                        "On particles: true, the pressure acts on the "
                        "deformed surface (J F^-T A0); false, on the "
                        "initial one (dead load).");
      prm.declare_entry("Load curve",
                        "",
                        Patterns::Anything(),
                        "A factor on both, piecewise linear in time: "
                        "'t0: f0, t1: f1, ...', constant outside; "
                        "empty for 1.");
    }

    template <int dim>
    std::unique_ptr<Effect<dim>>
    read_traction(SceneReader &reader)
    {
      typename Traction<dim>::Settings settings;
      for (const double b : reader.get_doubles("Bodies"))
        settings.bodies.insert(static_cast<unsigned int>(b) - 1);
      for (const double id : reader.get_doubles("Boundary ids"))
        settings.boundary_ids.insert(static_cast<types::boundary_id>(id));
      if (settings.bodies.empty() && settings.boundary_ids.empty())
        reader.fail("Bodies",
                    "at least one body or one of 'Boundary ids' to "
                    "load");
      settings.selection         = reader.get("Surface selection");
      settings.face_normal_entry = reader.where("Face normal");
      const std::string normal   = reader.get("Face normal");
      settings.all_faces         = normal == "all";
      if (!normal.empty() && !settings.all_faces)
        {
          settings.face_normal = reader.get_vector<dim>("Face normal");
          if (settings.face_normal.norm() == 0.)
            reader.fail("Face normal",
                        "a nonzero vector, 'all' or nothing (see the "
                        "entry's documentation)");
        }
      settings.traction =
        Utilities::split_string_list(reader.get("Traction"), ';');
      settings.pressure = reader.get("Pressure");
      settings.follower = reader.get_bool("Follower pressure");
      settings.curve    = LoadCurve::read(reader, "Load curve");
      return std::make_unique<Traction<dim>>(settings, reader);
    }
  } // namespace

  template <int dim>
  void
  add_traction_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "traction",
      "surface loads, a traction and a pressure (expressions of x and t "
      "times a load curve), on the surface particles of bodies and on "
      "free grid boundaries (section Traction: Bodies, Surface "
      "selection, Face normal, Boundary ids, Traction, Pressure, "
      "Follower pressure, Load curve).",
      declare_traction_parameters<dim>,
      read_traction<dim>);
  }

  template void
  add_traction_effect(Registry<Effect<2>> &);
  template void
  add_traction_effect(Registry<Effect<3>> &);
} // namespace dealmpm
