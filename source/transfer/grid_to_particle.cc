#include <dealmpm/transfer/grid_to_particle.h>

namespace dealmpm
{
  template <int dim>
  bool
  grid_to_particle(const BackgroundGrid<dim> &  grid,
                   const Stencil<dim> &         stencil,
                   const NodalFields<dim> &     fields,
                   const double                 dt,
                   const double                 flip_fraction,
                   ParticleSet<dim> &           particles,
                   std::vector<Tensor<2, dim>> &velocity_gradient)
  {
    const double *velocity[dim], *increment[dim];
    for (unsigned int d = 0; d < dim; ++d)
      {
        velocity[d]  = fields.velocity[d].begin();
        increment[d] = fields.velocity_increment[d].begin();
      }
    velocity_gradient.resize(stencil.n_particles());
    const CoreFields &f = particles.fields;
    // Slack so that a particle sitting on a face does not trigger a sort.
    const double tolerance = 1e-12;
    bool         left_cell = false;

    std::size_t k = 0;
    for (const GridCell<dim> &c : grid.cells)
      for (auto &p : particles.handler.particles_in_cell(c.cell))
        {
          Tensor<1, dim> v_new, dv;
          Tensor<2, dim> L;
          for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
            {
              const unsigned int n = stencil.node[e];
              const double       N = stencil.N[e];
              for (unsigned int d = 0; d < dim; ++d)
                {
                  v_new[d] += N * velocity[d][n];
                  dv[d] += N * increment[d][n];
                  for (unsigned int b = 0; b < dim; ++b)
                    L[d][b] += velocity[d][n] * stencil.grad_N[e][b];
                }
            }
          const ArrayView<double> props = p.get_properties();
          const Tensor<1, dim>    v_old = read_vector<dim>(&props[f.velocity]);
          write_vector<dim>(&props[f.velocity],
                            flip_fraction * (v_old + dv) +
                              (1. - flip_fraction) * v_new);
          const Tensor<1, dim> dx = dt * v_new;
          write_vector<dim>(&props[f.displacement],
                            read_vector<dim>(&props[f.displacement]) + dx);
          const Point<dim> x = p.get_location() + dx;
          p.set_location(x);

          Tensor<2, dim> F = read_tensor<dim>(&props[f.deformation_gradient]);
          Tensor<2, dim> dF = dt * L;
          for (unsigned int d = 0; d < dim; ++d)
            dF[d][d] += 1.;
          write_tensor<dim>(&props[f.deformation_gradient], dF * F);
          velocity_gradient[k] = L;

          const Point<dim> xi = c.reference_point(x);
          p.set_reference_location(xi);
          for (unsigned int d = 0; d < dim; ++d)
            left_cell = left_cell || xi[d] < -tolerance || xi[d] > 1. + tolerance;
          ++k;
        }
    return left_cell;
  }

  template bool
  grid_to_particle(const BackgroundGrid<2> &, const Stencil<2> &, const NodalFields<2> &, double, double, ParticleSet<2> &, std::vector<Tensor<2, 2>> &);
  template bool
  grid_to_particle(const BackgroundGrid<3> &, const Stencil<3> &, const NodalFields<3> &, double, double, ParticleSet<3> &, std::vector<Tensor<2, 3>> &);
} // namespace dealmpm
