#include <dealmpm/base/errors.h>
#include <dealmpm/materials/drucker_prager.h>
#include <dealmpm/materials/j2_plasticity.h>
#include <dealmpm/materials/johnson_cook.h>
#include <dealmpm/materials/linear_elastic.h>
#include <dealmpm/materials/modified_cam_clay.h>
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

  /* The built-in models: each file registers its own (its parameters, their
   * reading and checks) in the table built on first use. */
  template <int dim>
  Registry<Material<dim>> &
  material_registry()
  {
    static Registry<Material<dim>> registry = [] {
      Registry<Material<dim>> r;
      add_linear_elastic_material(r);
      add_neo_hookean_material(r);
      add_j2_plasticity_material(r);
      add_johnson_cook_material(r);
      add_drucker_prager_material(r);
      add_mohr_coulomb_material(r);
      add_modified_cam_clay_material(r);
      add_tait_fluid_material(r);
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
