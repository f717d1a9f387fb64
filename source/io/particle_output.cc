#include <deal.II/base/mpi.h>

#include <dealmpm/io/particle_output.h>

#include <fstream>

namespace dealmpm
{
  template <int dim>
  void
  ParticleOutput<dim>::build_patches(const ParticleSet<dim> &particles)
  {
    using DCI = DataComponentInterpretation::DataComponentInterpretation;
    names.clear();
    ranges.clear();
    const auto add =
      [&](const std::string &name, const unsigned int n, const DCI kind) {
        if (kind != DataComponentInterpretation::component_is_scalar)
          ranges.emplace_back(names.size(), names.size() + n - 1, name, kind);
        for (unsigned int i = 0; i < n; ++i)
          names.push_back(n == 1 ? name : name + "_" + std::to_string(i));
      };
    add("id", 1, DataComponentInterpretation::component_is_scalar);
    add("body", 1, DataComponentInterpretation::component_is_scalar);
    add("material", 1, DataComponentInterpretation::component_is_scalar);
    add("velocity",
        dim,
        DataComponentInterpretation::component_is_part_of_vector);
    add("displacement",
        dim,
        DataComponentInterpretation::component_is_part_of_vector);
    add("stress",
        dim * dim,
        DataComponentInterpretation::component_is_part_of_tensor);
    add("J", 1, DataComponentInterpretation::component_is_scalar);
    add("volume", 1, DataComponentInterpretation::component_is_scalar);
    add("mass", 1, DataComponentInterpretation::component_is_scalar);
    // Every field of the layout after the core ones: the materials'
    // internal variables and the kernels' and transfers' own (apic_B,
    // domain_half_length), named as in the layout.
    std::vector<PropertyLayout::Field> internal;
    for (const auto &field : particles.layout.fields())
      if (field.offset > particles.fields.material)
        {
          internal.push_back(field);
          add(field.name,
              field.n_components,
              DataComponentInterpretation::component_is_scalar);
        }

    const CoreFields &f = particles.fields;
    patches.resize(particles.handler.n_locally_owned_particles());
    std::size_t i = 0;
    for (const auto &p : particles.handler)
      {
        DataOutBase::Patch<0, dim> &patch = patches[i];
        patch.vertices[0]                 = p.get_location();
        patch.patch_index                 = i;
        patch.data.reinit(names.size(), 1);
        const auto   props = p.get_properties();
        const auto   F     = read_tensor<dim>(&props[f.deformation_gradient]);
        const auto   sigma = read_symmetric<dim>(&props[f.stress]);
        const double J     = determinant(F);
        unsigned int c     = 0;
        patch.data(c++, 0) = p.get_id();
        patch.data(c++, 0) = props[f.body];
        patch.data(c++, 0) = props[f.material];
        for (unsigned int d = 0; d < dim; ++d)
          patch.data(c++, 0) = props[f.velocity + d];
        for (unsigned int d = 0; d < dim; ++d)
          patch.data(c++, 0) = props[f.displacement + d];
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            patch.data(c++, 0) = sigma[a][b];
        patch.data(c++, 0) = J;
        patch.data(c++, 0) = J * props[f.initial_volume];
        patch.data(c++, 0) = props[f.mass];
        for (const auto &field : internal)
          for (unsigned int k = 0; k < field.n_components; ++k)
            patch.data(c++, 0) = props[field.offset + k];
        ++i;
      }
  }

  template <int dim>
  std::string
  ParticleOutput<dim>::write(const std::string &directory,
                             const unsigned int counter,
                             const MPI_Comm     comm) const
  {
    return this->write_vtu_with_pvtu_record(
      directory + "/", "particles", counter, comm, 5, 0);
  }

  void
  PvdSeries::add_and_write(const double       time,
                           const std::string &file,
                           const std::string &pvd_path)
  {
    entries.emplace_back(time, file);
    std::ofstream out(pvd_path);
    DataOutBase::write_pvd_record(out, entries);
  }

  template class ParticleOutput<2>;
  template class ParticleOutput<3>;
} // namespace dealmpm
