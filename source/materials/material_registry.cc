#include <dealmpm/base/errors.h>
#include <dealmpm/materials/drucker_prager.h>
#include <dealmpm/materials/j2_plasticity.h>
#include <dealmpm/materials/johnson_cook.h>
#include <dealmpm/materials/linear_elastic.h>
#include <dealmpm/materials/mohr_coulomb.h>
#include <dealmpm/materials/neo_hookean.h>
#include <dealmpm/materials/tait_fluid.h>

#include <cmath>

namespace dealmpm
{
  void
  declare_elastic_constants(ParameterHandler &prm,
                            const double      youngs_modulus,
                            const double      poissons_ratio)
  {
    prm.declare_entry("Young's modulus",
                      std::to_string(youngs_modulus),
                      Patterns::Double(),
                      "Young's modulus E (Pa), > 0.");
    prm.declare_entry("Poisson's ratio",
                      std::to_string(poissons_ratio),
                      Patterns::Double(),
                      "Poisson's ratio nu, -1 < nu < 0.5.");
  }

  LameParameters
  read_elastic_constants(SceneReader &reader)
  {
    const double E  = reader.get_positive("Young's modulus");
    const double nu = reader.get_in_open_range("Poisson's ratio", -1., 0.5);
    return {E * nu / ((1. + nu) * (1. - 2. * nu)), E / (2. * (1. + nu))};
  }

  namespace
  {
    void
    declare_j2_parameters(ParameterHandler &prm)
    {
      declare_elastic_constants(prm, 200e9, 0.3);
      prm.declare_entry("Yield stress",
                        "250e6",
                        Patterns::Double(),
                        "Initial yield stress sigma_y0 (Pa), > 0.");
      prm.declare_entry("Hardening modulus",
                        "0",
                        Patterns::Double(),
                        "Linear hardening modulus H (Pa), >= 0.");
      prm.declare_entry("Hardening coefficient",
                        "0",
                        Patterns::Double(),
                        "Power-law hardening coefficient B (Pa), >= 0.");
      prm.declare_entry("Hardening exponent",
                        "1",
                        Patterns::Double(),
                        "Power-law hardening exponent n, in (0, 1].");
    }

    IsotropicHardening
    read_j2_hardening(SceneReader &reader)
    {
      IsotropicHardening h;
      h.yield_stress = reader.get_positive("Yield stress");
      h.modulus      = reader.get_nonnegative("Hardening modulus");
      h.coefficient  = reader.get_nonnegative("Hardening coefficient");
      h.exponent     = reader.get_positive("Hardening exponent");
      if (h.exponent > 1)
        reader.fail("Hardening exponent", "a number in (0, 1]");
      return h;
    }

    /** The Johnson-Cook entries: name, default, documentation. */
    struct JohnsonCookEntry
    {
      const char *name;
      double JohnsonCookParameters::*member;
      const char                    *documentation;
    };
    const JohnsonCookEntry johnson_cook_entries[] = {
      {"A", &JohnsonCookParameters::A, "Yield stress A (Pa), > 0."},
      {"B", &JohnsonCookParameters::B, "Hardening coefficient B (Pa), >= 0."},
      {"n", &JohnsonCookParameters::n, "Hardening exponent n, in (0, 1]."},
      {"C", &JohnsonCookParameters::C, "Strain-rate coefficient C, >= 0."},
      {"Reference strain rate",
       &JohnsonCookParameters::reference_rate,
       "Reference equivalent plastic strain rate (1/s), > 0."},
      {"m", &JohnsonCookParameters::m, "Thermal softening exponent m, > 0."},
      {"Room temperature",
       &JohnsonCookParameters::room_temperature,
       "Room (and initial) temperature (K), > 0."},
      {"Melting temperature",
       &JohnsonCookParameters::melting_temperature,
       "Melting temperature (K), > Room temperature."},
      {"Specific heat",
       &JohnsonCookParameters::specific_heat,
       "Specific heat c_p (J/(kg K)), > 0."},
      {"Taylor-Quinney coefficient",
       &JohnsonCookParameters::taylor_quinney,
       "Fraction of the plastic work that heats the material, in [0, 1]; "
       "0: no heating."},
      {"D1",
       &JohnsonCookParameters::D1,
       "Damage constant D1 (with Damage indicator)."},
      {"D2", &JohnsonCookParameters::D2, "Damage constant D2."},
      {"D3", &JohnsonCookParameters::D3, "Damage constant D3 (triaxiality)."},
      {"D4", &JohnsonCookParameters::D4, "Damage constant D4 (strain rate)."},
      {"D5", &JohnsonCookParameters::D5, "Damage constant D5 (temperature)."}};

