#include <dealmpm/transfer/stencil_order.h>
#include <dealmpm/transfer/stress_update.h>

namespace dealmpm
{
  template <int dim>
  ParticleCheck<dim>
  check_particles(const BackgroundGrid<dim>                         &grid,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials,
                  const ParticleSet<dim>                            &particles,
                  const bool reference_cells)
  {
    ParticleCheck<dim> check;
    const CoreFields  &f = particles.fields;
    for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](std::size_t, const auto &p, const GridCell<dim> &c)
        DEAL_II_ALWAYS_INLINE {
          const auto           props = p.get_properties();
          const Tensor<2, dim> F =
            read_tensor<dim>(&props[f.deformation_gradient]);
          const unsigned int m = particles.material_of(props);
          // A unit test's particles may be laid out for other materials
          // (StressUpdate): then the state is not there to read.
          const bool laid_out = m < particles.internal_offset.size();
          check.inspect(p,
                        read_vector<dim>(&props[f.velocity]),
                        F,
                        read_symmetric<dim>(&props[f.stress]),
                        *materials[m],
                        laid_out ? ArrayView<const double>(
                                     &props[0] + particles.internal_offset[m],
                                     particles.n_internal[m]) :
                                   ArrayView<const double>(),
                        reference_cells ? c.h * smallest_stretch(F) : c.h);
        });
    return check;
  }

#define DEALMPM_INSTANTIATE(dim)                         \
  template ParticleCheck<dim> check_particles(           \
    const BackgroundGrid<dim> &,                         \
    const std::vector<std::unique_ptr<Material<dim>>> &, \
    const ParticleSet<dim> &,                            \
    bool);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
