#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>

#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * What the stress stage learns about the particles on the way: the
   * largest signal rate (c_p + |v_p|) / h for the CFL time step, and the
   * first particle whose state is unusable (non-finite, or J <= 0).
   */
  template <int dim>
  struct ParticleCheck
  {
    double                max_signal_rate = 0;
    bool                  failed          = false;
    types::particle_index particle        = 0;
    Point<dim>            location;
    std::string           reason;
  };

  /** Stress update of every local particle with its material, using the
   * velocity gradients of G2P (same particle order). */
  template <int dim>
  ParticleCheck<dim>
  update_stresses(const BackgroundGrid<dim> &                        grid,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials,
                  const std::vector<Tensor<2, dim>> &velocity_gradient,
                  const double                       dt,
                  ParticleSet<dim> &                 particles);

  /** The same checks without a stress update (for the first time step). */
  template <int dim>
  ParticleCheck<dim>
  check_particles(const BackgroundGrid<dim> &                        grid,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials,
                  const ParticleSet<dim> &                           particles);
} // namespace dealmpm
