#include <dealmpm/base/run_messages.h>
#include <dealmpm/materials/damaged_material.h>
#include <dealmpm/materials/geostatic_history.h>
#include <dealmpm/materials/geostatic_start.h>
#include <dealmpm/materials/initial_stress.h>

#include <algorithm>
#include <limits>

namespace dealmpm
{
  namespace
  {
    /** Put the particle @p p of material @p m in its geostatic state at
     * @p depth; false when the material cannot rest under it. */
    template <int dim>
    bool
    start_particle(const Material<dim>     &material,
                   const unsigned int       m,
                   const double             sigma_v,
                   const Tensor<1, dim>    &n,
                   const double             K0,
                   ParticleSet<dim>        &particles,
                   const ArrayView<double> &props)
    {
      const CoreFields             &f      = particles.fields;
      const SymmetricTensor<2, dim> target = geostatic_stress(sigma_v, n, K0);
      Tensor<2, dim>                F;
      SymmetricTensor<2, dim>       stress;
      if (!start_at_stress(material,
                           target,
                           F,
                           stress,
                           ArrayView<double>(props.data() +
                                               particles.internal_offset[m],
                                             particles.n_internal[m])))
        return false;
      // A damaged model's own variables come first.
      const auto *damaged =
        dynamic_cast<const DamagedMaterial<dim> *>(&material);
      if (const auto *history = dynamic_cast<const GeostaticHistory<dim> *>(
            damaged != nullptr ? &damaged->inner_model() : &material))
        history->start_history(F,
                               stress,
                               ArrayView<double>(props.data() +
                                                   particles.internal_offset[m],
                                                 particles.n_internal[m]));
      write_tensor<dim>(&props[f.deformation_gradient], F);
      write_symmetric<dim>(&props[f.stress], stress);
      // The particle fills its place at that stretch: its volume and
      // (cpGIMP, CPDI) its domain are those it was filled with.
      props[f.initial_volume] /= determinant(F);
      if (f.domain_half_length != numbers::invalid_unsigned_int)
        for (unsigned int d = 0; d < dim; ++d)
          props[f.domain_half_length + d] /= F[d][d];
      return true;
    }
  } // namespace

  template <int dim>
  void
  start_geostatic_bodies(
    SceneReader                                       &reader,
    const std::vector<Body<dim>>                      &bodies,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const Tensor<1, dim>                              &g,
    ParticleSet<dim>                                  &particles,
    const MPI_Comm                                     comm)
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        if (!bodies[b].geostatic)
          continue;
        SectionScope         section(reader, "Body " + std::to_string(b + 1));
        const Tensor<1, dim> n        = g / g.norm();
        const unsigned int   m        = bodies[b].material;
        const Material<dim> &material = *materials[m];
        const double         K0 =
          bodies[b].K0 >= 0 ?
                    bodies[b].K0 :
                    confined_stress_ratio(material, particles.n_internal[m], n);
        std::string failure;
        for (auto &p : particles.handler)
          {
            const auto props = p.get_properties();
            if (particles.body_of(props) != b)
              continue;
            const double depth = bodies[b].shape->depth(p.get_location(), n);
            if (!start_particle(material,
                                m,
                                -material.density * g.norm() * depth,
                                n,
                                K0,
                                particles,
                                props) &&
                failure.empty())
              failure = "'Material " + std::to_string(m + 1) +
                        "' cannot rest under the geostatic stress at depth " +
                        short_number(depth) + " (particle " +
                        std::to_string(p.get_id()) + ")";
          }
        failure = first_message(failure, comm);
        if (!failure.empty())
          reader.fail("K0",
                      "a K0 whose stress the material carries at rest "
                      "(inside its yield surface; 1 for a fluid): " +
                        failure + ", with K0 = " + short_number(K0));
      }
  }

#define DEALMPM_INSTANTIATE(dim)                         \
  template void start_geostatic_bodies(                  \
    SceneReader &,                                       \
    const std::vector<Body<dim>> &,                      \
    const std::vector<std::unique_ptr<Material<dim>>> &, \
    const Tensor<1, dim> &,                              \
    ParticleSet<dim> &,                                  \
    const MPI_Comm);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
