#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/io/hdf5_points.h>
#include <dealmpm/io/output_folder.h>
#include <dealmpm/io/particle_output.h>

namespace dealmpm
{
  namespace
  {
    /** The arrays every particle has, by index into cloud.arrays. */
    struct CoreArrays
    {
      unsigned int id, body, material, rank, velocity, displacement, stress,
        deformation_gradient, J, volume, mass;
    };

    /** Vectors, the stress and F are 3D whatever dim is: ParaView treats
     * 3-component arrays as vectors and 9-component ones as tensors (in
     * 2D, F_zz = 1: plane strain). */
    CoreArrays
    add_core_arrays(VtuPointCloud &cloud)
    {
      CoreArrays a;
      a.id           = cloud.add_array("id", VtuType::Int64, 1);
      a.body         = cloud.add_array("body", VtuType::Int32, 1);
      a.material     = cloud.add_array("material", VtuType::Int32, 1);
      a.rank         = cloud.add_array("mpi_rank", VtuType::Int32, 1);
      a.velocity     = cloud.add_array("velocity", VtuType::Float32, 3);
      a.displacement = cloud.add_array("displacement", VtuType::Float32, 3);
      a.stress       = cloud.add_array("stress", VtuType::Float32, 9);
      a.deformation_gradient =
        cloud.add_array("deformation gradient", VtuType::Float32, 9);
      a.J      = cloud.add_array("J", VtuType::Float32, 1);
      a.volume = cloud.add_array("volume", VtuType::Float32, 1);
      a.mass   = cloud.add_array("mass", VtuType::Float32, 1);
      return a;
    }

    /** A layout field beyond the core ones and the array that shows it. */
    struct ExtraArray
    {
      PropertyLayout::Field field;
      unsigned int          array;
    };

    /** Every field of the layout after the core ones: the materials'
     * internal variables and the kernels' and transfers' own (apic_B,
     * domain_half_length), named as in the layout; but not a 2D
     * material's stress_zz, which 'stress' shows as its zz component. */
    template <int dim>
    std::vector<ExtraArray>
    add_extra_arrays(VtuPointCloud &cloud, const ParticleSet<dim> &particles)
    {
      std::vector<ExtraArray> extra;
      for (const auto &field : particles.layout.fields())
        if (field.offset >= particles.fields.n_core &&
            !(dim == 2 && field.name == "stress_zz"))
          extra.push_back({field,
                           cloud.add_array(field.name,
                                           VtuType::Float32,
                                           field.n_components)});
      return extra;
    }

    /** Point @p i: the particle's position and core fields; the stress
     * as its material completes it to 3 x 3 (plane strain's sigma_zz). */
    template <int dim, typename Particle>
    void
    store_core_fields(
      VtuPointCloud                                     &cloud,
      const CoreArrays                                  &a,
      const std::size_t                                  i,
      const Particle                                    &p,
      const ParticleSet<dim>                            &particles,
      const std::vector<std::unique_ptr<Material<dim>>> &materials)
    {
      const ArrayView<const double> props = p.get_properties();
      const CoreFields             &f     = particles.fields;
      const unsigned int            m     = particles.material_of(props);
      const auto   F     = read_tensor<dim>(&props[f.deformation_gradient]);
      const double det_F = determinant(F);
      const SymmetricTensor<2, 3> sigma =
        full_stress(*materials[m],
                    F,
                    read_symmetric<dim>(&props[f.stress]),
                    ArrayView<const double>(props.data() +
                                              particles.internal_offset[m],
                                            particles.n_internal[m]));
      const Point<dim> x = p.get_location();
      for (unsigned int d = 0; d < dim; ++d)
        {
          cloud.points[3 * i + d]                   = x[d];
          cloud.arrays[a.velocity].reals[3 * i + d] = props[f.velocity + d];
          cloud.arrays[a.displacement].reals[3 * i + d] =
            props[f.displacement + d];
        }
      for (unsigned int r = 0; r < 3; ++r)
        for (unsigned int c = 0; c < 3; ++c)
          {
            cloud.arrays[a.stress].reals[9 * i + 3 * r + c] = sigma[r][c];
            cloud.arrays[a.deformation_gradient].reals[9 * i + 3 * r + c] =
              (r < dim && c < dim) ? F[r][c] : (r == c ? 1. : 0.);
          }
      cloud.arrays[a.id].integers[i] = p.get_id();
      // Counted from 1, as the scene's 'Body N' and 'Material N' are.
      cloud.arrays[a.body].integers[i]     = particles.body_of(props) + 1;
      cloud.arrays[a.material].integers[i] = m + 1;
      // The rank that owns the particle's cell owns the particle.
      cloud.arrays[a.rank].integers[i] =
        p.get_surrounding_cell()->subdomain_id();
      cloud.arrays[a.J].reals[i]      = det_F;
      cloud.arrays[a.volume].reals[i] = det_F * props[f.initial_volume];
      cloud.arrays[a.mass].reals[i]   = props[f.mass];
    }

    /** Point @p i: the extra fields' components. */
    void
    store_extra_fields(VtuPointCloud                 &cloud,
                       const std::vector<ExtraArray> &extra,
                       const std::size_t              i,
                       const ArrayView<const double>  props)
    {
      for (const ExtraArray &e : extra)
        {
          const unsigned int n = e.field.n_components;
          double *values       = cloud.arrays[e.array].reals.data() + n * i;
          for (unsigned int k = 0; k < n; ++k)
            values[k] = props[e.field.offset + k];
        }
    }
  } // namespace

  template <int dim>
  void
  ParticleOutput<dim>::build_patches(
    const ParticleSet<dim>                            &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials)
  {
    cloud                               = VtuPointCloud();
    const CoreArrays              core  = add_core_arrays(cloud);
    const std::vector<ExtraArray> extra = add_extra_arrays(cloud, particles);
    cloud.resize(particles.handler.n_locally_owned_particles());
    std::size_t i = 0;
    for (const auto &p : particles.handler)
      {
        store_core_fields(cloud, core, i, p, particles, materials);
        store_extra_fields(cloud, extra, i, p.get_properties());
        ++i;
      }
  }

  template <int dim>
  std::string
  ParticleOutput<dim>::write(const std::string &directory,
                             const unsigned int counter,
                             const MPI_Comm     comm,
                             const bool         zlib) const
  {
    const std::string base =
      "particles_" + Utilities::int_to_string(counter, 5);
    return write_vtu_pieces(cloud,
                            directory,
                            base,
                            Utilities::MPI::this_mpi_process(comm),
                            Utilities::MPI::n_mpi_processes(comm),
                            zlib);
  }

  template <int dim>
  std::string
  ParticleOutput<dim>::write_hdf5(const std::string &directory,
                                  const unsigned int counter,
                                  const double       time,
                                  const MPI_Comm     comm) const
  {
    const std::string name =
      "particles_" + Utilities::int_to_string(counter, 5) + ".h5";
    return Hdf5PointCloud::write(
      cloud, directory + "/" + name, step_folder + "/" + name, time, comm);
  }

  template class ParticleOutput<2>;
  template class ParticleOutput<3>;
} // namespace dealmpm
