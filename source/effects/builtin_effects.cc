#include <dealmpm/effects/absorbing_boundary.h>
#include <dealmpm/effects/boundary_friction.h>
#include <dealmpm/effects/damage.h>
#include <dealmpm/effects/effect.h>
#include <dealmpm/effects/frictional_contact.h>
#include <dealmpm/effects/generalized_vortex.h>
#include <dealmpm/effects/manufactured_solution.h>
#include <dealmpm/effects/rigid_body.h>
#include <dealmpm/effects/rotating_frame.h>
#include <dealmpm/effects/traction.h>

#include <algorithm>
#include <cmath>

namespace dealmpm
{
  namespace
  {
    /**
     * Uniform body force g per unit mass: f_i += m_i g, which equals
     * sum_p N_ip m_p g. With a ramp time T, g grows linearly from 0 to its
     * full value over [0, T] (the step uses its value at mid-step); the
     * potential -m g(t) . x then changes with t too, and that change,
     * -(g(t + dt) - g(t)) . sum_p m_p x_p (at mid-step), is counted as
     * work so that the energy balance closes (a particle sweep in the
     * ramp's steps only).
     */
    template <int dim>
    class Gravity : public Effect<dim>
    {
    public:
      Gravity(const Tensor<1, dim> &g, const double ramp_time)
        : g(g)
        , ramp_time(ramp_time)
        , factor_now(factor(0.))
      {}

      void
      add_nodal_forces(const EffectContext<dim> &state,
                       NodalFields<dim>         &fields) override
      {
        const double t = state.time, dt = state.dt;
        const double scale = factor(t + 0.5 * dt);
        if (factor(t + dt) != factor(t))
          {
            // sum_p m_p x_p at mid-step, x_p + dt / 2 v_p.
            const CoreFields &f = state.particles.fields;
            Tensor<1, dim>    moment;
            for (const auto &p : state.particles.handler)
              {
                const auto props = p.get_properties();
                moment += props[f.mass] *
                          (Tensor<1, dim>(p.get_location()) +
                           0.5 * dt * read_vector<dim>(&props[f.velocity]));
              }
            work -= (factor(t + dt) - factor(t)) * (g * moment);
          }
        factor_now = factor(t + dt);

        const unsigned int n    = fields.mass.locally_owned_size();
        const double      *mass = fields.mass.begin();
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double gd    = scale * g[d];
            double      *force = fields.force[d].begin();
            for (unsigned int i = 0; i < n; ++i)
              force[i] += mass[i] * gd;
          }
      }

      double
      potential_energy(const double mass, const Point<dim> &x) const override
      {
        return -mass * factor_now * (g * x);
      }

      Tensor<1, dim>
      body_acceleration(const Point<dim> &,
                        const Point<dim> &,
                        const Tensor<1, dim> &,
                        const double t) const override
      {
        return factor(t) * g;
      }

      double
      work_done() const override
      {
        return work;
      }

      std::vector<double>
      saved_state() const override
      {
        return {factor_now, work};
      }

      std::vector<bool>
      state_shared_by_ranks() const override
      {
        return {true, false};
      }

      void
      restore_state(const std::vector<double> &state) override
      {
        factor_now = state.at(0);
        work       = state.at(1);
      }

    private:
      /** g(t) / g. */
      double
      factor(const double t) const
      {
        return ramp_time > 0. ? std::min(1., t / ramp_time) : 1.;
      }

      Tensor<1, dim> g;
      double         ramp_time;
      double         factor_now; ///< g(t) / g at the end of the last step
      double         work = 0;   ///< of the ramp's change in time
    };

    /**
     * Cundall's local non-viscous damping on the grid: each nodal force
     * component is reduced by alpha |f| against the direction of motion. It
     * drives a scene to its static state without changing that state.
     */
    template <int dim>
    class LocalDamping : public Effect<dim>
    {
    public:
      explicit LocalDamping(const double alpha)
        : alpha(alpha)
      {}

      void
      adjust_nodal_forces(NodalFields<dim> &fields) override
      {
        const unsigned int n = fields.mass.locally_owned_size();
        for (unsigned int d = 0; d < dim; ++d)
          {
            double       *force    = fields.force[d].begin();
            const double *momentum = fields.momentum[d].begin();
            for (unsigned int i = 0; i < n; ++i)
              if (momentum[i] != 0.)
                force[i] -=
                  alpha * std::abs(force[i]) * (momentum[i] > 0. ? 1. : -1.);
          }
      }

