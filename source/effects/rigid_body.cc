#include <deal.II/base/mpi.h>

#include <dealmpm/effects/coulomb_friction.h>
#include <dealmpm/effects/expressions.h>
#include <dealmpm/effects/rigid_body.h>
#include <dealmpm/grid/nodal_exchange.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <cmath>

namespace dealmpm
{
  template <int dim>
  double
  RigidShape<dim>::distance(const Point<dim> &x) const
  {
    switch (kind)
      {
          case Kind::box: {
            // Outside: distance to the box; inside: minus the nearest face's.
            double outside = 0, inside = -std::numeric_limits<double>::max();
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double g = std::max(lower[d] - x[d], x[d] - upper[d]);
                outside += std::pow(std::max(g, 0.), 2);
                inside = std::max(inside, g);
              }
            return outside > 0 ? std::sqrt(outside) : inside;
          }
          case Kind::cylinder: {
            Tensor<1, 2> r;
            for (unsigned int d = 0; d < 2; ++d)
              r[d] = x[d] - centre[d];
            return r.norm() - radius;
          }
        case Kind::half_space:
        default:
          return (x - centre) * face_normal;
      }
  }

  template <int dim>
  Tensor<1, dim>
  RigidShape<dim>::normal(const Point<dim> &x) const
  {
    Tensor<1, dim> n;
    switch (kind)
      {
          case Kind::box: {
            // The face that is nearest from inside, or the direction to
            // the box from outside.
            unsigned int best = 0;
            double       gap  = -std::numeric_limits<double>::max();
            for (unsigned int d = 0; d < dim; ++d)
              for (const double side : {-1., 1.})
                {
                  const double g = side > 0 ? x[d] - upper[d] : lower[d] - x[d];
                  if (g > 0)
                    n[d] += side * g;
                  if (g > gap)
                    {
                      gap  = g;
                      best = 2 * d + (side > 0);
                    }
                }
            if (n.norm() > 0)
              return n / n.norm();
            n[best / 2] = (best % 2) ? 1. : -1.;
            return n;
          }
          case Kind::cylinder: {
            for (unsigned int d = 0; d < 2; ++d)
              n[d] = x[d] - centre[d];
            const double r = n.norm();
            if (r == 0.)
              n[0] = 1.;
            return r > 0 ? n / r : n;
          }
        case Kind::half_space:
        default:
          return face_normal;
      }
  }

  template <int dim>
  bool
  RigidShape<dim>::under_a_face(const Point<dim> &x) const
  {
    if (kind != Kind::box)
      return true;
    // Beside one face only: at most one coordinate is outside the box.
    unsigned int outside = 0;
    for (unsigned int d = 0; d < dim; ++d)
      outside += x[d] < lower[d] || x[d] > upper[d];
    return outside <= 1;
  }

  namespace
  {
    /** The corners of the box [lower, upper] in VTK's order of a quad or
     * hexahedron (counter-clockwise in x-y, then the same at upper z). */
    template <int dim>
    std::vector<Point<dim>>
    box_corners(const Point<dim> &lower, const Point<dim> &upper)
    {
      static const unsigned int x_upper[4] = {0, 1, 1, 0},
                                y_upper[4] = {0, 0, 1, 1};
      std::vector<Point<dim>> corners;
      for (unsigned int k = 0; k < (dim == 3 ? 2u : 1u); ++k)
        for (unsigned int c = 0; c < 4; ++c)
          {
            Point<dim> p = lower;
            p[0]         = x_upper[c] ? upper[0] : lower[0];
            p[1]         = y_upper[c] ? upper[1] : lower[1];
            if (dim == 3)
              p[dim - 1] = k ? upper[dim - 1] : lower[dim - 1];
            corners.push_back(p);
          }
      return corners;
    }

    /** A disk (2D, triangles around its centre) or a cylinder along z
     * from @p grid_box's bottom to its top (3D, wedges), of @p n sides. */
    template <int dim>
    void
    draw_cylinder(const Point<dim>       &centre,
                  const double            radius,
                  const BoundingBox<dim> &grid_box,
                  DrawnBody<dim>         &body)
    {
      const unsigned int n = 64;
      for (unsigned int k = 0; k < (dim == 3 ? 2u : 1u); ++k)
        {
          Point<dim> c = centre;
          if (dim == 3)
            c[dim - 1] = (k ? grid_box.get_boundary_points().second :
                              grid_box.get_boundary_points().first)[dim - 1];
          body.points.push_back(c);
          for (unsigned int i = 0; i < n; ++i)
            {
              Point<dim>   p     = c;
              const double angle = 2 * numbers::PI * i / n;
              p[0] += radius * std::cos(angle);
              p[1] += radius * std::sin(angle);
              body.points.push_back(p);
            }
        }
      body.cell_type =
        dim == 2 ? DrawnBody<dim>::triangle : DrawnBody<dim>::wedge;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int k = 0; k < (dim == 3 ? 2u : 1u); ++k)
          {
            const unsigned int centre = k * (n + 1), next = (i + 1) % n;
            // Counter-clockwise in 2D; a wedge's first triangle faces away
            // from its second (VTK's rule).
            for (const unsigned int v :
                 {0u, 1 + (dim == 2 ? i : next), 1 + (dim == 2 ? next : i)})
              body.connectivity.push_back(centre + v);
          }
    }

    /** A half-space as a slab behind its face through @p point with
     * outward unit @p normal, centred on @p grid_box's centre. */
    template <int dim>
    void
    draw_half_space(const Point<dim>       &point,
                    const Tensor<1, dim>   &normal,
                    const BoundingBox<dim> &grid_box,
                    DrawnBody<dim>         &body)
    {
      const auto  &corners  = grid_box.get_boundary_points();
      const double diagonal = corners.first.distance(corners.second);
      Point<dim>   centre   = grid_box.center();
      centre -= ((centre - point) * normal) * normal;
      // Directions along the face.
      std::array<Tensor<1, dim>, dim - 1> along;
      along[0][0] = -normal[1];
      along[0][1] = normal[0];
      if constexpr (dim == 3)
        {
          Tensor<1, dim> e; // the axis least parallel to the normal
          unsigned int   axis = 0;
          for (unsigned int d = 1; d < dim; ++d)
            if (std::abs(normal[d]) < std::abs(normal[axis]))
              axis = d;
          e[axis]  = 1.;
          along[0] = e - (e * normal) * normal;
          along[0] /= along[0].norm();
          along[dim - 2] = cross_product_3d(normal, along[0]);
        }
      static const double s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const double depth : {0.1 * diagonal, 0.})
        for (unsigned int c = 0; c < (dim == 2 ? 2u : 4u); ++c)
          {
            Point<dim> p = centre - depth * normal;
            for (unsigned int a = 0; a < dim - 1; ++a)
              p += 0.5 * diagonal *
                   s[dim == 2 ? (depth > 0 ? c : 1 - c) : c][a] * along[a];
            body.points.push_back(p);
          }
      body.cell_type =
        dim == 2 ? DrawnBody<dim>::quad : DrawnBody<dim>::hexahedron;
    }
  } // namespace

  template <int dim>
  DrawnBody<dim>
  RigidShape<dim>::drawn(const Tensor<1, dim>   &shift,
                         const BoundingBox<dim> &grid_box) const
  {
    DrawnBody<dim> body;
    switch (kind)
      {
        case Kind::box:
          body.points = box_corners(lower, upper);
          body.cell_type =
            dim == 2 ? DrawnBody<dim>::quad : DrawnBody<dim>::hexahedron;
          break;
        case Kind::cylinder:
          draw_cylinder(centre, radius, grid_box, body);
          break;
        case Kind::half_space:
        default:
          draw_half_space(centre, face_normal, grid_box, body);
      }
    if (body.connectivity.empty()) // one cell of all points
      for (unsigned int i = 0; i < body.points.size(); ++i)
        body.connectivity.push_back(i);
    for (Point<dim> &p : body.points)
      p += shift;
    return body;
  }

  template <int dim>
  RigidBody<dim>::RigidBody(const Settings &settings, const SceneReader &reader)
    : settings(settings)
    , velocity(dim)
  {
    const std::string expected =
      std::to_string(dim) +
      " expressions of t separated by ';' (muparser), in m/s";
    if (settings.velocity.size() != dim)
      reader.fail("Velocity", expected);
    parse_expressions(
      velocity, settings.velocity, true, reader, "Velocity", expected);
  }

  template <int dim>
  Tensor<1, dim>
  RigidBody<dim>::hold(const EffectContext<dim> &state,
                       NodalFields<dim>         &fields,
                       const Tensor<1, dim>     &V,
                       const bool                count_work)
  {
    Tensor<1, dim>     given;
    const unsigned int n = fields.mass.locally_owned_size();
    // The grid update decides which nodes the body presses; MUSL's re-map
    // holds the same nodes, pressed again or not. A re-map
    // held only where it presses would hold the re-mapped velocity on one
    // side of its swings: the stress update would see a compression the
    // particles' motion never makes, and the top of a layer under a
    // platen would be squeezed step after step (energy grew sevenfold in
    // an oedometer once a row of particles crossed a row of nodes).
    // USF re-maps before this step's grid update: it holds the nodes of
    // the last step's, whose velocities the particles carry (none in the
    // first step and after a grid change: there the re-mapped velocity
    // decides, as in the grid update).
    const bool same_nodes = !count_work && pressed_in_update.size() == n;
    if (count_work)
      pressed_in_update.assign(n, false);
    // Its place at the end of the step, in its initial frame.
    const Tensor<1, dim> shift = moved;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double m = fields.mass.local_element(i);
        if (!(m > state.mass_threshold))
          continue;
        const Point<dim> x   = state.grid.node_positions[i] - shift;
        const double     gap = settings.shape.distance(x);
        if (gap > 0. &&
            !(gap <= reach.local_element(i) && settings.shape.under_a_face(x)))
          continue;
        if (settings.touch_check && !(touched.local_element(i) > 0.))
          continue;
        Tensor<1, dim> v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = fields.velocity[d].local_element(i);
        const Tensor<1, dim> normal   = settings.shape.normal(x);
        Tensor<1, dim>       relative = v - V;
        const double         pressed  = -(relative * normal);
        if (same_nodes ? !pressed_in_update[i] : !(pressed > 0.))
          continue;
        if (count_work)
          pressed_in_update[i] = true;
        relative += pressed * normal;
        if (pressed > 0.)
          relative +=
            coulomb_change(relative, normal, pressed, settings.friction);
        Tensor<1, dim> change = V + relative - v;
        for (unsigned int d = 0; d < dim; ++d)
          if (!settings.mask[d])
            change[d] = 0.;
        given += m * change;
        if (count_work)
          work += m * (change * (v + change));
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields.velocity[d].local_element(i) += change[d];
            if (count_work)
              fields.velocity_increment[d].local_element(i) += change[d];
          }
      }
    NodalExchange ghosts;
    ghosts.add(fields.velocity);
    if (count_work)
      ghosts.add(fields.velocity_increment);
    ghosts.copy_owners_to_ghosts();
    return given;
  }

  template <int dim>
  Tensor<1, dim>
  RigidBody<dim>::velocity_at(const double t)
  {
    velocity.set_time(t);
    const double   factor = settings.curve(t);
    Tensor<1, dim> V;
    for (unsigned int d = 0; d < dim; ++d)
      V[d] = factor * velocity.value(Point<dim>(), d);
    return V;
  }

  template <int dim>
  void
  RigidBody<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    reach.reinit(grid.partitioner);
    pressed_in_update.clear();
    if (settings.touch_check)
      touched.reinit(grid.partitioner);
  }

  template <int dim>
  void
  RigidBody<dim>::add_nodal_forces(const EffectContext<dim> &state,
                                   NodalFields<dim> & /*fields*/)
  {
    reach = 0;
    if (settings.touch_check)
      touched = 0;
    // Where it will be at the end of the step, in its initial frame.
    const Tensor<1, dim> shift =
      moved + state.dt * velocity_at(state.time + 0.5 * state.dt);
    const CoreFields &f = state.particles.fields;
    for_each_particle_in_stencil_order(
      state.grid,
      state.particles,
      [&](const std::size_t k, const auto &p, const GridCell<dim> &) {
        const auto   props = p.get_properties();
        const double half =
          0.5 * std::pow(current_volume<dim>(&props[0], f), 1. / dim);
        if (settings.shape.distance(p.get_location() - shift) > half)
          return;
        for (unsigned int e = state.stencil.begin[k];
             e < state.stencil.begin[k + 1];
             ++e)
          {
            const unsigned int node = state.stencil.node[e];
            reach.local_element(node) =
              std::max(reach.local_element(node), half);
            if (settings.touch_check)
              touched.local_element(node) += 1.;
          }
      });
    reach.compress(VectorOperation::max);
    if (settings.touch_check)
      touched.compress(VectorOperation::add);
  }

  template <int dim>
  void
  RigidBody<dim>::after_grid_update(const EffectContext<dim> &state,
                                    NodalFields<dim>         &fields)
  {
    V_now = velocity_at(state.time + 0.5 * state.dt);
    moved += state.dt * V_now;
    force = -hold(state, fields, V_now, true) / state.dt;
  }

  template <int dim>
  void
  RigidBody<dim>::after_remap(const EffectContext<dim> &state,
                              NodalFields<dim>         &fields)
  {
    hold(state, fields, V_now, false);
  }

  template <int dim>
  std::vector<std::pair<std::string, double>>
  RigidBody<dim>::statistics_columns() const
  {
    // Summed over the ranks: the displacement only on rank 0.
    const bool  first  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const char *axes[] = {"x", "y", "z"};
    std::vector<std::pair<std::string, double>> columns;
    for (unsigned int d = 0; d < dim; ++d)
      columns.emplace_back(std::string("rigid_force_") + axes[d], force[d]);
    for (unsigned int d = 0; d < dim; ++d)
      columns.emplace_back(std::string("rigid_displacement_") + axes[d],
                           first ? moved[d] : 0.);
    columns.emplace_back("rigid_body_work", work);
    return columns;
  }

  template <int dim>
  std::vector<double>
  RigidBody<dim>::saved_state() const
  {
    std::vector<double> state(&moved[0], &moved[0] + dim);
    state.push_back(work);
    return state;
  }

  template <int dim>
  void
  RigidBody<dim>::restore_state(const std::vector<double> &state)
  {
    for (unsigned int d = 0; d < dim; ++d)
      moved[d] = state.at(d);
    work = state.at(dim);
  }

  template struct RigidShape<2>;
  template struct RigidShape<3>;
  template class RigidBody<2>;
  template class RigidBody<3>;

  namespace
  {
    template <int dim>
    void
    declare_rigid_body_parameters(ParameterHandler &prm)
    {
      const std::string zero = dim == 2 ? "0, 0" : "0, 0, 0";
      prm.declare_entry("Shape",
                        "box",
                        Patterns::Selection("box|cylinder|half-space"),
                        "box (Lower corner, Upper corner), cylinder "
                        "(Center, Radius; a disk in 2D, along z in 3D) "
                        "or half-space (Point on its face, outward "
                        "Normal), where it starts.");
      prm.declare_entry("Lower corner",
                        zero,
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: lower corner (m).");
      prm.declare_entry("Upper corner",
                        zero,
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box: upper corner (m).");
      prm.declare_entry("Center",
                        zero,
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Cylinder: centre (m).");
      prm.declare_entry("Radius",
                        "0",
                        Patterns::Double(0),
                        "Cylinder: radius (m).");
      prm.declare_entry("Point",
                        zero,
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Half-space: a point of its face (m).");
      prm.declare_entry("Normal",
                        zero,
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Half-space: its outward normal, towards the "
                        "material (need not be unit).");
      prm.declare_entry("Velocity",
                        dim == 2 ? "0; 0" : "0; 0; 0",
                        Patterns::Anything(),
                        "Its velocity (m/s), one expression of t per "
                        "direction separated by ';'.");
      prm.declare_entry("Load curve",
                        "",
                        Patterns::Anything(),
                        "A factor on the velocity, piecewise linear in "
                        "time: 't0: f0, t1: f1, ...' (a velocity "
                        "table); empty for 1.");
      prm.declare_entry("Direction mask",
                        dim == 2 ? "1, 1" : "1, 1, 1",
                        Patterns::List(Patterns::Integer(0, 1), dim, dim),
                        "1 where it acts on the material's velocity "
                        "component, 0 where it leaves it alone.");
      prm.declare_entry("Friction coefficient",
                        "0",
                        Patterns::Double(0),
                        "Coulomb's mu between it and the material.");
      prm.declare_entry(
        "Touch check",
        "false",
        Patterns::Bool(),
        "true: it acts only on the nodes of particles whose domain "
        "(half a particle spacing around them) reaches it, not on "
        "every node with mass inside it: a disk rolling on it is held "
        "at its contact point only, not on a cell-wide patch.");
    }

    template <int dim>
    std::unique_ptr<Effect<dim>>
    read_rigid_body(SceneReader &reader)
    {
      typename RigidBody<dim>::Settings settings;
      RigidShape<dim>                  &shape = settings.shape;
      const std::string                 kind  = reader.get("Shape");
      if (kind == "box")
        {
          shape.kind  = RigidShape<dim>::Kind::box;
          shape.lower = reader.get_point<dim>("Lower corner");
          shape.upper = reader.get_point<dim>("Upper corner");
          for (unsigned int d = 0; d < dim; ++d)
            if (!(shape.lower[d] < shape.upper[d]))
              reader.fail("Upper corner",
                          "a point above 'Lower corner' in every "
                          "direction");
        }
      else if (kind == "cylinder")
        {
          shape.kind   = RigidShape<dim>::Kind::cylinder;
          shape.centre = reader.get_point<dim>("Center");
          shape.radius = reader.get_positive("Radius");
        }
      else
        {
          shape.kind                  = RigidShape<dim>::Kind::half_space;
          shape.centre                = reader.get_point<dim>("Point");
          const Tensor<1, dim> normal = reader.get_vector<dim>("Normal");
          if (normal.norm() == 0.)
            reader.fail("Normal", "a direction that is not zero");
          shape.face_normal = normal / normal.norm();
        }
      settings.velocity =
        Utilities::split_string_list(reader.get("Velocity"), ';');
      settings.curve                 = LoadCurve::read(reader, "Load curve");
      const std::vector<double> mask = reader.get_doubles("Direction mask");
      for (unsigned int d = 0; d < dim; ++d)
        settings.mask[d] = mask.at(d) != 0.;
      settings.friction    = reader.get_nonnegative("Friction coefficient");
      settings.touch_check = reader.get_bool("Touch check");
      return std::make_unique<RigidBody<dim>>(settings, reader);
    }
  } // namespace

  template <int dim>
  void
  add_rigid_body_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "rigid body",
      "a rigid body moving with a prescribed velocity (a punch, a "
      "piston, a moving wall or a fixed obstacle), with friction; its "
      "reaction force goes to the statistics (section Rigid body: Shape, "
      "Lower corner, Upper corner, Center, Radius, Point, Normal, "
      "Velocity, Load curve, Direction mask, Friction coefficient).",
      declare_rigid_body_parameters<dim>,
      read_rigid_body<dim>);
  }

  template void
  add_rigid_body_effect(Registry<Effect<2>> &);
  template void
  add_rigid_body_effect(Registry<Effect<3>> &);
} // namespace dealmpm
