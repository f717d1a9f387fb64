#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/io/particle_output.h>

namespace dealmpm
{
  template <int dim>
  void
  ParticleOutput<dim>::build_patches(
    const ParticleSet<dim>                            &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials)
  {
    cloud = VtuPointCloud();
    // Vectors and the stress are 3D whatever dim is: ParaView treats
    // 3-component arrays as vectors and 9-component ones as tensors.
    const unsigned int i_id   = cloud.add_array("id", VtuType::Int64, 1);
    const unsigned int i_body = cloud.add_array("body", VtuType::Int32, 1);
    const unsigned int i_material =
      cloud.add_array("material", VtuType::Int32, 1);
    const unsigned int i_velocity =
      cloud.add_array("velocity", VtuType::Float32, 3);
    const unsigned int i_displacement =
      cloud.add_array("displacement", VtuType::Float32, 3);
    const unsigned int i_stress =
      cloud.add_array("stress", VtuType::Float32, 9);
    const unsigned int i_J = cloud.add_array("J", VtuType::Float32, 1);
    const unsigned int i_volume =
      cloud.add_array("volume", VtuType::Float32, 1);
    const unsigned int i_mass = cloud.add_array("mass", VtuType::Float32, 1);
    // Every field of the layout after the core ones: the materials'
    // internal variables and the kernels' and transfers' own (apic_B,
    // domain_half_length), named as in the layout.
    const CoreFields                  &f = particles.fields;
    std::vector<PropertyLayout::Field> extra;
    std::vector<unsigned int>          i_extra;
    for (const auto &field : particles.layout.fields())
      if (field.offset > f.material)
        {
          extra.push_back(field);
          i_extra.push_back(
            cloud.add_array(field.name, VtuType::Float32, field.n_components));
        }

    cloud.resize(particles.handler.n_locally_owned_particles());
    std::int64_t *id           = cloud.arrays[i_id].integers.data();
    std::int64_t *body         = cloud.arrays[i_body].integers.data();
    std::int64_t *material     = cloud.arrays[i_material].integers.data();
    double       *velocity     = cloud.arrays[i_velocity].reals.data();
    double       *displacement = cloud.arrays[i_displacement].reals.data();
    double       *stress       = cloud.arrays[i_stress].reals.data();
    double       *J            = cloud.arrays[i_J].reals.data();
    double       *volume       = cloud.arrays[i_volume].reals.data();
    double       *mass         = cloud.arrays[i_mass].reals.data();
    std::size_t   i            = 0;
    for (const auto &p : particles.handler)
      {
        const auto         props = p.get_properties();
        const Point<dim>   x     = p.get_location();
        const unsigned int m     = static_cast<unsigned int>(props[f.material]);
        const auto         F = read_tensor<dim>(&props[f.deformation_gradient]);
        const double       det_F = determinant(F);
        const SymmetricTensor<2, 3> sigma =
          full_stress(*materials[m],
                      F,
                      read_symmetric<dim>(&props[f.stress]),
                      ArrayView<const double>(props.data() +
                                                particles.internal_offset[m],
                                              particles.n_internal[m]));
        for (unsigned int d = 0; d < dim; ++d)
          {
            cloud.points[3 * i + d] = x[d];
            velocity[3 * i + d]     = props[f.velocity + d];
            displacement[3 * i + d] = props[f.displacement + d];
          }
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            stress[9 * i + 3 * a + b] = sigma[a][b];
        id[i]       = p.get_id();
        body[i]     = static_cast<std::int64_t>(props[f.body]);
        material[i] = m;
        J[i]        = det_F;
        volume[i]   = det_F * props[f.initial_volume];
        mass[i]     = props[f.mass];
        for (unsigned int e = 0; e < extra.size(); ++e)
          {
            const unsigned int n = extra[e].n_components;
            double *values = cloud.arrays[i_extra[e]].reals.data() + n * i;
            for (unsigned int k = 0; k < n; ++k)
              values[k] = props[extra[e].offset + k];
          }
        ++i;
      }
  }

  template <int dim>
  std::string
  ParticleOutput<dim>::write(const std::string &directory,
                             const unsigned int counter,
                             const MPI_Comm     comm) const
  {
    const std::string base =
      "particles_" + Utilities::int_to_string(counter, 5);
    const auto piece = [&](const unsigned int rank) {
      return base + "." + Utilities::int_to_string(rank) + ".vtu";
    };
    cloud.write_vtu(directory + "/" +
                    piece(Utilities::MPI::this_mpi_process(comm)));
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < Utilities::MPI::n_mpi_processes(comm); ++r)
          pieces.push_back(piece(r));
        cloud.write_pvtu(directory + "/" + base + ".pvtu", pieces);
      }
    return base + ".pvtu";
  }

  template class ParticleOutput<2>;
  template class ParticleOutput<3>;
} // namespace dealmpm