    private:
      double alpha;
    };

    /** The entries of an effect with a known motion: the neo-Hookean
     * material's constants (which must equal the material's), its
     * amplitude and its wave speed. */
    void
    declare_known_motion(ParameterHandler  &prm,
                         const double       youngs_modulus,
                         const std::string &density,
                         const std::string &amplitude,
                         const std::string &wave_speed,
                         const std::string &amplitude_doc,
                         const std::string &wave_speed_doc)
    {
      declare_elastic_constants(prm, youngs_modulus, 0.3);
      prm.declare_entry("Density",
                        density,
                        Patterns::Double(),
                        "The material's reference density.");
      prm.declare_entry("Amplitude",
                        amplitude,
                        Patterns::Double(),
                        amplitude_doc);
      prm.declare_entry("Wave speed",
                        wave_speed,
                        Patterns::Double(),
                        wave_speed_doc);
    }
  } // namespace

  std::string
  section_title(const std::string &name)
  {
    std::string title = name;
    if (!title.empty())
      title[0] = std::toupper(title[0]);
    return title;
  }

  namespace
  {
    /** Gravity and local damping: the effects of ordinary scenes. */
    template <int dim>
    void
    add_forces_and_damping(Registry<Effect<dim>> &r)
    {
      r.add(
        "gravity",
        "uniform body force (section Gravity: Acceleration).",
        [](ParameterHandler &prm) {
          prm.declare_entry("Acceleration",
                            dim == 2 ? "0, -9.81" : "0, 0, -9.81",
                            Patterns::List(Patterns::Double(), dim, dim),
                            "Gravitational acceleration vector (m/s^2). "
                            "Tilt it to put a scene on an incline.");
          prm.declare_entry("Ramp time",
                            "0",
                            Patterns::Double(0),
                            "0: full gravity from t = 0. T > 0: gravity "
                            "grows linearly from 0 to full over [0, T] (s), "
                            "so that a body settles without a shock.");
        },
        [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
          return std::make_unique<Gravity<dim>>(
            reader.get_vector<dim>("Acceleration"),
            reader.get_nonnegative("Ramp time"));
        });
      r.add(
        "boundary friction",
        "Coulomb friction on slip walls of the grid (section Boundary "
        "friction: Coefficients).",
        [](ParameterHandler &prm) {
          prm.declare_entry(
            "Coefficients",
            "",
            Patterns::Anything(),
            "Friction coefficient per boundary id, e.g. '2: 0.3, 3: 0.5'; "
            "each id must have 'slip' in 'Grid/Boundary conditions'.");
        },
        [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
          const std::map<unsigned int, double> read =
            reader.get_id_nonnegatives("Coefficients");
          const std::map<types::boundary_id, double> coefficients(read.begin(),
                                                                  read.end());
          if (coefficients.empty())
            reader.fail("Coefficients",
                        "at least one 'id: friction coefficient' pair");
          return std::make_unique<BoundaryFriction<dim>>(coefficients);
        });
      r.add(
        "local damping",
        "Cundall's local damping of nodal forces, for quasi-static "
        "settling (section Local damping: Coefficient).",
        [](ParameterHandler &prm) {
          prm.declare_entry("Coefficient",
                            "0.05",
                            Patterns::Double(),
                            "Damping coefficient alpha, 0 <= alpha < 1.");
        },
        [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
          const double alpha = reader.get_double("Coefficient");
          if (!(alpha >= 0. && alpha < 1.))
            reader.fail("Coefficient", "a number in [0, 1)");
          return std::make_unique<LocalDamping<dim>>(alpha);
        });
      r.add(
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
      r.add(
        "rigid body",
        "a rigid body moving with a prescribed velocity (a punch, a "
        "piston, a moving wall or a fixed obstacle), with friction; its "
        "reaction force goes to the statistics (section Rigid body: Shape, "
        "Lower corner, Upper corner, Center, Radius, Point, Normal, "
        "Velocity, Load curve, Direction mask, Friction coefficient).",
        [](ParameterHandler &prm) {
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
            "at its contact point only, not on a cell-wide patch. Costs a "
            "sweep over the particles.");
        },
        [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
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
          settings.curve = LoadCurve::read(reader, "Load curve");
          const std::vector<double> mask = reader.get_doubles("Direction mask");
          for (unsigned int d = 0; d < dim; ++d)
            settings.mask[d] = mask.at(d) != 0.;
          settings.friction    = reader.get_nonnegative("Friction coefficient");
          settings.touch_check = reader.get_bool("Touch check");
          return std::make_unique<RigidBody<dim>>(settings, reader);
        });
      r.add(
        "traction",
        "surface loads, a traction and a pressure (expressions of x and t "
        "times a load curve), on the surface particles of bodies and on "
        "free grid boundaries (section Traction: Bodies, Surface "
        "selection, Boundary ids, Traction, Pressure, Follower pressure, "
        "Load curve).",
        [](ParameterHandler &prm) {
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
        },
        [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
          typename Traction<dim>::Settings settings;
          for (const double b : reader.get_doubles("Bodies"))
            settings.bodies.insert(static_cast<unsigned int>(b) - 1);
          for (const double id : reader.get_doubles("Boundary ids"))
            settings.boundary_ids.insert(static_cast<types::boundary_id>(id));
          if (settings.bodies.empty() && settings.boundary_ids.empty())
            reader.fail("Bodies",
                        "at least one body or one of 'Boundary ids' to "
                        "load");
          settings.selection = reader.get("Surface selection");
          settings.traction =
            Utilities::split_string_list(reader.get("Traction"), ';');
          settings.pressure = reader.get("Pressure");
          settings.follower = reader.get_bool("Follower pressure");
          settings.curve    = LoadCurve::read(reader, "Load curve");
          return std::make_unique<Traction<dim>>(settings, reader);
        });
      r.add(
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

    /** "1 2: 0.4, 2 3: 0.1": body pairs (1-based in the scene, 0-based
     * and ordered in the map) to friction coefficients. */
    std::map<std::pair<unsigned int, unsigned int>, double>
    read_pair_friction(SceneReader &reader, const std::string &entry)
    {
      const std::string expected =
        "a list of 'b c: mu' items (two different body numbers, each pair "
        "once, and a number mu >= 0)";
      std::map<std::pair<unsigned int, unsigned int>, double> pairs;
      for (const auto &item :
           Utilities::split_string_list(reader.get(entry), ','))
        {
          const auto parts = Utilities::split_string_list(item, ':');
          if (parts.size() != 2)
            reader.fail(entry, expected);
          std::vector<long> bodies;
          double            mu = -1;
          try
            {
              for (const auto &word :
                   Utilities::split_string_list(parts[0], ' '))
                if (!word.empty())
                  bodies.push_back(Utilities::string_to_int(word));
              mu = Utilities::string_to_double(parts[1]);
            }
          catch (...)
            {
              reader.fail(entry, expected);
            }
          if (bodies.size() != 2 || bodies[0] < 1 || bodies[1] < 1 ||
              bodies[0] == bodies[1] || !(mu >= 0.) || !std::isfinite(mu))
            reader.fail(entry, expected);
          const std::pair<unsigned int, unsigned int> key(
            std::min(bodies[0], bodies[1]) - 1,
            std::max(bodies[0], bodies[1]) - 1);
          if (pairs.count(key) > 0)
            reader.fail(entry, expected);
          pairs[key] = mu;
        }
      return pairs;
    }

    /** Contact between bodies. */
    template <int dim>
    void
    add_contact(Registry<Effect<dim>> &r)
    {
      r.add(
        "frictional contact",
        "contact between bodies with Coulomb friction: each body moves in "
        "its own nodal velocity field, corrected where bodies meet and "
        "approach (section Frictional contact: Friction coefficient, Pair "
        "friction coefficients, Normals).",
        [](ParameterHandler &prm) {
          prm.declare_entry("Friction coefficient",
                            "0",
                            Patterns::Double(0),
                            "Coulomb coefficient mu >= 0 between any two "
                            "bodies (0: frictionless).");
          prm.declare_entry(
            "Pair friction coefficients",
            "",
            Patterns::Anything(),
            "Coefficients for particular pairs of bodies, e.g. '1 2: 0.4, "
            "2 3: 0.1'; the other pairs take 'Friction coefficient'.");
          prm.declare_entry(
            "Normals",
            "steepest mass gradient",
            Patterns::Selection(
              "steepest mass gradient|difference of bodies|mass gradient"),
            "The contact normal of body b at node i, from g_b = sum over "
            "b's particles of m_p grad N_i(x_p), which points out of b: "
            "'steepest mass gradient' along g_b or -g_c, whichever of b "
            "and the other body c is steeper (Nairn's maximum volume "
            "gradient: the flat face of a base, not the corner of a block "
            "sliding on it), 'difference of bodies' along g_b - g_others, "
            "'mass gradient' along g_b alone (Bardenhagen's). The first two "
            "give two bodies opposite normals, so that momentum is kept to "
            "round-off.");
          prm.declare_entry(
            "Separation check",
            "0",
            Patterns::Double(0, 1),
            "Contact at a node only where the bodies' particles fill at "
            "least this fraction of the node's volume (integral of N_i; "
            "Uintah's volume constraint): bodies that share a node across "
            "a gap narrower than a cell then do not touch before the gap "
            "closes. 0: off (contact wherever two bodies have mass at a "
            "node); 0.9 is a usual value. Costs a sweep over the particles.");
        },
        [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
          return std::make_unique<FrictionalContact<dim>>(
            reader.get_nonnegative("Friction coefficient"),
            read_pair_friction(reader, "Pair friction coefficients"),
            reader.get("Normals") == "mass gradient" ?
              FrictionalContact<dim>::Normals::own_mass_gradient :
            reader.get("Normals") == "difference of bodies" ?
              FrictionalContact<dim>::Normals::difference_of_bodies :
              FrictionalContact<dim>::Normals::steepest_mass_gradient,
            reader.get_double("Separation check"));
        });
    }

    /** The verification problems: effects with an exact solution. */
    template <int dim>
    void
    add_known_motions(Registry<Effect<dim>> &r)
    {
      r.add(
        "manufactured solution",
        "the axis-aligned manufactured solution of Wallstedt and Guilkey "
        "(2008) on the unit square/cube: initial velocity, body force and "
        "exact displacement for error norms (section Manufactured solution: "
        "Amplitude, Wave speed, and the neo-Hookean material's Young's "
        "modulus, Poisson's ratio and Density).",
        [](ParameterHandler &prm) {
          declare_known_motion(prm,
                               1e4,
                               "1",
                               "0.05",
                               "100",
                               "Displacement amplitude A.",
                               "c in sin(c pi t + phi): the period is 2 / c.");
        },
        [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
          return std::make_unique<ManufacturedSolution<dim>>(
            read_elastic_constants(reader),
            reader.get_positive("Density"),
            reader.get_positive("Amplitude"),
            reader.get_positive("Wave speed"));
        });
      r.add(
        "generalized vortex",
        "the generalized vortex on the annulus 0.75 < R < 1.25 (2D): "
        "initial velocity, body force and exact displacement for error "
        "norms (section Generalized vortex: Amplitude, Wave speed, and the "
        "neo-Hookean material's Young's modulus, Poisson's ratio and "
        "Density).",
        [](ParameterHandler &prm) {
          declare_known_motion(prm,
                               1e3,
                               "1000",
                               "1",
                               "1",
                               "A in alpha = A sin(c pi t) h(R).",
                               "c in sin(c pi t): the period is 2 / c.");
        },
        [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
          if (dim != 2)
            reader.fail(
              "Amplitude",
              "Dimension = 2: the generalized vortex is a 2D problem");
          return std::make_unique<GeneralizedVortex<dim>>(
            read_elastic_constants(reader).mu,
            reader.get_positive("Density"),
            reader.get_positive("Amplitude"),
            reader.get_positive("Wave speed"));
        });
    }
  } // namespace

  template <int dim>
  Registry<Effect<dim>> &
  effect_registry()
  {
    static Registry<Effect<dim>> registry = [] {
      Registry<Effect<dim>> r;
      add_forces_and_damping(r);
      add_contact(r);
      add_known_motions(r);
      add_damage_effect(r);
      return r;
    }();
    return registry;
  }

#define DEALMPM_INSTANTIATE(dim) \
  template Registry<Effect<dim>> &effect_registry<dim>();
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
