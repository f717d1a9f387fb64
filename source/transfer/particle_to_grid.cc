#include <dealmpm/transfer/particle_to_grid.h>
#include <dealmpm/transfer/stencil_order.h>

namespace dealmpm
{
  namespace
  {
    /** -V_p sigma_p (updated Lagrangian), or -V_p0 P_p = -V_p sigma_p
     * F_p^-T (total Lagrangian, whose stencil holds reference gradients):
     * the particle's internal force on a node is this times grad N. */
    template <bool total_lagrangian, int dim>
    DEAL_II_ALWAYS_INLINE inline auto
    force_per_gradient(const ArrayView<const double> &props,
                       const CoreFields              &f)
    {
      const Tensor<2, dim> F = read_tensor<dim>(&props[f.deformation_gradient]);
      const SymmetricTensor<2, dim> minus_V_sigma =
        -determinant(F) * props[f.initial_volume] *
        read_symmetric<dim>(&props[f.stress]);
      if constexpr (total_lagrangian)
        return Tensor<2, dim>(minus_V_sigma * transpose(invert(F)));
      else
        return minus_V_sigma;
    }

    /** The kernel, compiled once per choice of quantities so that the usual
     * all-in-one P2G has no branch in its loop. */
    template <int  dim,
              bool mass_and_momentum,
              bool internal_force,
              bool affine,
              bool total_lagrangian = false,
              bool predictor        = false>
    void
    transfer(const BackgroundGrid<dim> &grid,
             const ParticleSet<dim>    &particles,
             const Stencil<dim>        &stencil,
             NodalFields<dim>          &fields,
             const double               predictor_offset = 0)
    {
      double *mass = fields.mass.begin();
      double *momentum[dim], *force[dim];
      for (unsigned int d = 0; d < dim; ++d)
        {
          momentum[d] = fields.momentum[d].begin();
          force[d]    = fields.force[d].begin();
        }
      const CoreFields &f = particles.fields;

      for_each_particle_in_stencil_order(
        grid,
        particles.handler,
        [&](const std::size_t k,
            const auto       &p,
            const GridCell<dim> &) DEAL_II_ALWAYS_INLINE {
          const ArrayView<const double> props = p.get_properties();
          const double                  m     = props[f.mass];
          Tensor<1, dim> v = read_vector<dim>(&props[f.velocity]);
          // Newmark: the grid carries the predicted velocity.
          if constexpr (predictor)
            v -= predictor_offset * read_vector<dim>(&props[f.acceleration]);
          // APIC: the particle carries the affine field v + C (x - x_p)
          // with C = B D^-1, B stored by G2P and D = sum N (x_i - x_p) (x)
          // (x_i - x_p), x_p the position of the stencil (MUSL re-maps
          // after the particles moved): with this D the round trip
          // conserves angular momentum exactly (Jiang et al. 2015).
          Tensor<2, dim> C;
          Point<dim>     x_p;
          if (affine)
            {
              x_p = stencil.position[k];
              Tensor<2, dim> D;
              for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1];
                   ++e)
                {
                  const Tensor<1, dim> r =
                    grid.node_positions[stencil.node[e]] - x_p;
                  D += stencil.N[e] * outer_product(r, r);
                }
              // D is singular only for a particle on a node line.
              if (std::abs(determinant(D)) >
                  1e-12 * Utilities::fixed_power<dim>(trace(D)))
                C = read_tensor<dim>(&props[f.affine_velocity]) * invert(D);
            }
          // Once per particle.
          decltype(force_per_gradient<total_lagrangian, dim>(props, f)) Vsigma;
          if (internal_force)
            Vsigma = force_per_gradient<total_lagrangian, dim>(props, f);
          for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
            {
              const unsigned int n = stencil.node[e];
              if (mass_and_momentum)
                {
                  const double mN = m * stencil.N[e];
                  mass[n] += mN;
                  const Tensor<1, dim> v_n =
                    affine ? v + C * (grid.node_positions[n] - x_p) : v;
                  for (unsigned int d = 0; d < dim; ++d)
                    momentum[d][n] += mN * v_n[d];
                }
              if (internal_force)
                {
                  const Tensor<1, dim> fi = Vsigma * stencil.grad_N[e];
                  for (unsigned int d = 0; d < dim; ++d)
                    force[d][n] += fi[d];
                }
            }
        });
    }
  } // namespace

  template <int dim>
  void
  particle_to_grid(const BackgroundGrid<dim> &grid,
                   const ParticleSet<dim>    &particles,
                   const Stencil<dim>        &stencil,
                   NodalFields<dim>          &fields,
                   const bool                 mass_and_momentum,
                   const bool                 internal_force,
                   const Formulation          formulation,
                   const double               predictor_offset)
  {
    if (mass_and_momentum)
      {
        fields.mass = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          fields.momentum[d] = 0.;
      }
    if (internal_force)
      for (unsigned int d = 0; d < dim; ++d)
        fields.force[d] = 0.;

    const bool affine =
      particles.fields.affine_velocity != numbers::invalid_unsigned_int;
    const bool reference = formulation == Formulation::total_lagrangian;
    if (predictor_offset != 0.)
      {
        // Newmark's first P2G (FLIP only: no affine part).
        AssertThrow(mass_and_momentum && internal_force && !affine &&
                      particles.fields.acceleration !=
                        numbers::invalid_unsigned_int,
                    ExcInternalError());
        if (reference)
          transfer<dim, true, true, false, true, true>(
            grid, particles, stencil, fields, predictor_offset);
        else
          transfer<dim, true, true, false, false, true>(
            grid, particles, stencil, fields, predictor_offset);
      }
    else if (internal_force && reference)
      {
        if (mass_and_momentum && affine)
          transfer<dim, true, true, true, true>(grid,
                                                particles,
                                                stencil,
                                                fields);
        else if (mass_and_momentum)
          transfer<dim, true, true, false, true>(grid,
                                                 particles,
                                                 stencil,
                                                 fields);
        else
          transfer<dim, false, true, false, true>(grid,
                                                  particles,
                                                  stencil,
                                                  fields);
      }
    else if (mass_and_momentum && internal_force && affine)
      transfer<dim, true, true, true>(grid, particles, stencil, fields);
    else if (mass_and_momentum && internal_force)
      transfer<dim, true, true, false>(grid, particles, stencil, fields);
    else if (mass_and_momentum && affine)
      transfer<dim, true, false, true>(grid, particles, stencil, fields);
    else if (mass_and_momentum)
      transfer<dim, true, false, false>(grid, particles, stencil, fields);
    else if (internal_force)
      transfer<dim, false, true, false>(grid, particles, stencil, fields);

    if (mass_and_momentum)
      {
        fields.mass.compress(VectorOperation::add);
        for (unsigned int d = 0; d < dim; ++d)
          fields.momentum[d].compress(VectorOperation::add);
      }
    if (internal_force)
      for (unsigned int d = 0; d < dim; ++d)
        fields.force[d].compress(VectorOperation::add);
  }

#define DEALMPM_INSTANTIATE(dim)                              \
  template void particle_to_grid(const BackgroundGrid<dim> &, \
                                 const ParticleSet<dim> &,    \
                                 const Stencil<dim> &,        \
                                 NodalFields<dim> &,          \
                                 bool,                        \
                                 bool,                        \
                                 Formulation,                 \
                                 double);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
