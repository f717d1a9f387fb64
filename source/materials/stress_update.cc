#include <dealmpm/materials/stress_update.h>
#include <dealmpm/transfer/stencil_order.h>

namespace dealmpm
{
  template <int dim>
  ParticleCheck<dim>
  check_particles(const BackgroundGrid<dim>                         &grid,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials,
                  const ParticleSet<dim>                            &particles)
  {
    ParticleCheck<dim> check;
    const CoreFields  &f = particles.fields;
    for_each_particle_in_stencil_order(
      grid,
      particles.handler,
      [&](std::size_t,
          const auto          &p,
          const GridCell<dim> &c) DEAL_II_ALWAYS_INLINE {
        const auto props = p.get_properties();
        check.inspect(p,
                      read_vector<dim>(&props[f.velocity]),
                      read_tensor<dim>(&props[f.deformation_gradient]),
                      read_symmetric<dim>(&props[f.stress]),
                      *materials[static_cast<unsigned int>(props[f.material])],
                      c.h);
      });
    return check;
  }

#define DEALMPM_INSTANTIATE(dim)                         \
  template ParticleCheck<dim> check_particles(           \
    const BackgroundGrid<dim> &,                         \
    const std::vector<std::unique_ptr<Material<dim>>> &, \
    const ParticleSet<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
