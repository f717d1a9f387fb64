#include <deal.II/base/numbers.h>
#include <deal.II/base/symmetric_tensor.h>

#include <dealmpm/particles/particle_set.h>

#include <map>
#include <stdexcept>

namespace dealmpm
{
  namespace
  {
    template <int dim>
    PropertyLayout
    core_layout(CoreFields &fields, const std::size_t n_bodies)
    {
      PropertyLayout layout;
      fields.mass           = layout.add("mass", 1);
      fields.initial_volume = layout.add("initial_volume", 1);
      fields.velocity       = layout.add("velocity", dim);
      fields.displacement   = layout.add("displacement", dim);
      fields.deformation_gradient =
        layout.add("deformation_gradient", dim * dim);
      fields.stress =
        layout.add("stress", SymmetricTensor<2, dim>::n_independent_components);
      // One body: every particle's would be 0, so none stores it.
      fields.body =
        n_bodies > 1 ? layout.add("body", 1) : numbers::invalid_unsigned_int;
      fields.n_core = layout.size();
      using Core    = FixedCore<dim>;
      AssertThrow(fields.mass == Core::mass &&
                    fields.initial_volume == Core::initial_volume &&
                    fields.velocity == Core::velocity &&
                    fields.displacement == Core::displacement &&
                    fields.deformation_gradient == Core::deformation_gradient &&
                    fields.stress == Core::stress,
                  ExcInternalError());
      return layout;
    }
  } // namespace

  namespace
  {
    /** One block of internal variables per model in use, shared by the
     * materials of that model: each material's count and offset. */
    void
    add_internal_variables(
      const std::vector<std::string>                   &model_names,
      const std::vector<std::vector<FieldDescription>> &internal_variables,
      PropertyLayout                                   &layout,
      std::vector<unsigned int>                        &n_internal,
      std::vector<unsigned int>                        &internal_offset)
    {
      std::map<std::string, unsigned int> block_of_model;
      for (unsigned int m = 0; m < internal_variables.size(); ++m)
        {
          unsigned int n = 0;
          for (const auto &f : internal_variables[m])
            n += f.n_components;
          n_internal.push_back(n);
          const auto it = block_of_model.find(model_names[m]);
          if (it != block_of_model.end())
            {
              internal_offset.push_back(it->second);
              continue;
            }
          unsigned int first = layout.size();
          for (const auto &f : internal_variables[m])
            layout.add(f.name, f.n_components);
          block_of_model[model_names[m]] = first;
          internal_offset.push_back(first);
        }
    }

    /** The effects' fields; one under a name already taken would silently
     * share (or overwrite) another part's storage. */
    void
    add_effect_fields(const std::vector<FieldDescription> &effect_fields,
                      PropertyLayout                      &layout)
    {
      for (const FieldDescription &f : effect_fields)
        {
          if (layout.has(f.name))
            throw std::logic_error("the particle field '" + f.name +
                                   "' of an effect is already in the layout");
          layout.add(f.name, f.n_components);
        }
    }
  } // namespace

  template <int dim>
  ParticleSet<dim>::ParticleSet(
    const Triangulation<dim>                         &tria,
    const Mapping<dim>                               &mapping,
    const std::vector<unsigned int>                  &body_materials,
    const std::vector<std::string>                   &model_names,
    const std::vector<std::vector<FieldDescription>> &internal_variables,
    const std::vector<FieldDescription>              &method_fields,
    const std::vector<FieldDescription>              &effect_fields)
    : layout(core_layout<dim>(fields, body_materials.size()))
    , material_of_body(body_materials)
  {
    for (const FieldDescription &f : method_fields)
      layout.add(f.name, f.n_components);
    fields.domain_half_length = layout.has("domain_half_length") ?
                                  layout.offset("domain_half_length") :
                                  numbers::invalid_unsigned_int;
    fields.affine_velocity    = layout.has("apic_B") ?
                                  layout.offset("apic_B") :
                                  numbers::invalid_unsigned_int;
    fields.acceleration       = layout.has("acceleration") ?
                                  layout.offset("acceleration") :
                                  numbers::invalid_unsigned_int;
    add_internal_variables(
      model_names, internal_variables, layout, n_internal, internal_offset);
    add_effect_fields(effect_fields, layout);
    handler.initialize(tria, mapping, layout.size());
  }

  template class ParticleSet<2>;
  template class ParticleSet<3>;
} // namespace dealmpm
