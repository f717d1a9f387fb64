#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/stencil.h>

namespace dealmpm
{
  /**
   * G2P: particle velocity (FLIP fraction alpha: alpha (v_p + sum N dv) +
   * (1 - alpha) sum N v*), position and displacement (x += dt sum N v*),
   * velocity gradient L = sum v* (x) grad N, F <- (I + dt L) F, and the new
   * reference location in the old cell.
   *
   * Then, in the same pass, @p after_kinematics(particle, properties, L, F,
   * cell) (for example the stress update, see StressUpdate): the step is
   * bound by memory traffic, and one sweep over the particles less is worth
   * more than any arithmetic saved.
   *
   * @return true if some local particle left its cell (a sort is needed).
   */
  template <int dim, typename AfterKinematics>
  bool
  grid_to_particle(const BackgroundGrid<dim> &grid,
                   const Stencil<dim>        &stencil,
                   const NodalFields<dim>    &fields,
                   const double               dt,
                   const double               flip_fraction,
                   ParticleSet<dim>          &particles,
                   AfterKinematics          &&after_kinematics)
  {
    const double *velocity[dim], *increment[dim];
    for (unsigned int d = 0; d < dim; ++d)
      {
        velocity[d]  = fields.velocity[d].begin();
        increment[d] = fields.velocity_increment[d].begin();
      }
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

          Tensor<2, dim> dF = dt * L;
          for (unsigned int d = 0; d < dim; ++d)
            dF[d][d] += 1.;
          const Tensor<2, dim> F =
            dF * read_tensor<dim>(&props[f.deformation_gradient]);
          write_tensor<dim>(&props[f.deformation_gradient], F);

          const Point<dim> xi = c.reference_point(x);
          p.set_reference_location(xi);
          for (unsigned int d = 0; d < dim; ++d)
            left_cell =
              left_cell || xi[d] < -tolerance || xi[d] > 1. + tolerance;

          after_kinematics(p, props, L, F, c);
          ++k;
        }
    return left_cell;
  }
} // namespace dealmpm
