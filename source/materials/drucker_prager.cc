#include <dealmpm/materials/drucker_prager.h>
#include <dealmpm/materials/friction_angles.h>

#include <cmath>

namespace dealmpm
{
  DruckerPragerCone
  DruckerPragerCone::matched(const std::string &matching,
                             const double       friction_angle,
                             const double       dilation_angle,
                             const double       cohesion)
  {
    const auto factors = [&](const double angle) -> std::array<double, 2> {
      if (matching == "plane strain")
        {
          const double root =
            std::sqrt(9. + 12. * std::pow(std::tan(angle), 2));
          return {{3. * std::tan(angle) / root, 3. / root}};
        }
      const double denominator =
        std::sqrt(3.) * (matching == "outer cone" ? 3. - std::sin(angle) :
                                                    3. + std::sin(angle));
      return {{6. * std::sin(angle) / denominator,
               6. * std::cos(angle) / denominator}};
    };
    const auto friction = factors(friction_angle);
    return {friction[0], factors(dilation_angle)[0], friction[1], cohesion};
  }

  template <int dim>
  DruckerPrager<dim>::DruckerPrager(const LameParameters    &lame,
                                    const DruckerPragerCone &cone)
    : HenckyPlasticity<dim>(lame)
    , cone(cone)
  {}

  template <int dim>
  double
  DruckerPrager<dim>::return_to_surface(std::array<double, 3> &strain,
                                        const double,
                                        ArrayView<double>) const
  {
    const double          K = this->bulk_modulus, G = this->shear_modulus;
    const double          volumetric = strain[0] + strain[1] + strain[2];
    std::array<double, 3> deviator;
    double                norm_squared = 0;
    for (unsigned int a = 0; a < 3; ++a)
      {
        deviator[a] = strain[a] - volumetric / 3.;
        norm_squared += deviator[a] * deviator[a];
      }
    // sqrt(J2) of the trial stress 2 G dev(eps), and its mean stress.
    const double root_J2 = 2. * G * std::sqrt(0.5 * norm_squared);
    const double p       = K * volumetric;
    const double f       = root_J2 + cone.eta * p - cone.xi * cone.cohesion;
    if (!(f > 0))
      return 0;

    // The smooth cone: d_gamma = f / (G + K eta eta_bar).
    const double d_gamma = f / (G + K * cone.eta * cone.eta_bar);
    double       new_p, scale;
    if (root_J2 - G * d_gamma >= 0)
      {
        scale = 1. - G * d_gamma / root_J2;
        new_p = p - K * cone.eta_bar * d_gamma;
      }
    else
      {
        // The apex: no deviator, p on the cone's tip (0 without cohesion).
        scale = 0;
        new_p = cone.eta > 0 ? cone.xi * cone.cohesion / cone.eta : p;
      }
    for (unsigned int a = 0; a < 3; ++a)
      strain[a] = scale * deviator[a] + new_p / (3. * K);
    // The equivalent plastic strain sqrt(2/3) |d eps_p|.
    const double d_volumetric = volumetric - new_p / K;
    double       d_plastic    = 0;
    for (unsigned int a = 0; a < 3; ++a)
      d_plastic += std::pow((1. - scale) * deviator[a] + d_volumetric / 3., 2);
    return std::sqrt(2. / 3. * d_plastic);
  }

  template class DruckerPrager<2>;
  template class DruckerPrager<3>;

  namespace
  {
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
  } // namespace

  template <int dim>
  void
  add_drucker_prager_material(Registry<Material<dim>> &registry)
  {
    registry.add(
      "Drucker-Prager",
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
  }

  template void
  add_drucker_prager_material(Registry<Material<2>> &);
  template void
  add_drucker_prager_material(Registry<Material<3>> &);
} // namespace dealmpm
