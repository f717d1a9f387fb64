#include <deal.II/base/utilities.h>

#include <dealmpm/effects/effect_list.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace dealmpm
{
  namespace
  {
    template <int dim>
    void
    check_known_motion_material(SceneReader                 &reader,
                                const std::string           &effect,
                                const MaterialSections<dim> &materials)
    {
      // The body force of a known motion is computed for a neo-Hookean
      // material with the effect's constants: a different material would give
      // silently wrong error norms.
      const ParameterHandler &prm   = reader.handler();
      const auto              value = [&](const std::vector<std::string> &path,
                             const std::string              &entry) {
        return Utilities::string_to_double(prm.get(path, entry));
      };
      for (unsigned int m = 0; m < materials.materials.size(); ++m)
        {
          const std::string material = "Material " + std::to_string(m + 1);
          if (materials.models[m] != "neo-Hookean")
            {
              SectionScope section(reader, effect);
              reader.fail("Young's modulus",
                          "a scene whose materials are neo-Hookean (" +
                            material + " is '" + materials.models[m] +
                            "'): the body force of this motion is computed for "
                            "a neo-Hookean material");
            }
          const std::vector<std::string> model = {material, "neo-Hookean"};
          for (const auto &[entry, own] :
               {std::make_pair(std::string("Young's modulus"),
                               value(model, "Young's modulus")),
                std::make_pair(std::string("Poisson's ratio"),
                               value(model, "Poisson's ratio")),
                std::make_pair(std::string("Density"),
                               materials.materials[m]->density)})
            {
              const double mine = value({effect}, entry);
              if (std::abs(mine - own) > 1e-12 * std::abs(own))
                {
                  SectionScope       section(reader, effect);
                  std::ostringstream expected;
                  expected << "the value of " << material << "'s " << entry
                           << " (" << own
                           << "): the body force is computed for it";
                  reader.fail(entry, expected.str());
                }
            }
        }
    }
  } // namespace

  template <int dim>
  void
  declare_effect_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Effects",
      "",
      Patterns::MultipleSelection(effect_registry<dim>().pattern()),
      "Comma-separated optional physics; what is not listed costs "
      "nothing. Available: " +
        effect_registry<dim>().describe());
    for (const auto &name : effect_registry<dim>().names())
      {
        prm.enter_subsection(section_title(name));
        effect_registry<dim>().get(name).declare(prm);
        prm.leave_subsection();
      }
  }

  template <int dim>
  EffectList<dim>
  read_effects(SceneReader &reader, MaterialSections<dim> &materials)
  {
    EffectList<dim> list;
    const auto     &registry = effect_registry<dim>();
    for (const auto &name :
         Utilities::split_string_list(reader.get("Effects"), ','))
      {
        if (!registry.has(name))
          reader.fail("Effects",
                      "a comma-separated list of: " + registry.describe());
        if (std::find(list.names.begin(), list.names.end(), name) !=
            list.names.end())
          reader.fail("Effects", "each effect listed once");
        {
          SectionScope section(reader, section_title(name));
          list.effects.push_back(registry.get(name).create(reader));
          list.names.push_back(name);
        }
        if (list.effects.back()->has_exact_solution())
          check_known_motion_material(reader, section_title(name), materials);
        {
          SectionScope section(reader, section_title(name));
          list.effects.back()->wrap_materials(materials, reader);
        }
      }
    return list;
  }

#define DEALMPM_INSTANTIATE(dim)                                               \
  template void            declare_effect_parameters<dim>(ParameterHandler &); \
  template EffectList<dim> read_effects(SceneReader &, MaterialSections<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