    void
    declare_johnson_cook_parameters(ParameterHandler &prm)
    {
      // OFHC copper (Johnson and Cook 1983).
      declare_elastic_constants(prm, 124e9, 0.34);
      const JohnsonCookParameters copper;
      for (const auto &e : johnson_cook_entries)
        prm.declare_entry(e.name,
                          Utilities::to_string(copper.*(e.member)),
                          Patterns::Double(),
                          e.documentation);
      prm.declare_entry(
        "Damage indicator",
        "false",
        Patterns::Bool(),
        "Accumulate Johnson and Cook's (1985) damage D = sum d eps_p / eps_f, "
        "eps_f = [D1 + D2 exp(D3 sigma*)][1 + D4 ln(rate*)][1 + D5 T*], as "
        "the particle field 'damage' (1: the model predicts fracture); the "
        "stress is not softened.");
    }

    JohnsonCookParameters
    read_johnson_cook(SceneReader &reader)
    {
      JohnsonCookParameters jc;
      for (const auto &e : johnson_cook_entries)
        jc.*(e.member) = reader.get_double(e.name);
      for (const char *positive : {"A",
                                   "Reference strain rate",
                                   "m",
                                   "Room temperature",
                                   "Specific heat"})
        reader.get_positive(positive);
      for (const char *nonnegative : {"B", "C"})
        reader.get_nonnegative(nonnegative);
      if (!(jc.n > 0 && jc.n <= 1))
        reader.fail("n", "a number in (0, 1]");
      if (!(jc.melting_temperature > jc.room_temperature))
        reader.fail("Melting temperature",
                    "a number above Room temperature (" +
                      Utilities::to_string(jc.room_temperature) + ")");
      if (!(jc.taylor_quinney >= 0 && jc.taylor_quinney <= 1))
        reader.fail("Taylor-Quinney coefficient", "a number in [0, 1]");
      jc.damage_indicator = reader.get_bool("Damage indicator");
      return jc;
    }

    /** Friction angle, Dilation angle and Cohesion of a frictional
     * model (Drucker-Prager, Mohr-Coulomb). */
    void
    declare_friction_parameters(ParameterHandler  &prm,
                                const std::string &friction_default,
                                const std::string &friction_documentation,
                                const std::string &cohesion_documentation)
    {
      prm.declare_entry("Friction angle",
                        friction_default,
                        Patterns::Double(),
                        friction_documentation);
      prm.declare_entry("Dilation angle",
                        "0",
                        Patterns::Double(),
                        "Dilation angle psi (degrees), in [0, phi]; psi = "
                        "phi: associative flow.");
      prm.declare_entry("Cohesion",
                        "0",
                        Patterns::Double(),
                        cohesion_documentation);
    }

    /** The friction and dilation angles, checked, in radians. */
    std::array<double, 2>
    read_friction_angles(SceneReader &reader)
    {
      const double friction = reader.get_double("Friction angle");
      if (!(friction >= 0 && friction < 90))
        reader.fail("Friction angle", "an angle in [0, 90) degrees");
      const double dilation = reader.get_double("Dilation angle");
      if (!(dilation >= 0 && dilation <= friction))
        reader.fail("Dilation angle",
                    "an angle in [0, Friction angle] degrees");
      return {{friction * M_PI / 180., dilation * M_PI / 180.}};
    }

