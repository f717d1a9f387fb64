#include <dealmpm/base/errors.h>
#include <dealmpm/materials/linear_elastic.h>
#include <dealmpm/materials/neo_hookean.h>

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
