#include <dealmpm/effects/effect.h>
#include <dealmpm/effects/generalized_vortex.h>
#include <dealmpm/effects/manufactured_solution.h>

#include <cmath>

namespace dealmpm
{
  namespace
  {
    /** Uniform body force g per unit mass: f_i += m_i g, which equals
     * sum_p N_ip m_p g. */
    template <int dim>
    class Gravity : public Effect<dim>
    {
    public:
      explicit Gravity(const Tensor<1, dim> &g)
        : g(g)
      {}

      void
      add_nodal_forces(const EffectContext<dim> &,
                       NodalFields<dim> &fields) override
      {
        const unsigned int n    = fields.mass.locally_owned_size();
        const double      *mass = fields.mass.begin();
        for (unsigned int d = 0; d < dim; ++d)
          {
            double *force = fields.force[d].begin();
            for (unsigned int i = 0; i < n; ++i)
              force[i] += mass[i] * g[d];
          }
      }

      double
      potential_energy(const double mass, const Point<dim> &x) const override
      {
        return -mass * (g * x);
      }

    private:
      Tensor<1, dim> g;
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
                            "Gravitational acceleration vector (m/s^2).");
        },
        [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
          return std::make_unique<Gravity<dim>>(
            reader.get_vector<dim>("Acceleration"));
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
      add_known_motions(r);
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