    void
    declare_drucker_prager_parameters(ParameterHandler &prm)
    {
      // Aluminium bars of Bui et al. (2008)'s granular column.
      declare_elastic_constants(prm, 0.84e6, 0.3);
      declare_friction_parameters(prm,
                                  "19.8",
                                  "Mohr-Coulomb friction angle phi "
                                  "(degrees), in [0, 90).",
                                  "Cohesion c (Pa), >= 0; 0: no tension.");
      prm.declare_entry(
        "Matching",
        "plane strain",
        Patterns::Selection("plane strain|outer cone|inner cone"),
        "How the cone matches Mohr-Coulomb: 'plane strain' (the same "
        "collapse loads in plane strain), 'outer cone' (triaxial "
        "compression), 'inner cone' (triaxial extension).");
    }

    DruckerPragerCone
    read_drucker_prager(SceneReader &reader)
    {
      const auto angles = read_friction_angles(reader);
      return DruckerPragerCone::matched(reader.get("Matching"),
                                        angles[0],
                                        angles[1],
                                        reader.get_nonnegative("Cohesion"));
    }

    void
    declare_mohr_coulomb_parameters(ParameterHandler &prm)
    {
      // A dense sand.
      declare_elastic_constants(prm, 50e6, 0.3);
      declare_friction_parameters(
        prm,
        "30",
        "Friction angle phi (degrees), in [0, 90); 0: Tresca.",
        "Cohesion c (Pa), >= 0; 0: no tension (the apex at zero stress). "
        "Tresca (phi = 0) needs c > 0.");
      prm.declare_entry("Tension cut-off",
                        "false",
                        Patterns::Bool(),
                        "Cap every principal stress at the Tensile strength "
                        "(Rankine), below Mohr-Coulomb's own apex c cot(phi).");
      prm.declare_entry("Tensile strength",
                        "0",
                        Patterns::Double(),
                        "T (Pa), >= 0: the largest principal stress with the "
                        "Tension cut-off.");
    }

    MohrCoulombParameters
    read_mohr_coulomb(SceneReader &reader)
    {
      MohrCoulombParameters mc;
      const auto            angles = read_friction_angles(reader);
      mc.friction_angle            = angles[0];
      mc.dilation_angle            = angles[1];
      mc.cohesion                  = reader.get_nonnegative("Cohesion");
      if (mc.friction_angle == 0 && !(mc.cohesion > 0))
        reader.fail("Cohesion", "a positive number when Friction angle is 0");
      const double strength = reader.get_nonnegative("Tensile strength");
      if (reader.get_bool("Tension cut-off"))
        mc.tension_cut_off = strength;
      return mc;
    }

