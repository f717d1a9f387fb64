#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/particle_update.h>
#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stencil_order.h>

namespace dealmpm
{
  /**
   * Newmark's first G2P (see NewmarkStep): the particle acceleration a_p =
   * sum N (v*_i - v_i) / @p dt from the grid update's increment (walls'
   * reactions included, as FLIP sees them), then velocity := the
   * displacement velocity d = v~ + step.displacement a_p (v~ = v -
   * step.predictor_offset a_old, what P2G mapped) for the re-map, and the
   * acceleration := a_p. The particles do not move here.
   */
  template <int dim>
  void
  newmark_predict(const BackgroundGrid<dim> &grid,
                  const Stencil<dim>        &stencil,
                  const NodalFields<dim>    &fields,
                  const NewmarkStep         &step,
                  const double               dt,
                  ParticleSet<dim>          &particles)
  {
    const double *increment[dim];
    for (unsigned int d = 0; d < dim; ++d)
      increment[d] = fields.velocity_increment[d].begin();
    const CoreFields &f = particles.fields;
    for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t k, auto &p, const GridCell<dim> &)
        DEAL_II_ALWAYS_INLINE {
          Tensor<1, dim> dv;
          for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
            for (unsigned int d = 0; d < dim; ++d)
              dv[d] += stencil.N[e] * increment[d][stencil.node[e]];
          const ArrayView<double> props = p.get_properties();
          const Tensor<1, dim>    a     = dv / dt;
          const Tensor<1, dim>    predicted =
            read_vector<dim>(&props[f.velocity]) -
            step.predictor_offset * read_vector<dim>(&props[f.acceleration]);
          write_vector<dim>(&props[f.velocity],
                            predicted + step.displacement * a);
          write_vector<dim>(&props[f.acceleration], a);
        });
  }

  /**
   * The after-deformation callback of Newmark's second G2P: the particle
   * velocity := d + @p reported a_p (NewmarkStep::reported; d the
   * displacement velocity newmark_predict() left there), then @p next (the
   * stress update).
   */
  template <typename Next>
  struct ReportNewmarkVelocity
  {
    double       reported;
    unsigned int velocity, acceleration;
    Next        &next;

    template <typename Particle, int dim>
    DEAL_II_ALWAYS_INLINE inline void
    operator()(Particle                &p,
               const ArrayView<double> &props,
               const Tensor<2, dim>    &L,
               const Tensor<2, dim>    &F,
               const double             h)
    {
      write_vector<dim>(&props[velocity],
                        read_vector<dim>(&props[velocity]) +
                          reported * read_vector<dim>(&props[acceleration]));
      next(p, props, L, F, h);
    }
  };
} // namespace dealmpm
