#include <dealmpm/transfer/particle_to_grid.h>

namespace dealmpm
{
  template <int dim>
  void
  particle_to_grid(const BackgroundGrid<dim> &grid,
                   const ParticleSet<dim>    &particles,
                   const Stencil<dim>        &stencil,
                   NodalFields<dim>          &fields)
  {
    fields.mass  = 0.;
    double *mass = fields.mass.begin();
    double *momentum[dim], *force[dim];
    for (unsigned int d = 0; d < dim; ++d)
      {
        fields.momentum[d] = 0.;
        fields.force[d]    = 0.;
        momentum[d]        = fields.momentum[d].begin();
        force[d]           = fields.force[d].begin();
      }
    const CoreFields &f = particles.fields;

    std::size_t k = 0;
    for (const GridCell<dim> &c : grid.cells)
      for (const auto &p : particles.handler.particles_in_cell(c.cell))
        {
          const ArrayView<const double> props = p.get_properties();
          const double                  m     = props[f.mass];
          const Tensor<1, dim> v = read_vector<dim>(&props[f.velocity]);
          const Tensor<2, dim> F =
            read_tensor<dim>(&props[f.deformation_gradient]);
          const SymmetricTensor<2, dim> sigma =
            read_symmetric<dim>(&props[f.stress]);
          const double volume = determinant(F) * props[f.initial_volume];
          // -V sigma grad N, with sigma scaled once per particle.
          const SymmetricTensor<2, dim> Vsigma = -volume * sigma;
          for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
            {
              const unsigned int   n  = stencil.node[e];
              const double         mN = m * stencil.N[e];
              const Tensor<1, dim> fi = Vsigma * stencil.grad_N[e];
              mass[n] += mN;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  momentum[d][n] += mN * v[d];
                  force[d][n] += fi[d];
                }
            }
          ++k;
        }

    fields.mass.compress(VectorOperation::add);
    for (unsigned int d = 0; d < dim; ++d)
      {
        fields.momentum[d].compress(VectorOperation::add);
        fields.force[d].compress(VectorOperation::add);
      }
  }

  template void
  particle_to_grid(const BackgroundGrid<2> &,
                   const ParticleSet<2> &,
                   const Stencil<2> &,
                   NodalFields<2> &);
  template void
  particle_to_grid(const BackgroundGrid<3> &,
                   const ParticleSet<3> &,
                   const Stencil<3> &,
                   NodalFields<3> &);
} // namespace dealmpm