    void
    declare_tait_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Sound speed",
                        "50",
                        Patterns::Double(),
                        "c0 (m/s), > 0: about 10 times the fastest flow keeps "
                        "the density within 1 % (weakly compressible); the "
                        "time step scales with 1 / c0.");
      prm.declare_entry("Exponent",
                        "7",
                        Patterns::Double(),
                        "gamma of Tait's equation p = B (J^-gamma - 1), "
                        "> 1 (7 for water).");
      prm.declare_entry("Viscosity",
                        "1e-3",
                        Patterns::Double(),
                        "Dynamic viscosity mu (Pa s), >= 0 (1e-3 for water).");
      prm.declare_entry("Tension cut-off",
                        "true",
                        Patterns::Bool(),
                        "No negative pressure (free surfaces do not pull).");
    }

    TaitParameters
    read_tait(SceneReader &reader)
    {
      TaitParameters t;
      t.sound_speed = reader.get_positive("Sound speed");
      t.exponent    = reader.get_double("Exponent");
      if (!(t.exponent > 1))
        reader.fail("Exponent", "a number > 1");
      t.viscosity       = reader.get_nonnegative("Viscosity");
      t.tension_cut_off = reader.get_bool("Tension cut-off");
      return t;
    }
  } // namespace

  template <int dim>
  Registry<Material<dim>> &
  material_registry()
  {
    static Registry<Material<dim>> registry = [] {
      Registry<Material<dim>> r;
      const auto              declare = [](ParameterHandler &prm) {
        declare_elastic_constants(prm, 1e3, 0.3);
      };
      r.add("linear elastic",
            "isotropic small-strain elasticity in rate form (Young's modulus, "
            "Poisson's ratio).",
            declare,
            [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
              return std::make_unique<LinearElastic<dim>>(
                read_elastic_constants(reader));
            });
      r.add("neo-Hookean",
            "compressible neo-Hookean hyperelasticity, stress from F "
            "(Young's modulus, Poisson's ratio).",
            declare,
            [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
              return std::make_unique<NeoHookean<dim>>(
                read_elastic_constants(reader));
            });
      r.add("J2 plasticity",
            "finite-strain von Mises plasticity (Simo 1992): Hencky "
            "elasticity in the logarithmic elastic strain, radial return, "
            "isotropic hardening sigma_y = Yield stress + Hardening modulus "
            "alpha + Hardening coefficient alpha^Hardening exponent (Young's "
            "modulus, Poisson's ratio, Yield stress, Hardening modulus, "
            "Hardening coefficient, Hardening exponent).",
            declare_j2_parameters,
            [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
              const LameParameters lame = read_elastic_constants(reader);
              return std::make_unique<J2Plasticity<dim>>(
                lame, read_j2_hardening(reader));
            });
      r.add("Johnson-Cook",
            "J2 plasticity with Johnson and Cook's flow stress (A + B "
            "alpha^n)(1 + C ln(rate / reference))(1 - T*^m) and adiabatic "
            "heating (temperature an internal variable); defaults: OFHC "
            "copper.",
            declare_johnson_cook_parameters,
            [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
              const LameParameters lame = read_elastic_constants(reader);
              return std::make_unique<JohnsonCook<dim>>(
                lame, read_johnson_cook(reader));
            });
      r.add("Drucker-Prager",
            "non-associative Drucker-Prager plasticity on Hencky elasticity, "
            "perfectly plastic, return to the cone or its apex (Young's "
            "modulus, Poisson's ratio, Friction angle, Dilation angle, "
            "Cohesion, Matching); for soils and granular flows.",
            declare_drucker_prager_parameters,
            [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
              const LameParameters lame = read_elastic_constants(reader);
              return std::make_unique<DruckerPrager<dim>>(
                lame, read_drucker_prager(reader));
            });
      r.add("Mohr-Coulomb",
            "non-associative Mohr-Coulomb plasticity on Hencky elasticity, "
            "perfectly plastic, principal-stress return to a plane, an edge "
            "or the apex, optional tension cut-off (Young's modulus, "
            "Poisson's ratio, Friction angle, Dilation angle, Cohesion, "
            "Tension cut-off, Tensile strength); for soils and rock.",
            declare_mohr_coulomb_parameters,
            [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
              const LameParameters lame = read_elastic_constants(reader);
              return std::make_unique<MohrCoulomb<dim>>(
                lame, read_mohr_coulomb(reader));
            });
      r.add("Tait fluid",
            "weakly compressible Newtonian fluid: Tait's equation of state "
            "from J, viscous stress 2 mu dev(D), optional tension cut-off; F "
            "is reset to J^(1/dim) I (Sound speed, Exponent, Viscosity, "
            "Tension cut-off).",
            declare_tait_parameters,
            [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
              return std::make_unique<TaitFluid<dim>>(read_tait(reader));
            });
      return r;
    }();
    return registry;
  }

#define DEALMPM_INSTANTIATE(dim) \
  template Registry<Material<dim>> &material_registry<dim>();
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
