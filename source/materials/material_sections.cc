#include <dealmpm/materials/material_sections.h>

namespace dealmpm
{
  template <int dim>
  void
  declare_material_sections(ParameterHandler &prm, const unsigned int n)
  {
    const auto &models = material_registry<dim>();
    for (unsigned int m = 1; m <= n; ++m)
      {
        prm.enter_subsection("Material " + std::to_string(m));
        prm.declare_entry(
          "Model",
          "linear elastic",
          Patterns::Selection(models.pattern()),
          "Constitutive model: " + models.describe() +
            "Its parameters go in a subsection named after it.");
        prm.declare_entry("Density",
                          "1000",
                          Patterns::Double(),
                          "Reference density (kg/m^3), > 0.");
        for (const auto &name : models.names())
          {
            prm.enter_subsection(name);
            models.get(name).declare(prm);
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }
  }

  template <int dim>
  MaterialSections<dim>
  read_material_sections(SceneReader &reader, const unsigned int n)
  {
    MaterialSections<dim> read;
    for (unsigned int m = 1; m <= n; ++m)
      {
        SectionScope      section(reader, "Material " + std::to_string(m));
        const std::string model   = reader.get("Model");
        const double      density = reader.get_positive("Density");
        SectionScope      parameters(reader, model);
        read.materials.push_back(
          material_registry<dim>().get(model).create(reader));
        read.materials.back()->density = density;
        read.models.push_back(model);
      }
    return read;
  }

#define DEALMPM_INSTANTIATE(dim)                                            \
  template void declare_material_sections<dim>(ParameterHandler &,          \
                                               unsigned int);               \
  template MaterialSections<dim> read_material_sections<dim>(SceneReader &, \
                                                             unsigned int);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
