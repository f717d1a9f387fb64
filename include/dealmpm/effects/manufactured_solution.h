#pragma once

#include <dealmpm/effects/exact_solution.h>
#include <dealmpm/materials/material.h>

namespace dealmpm
{
  /**
   * The axis-aligned manufactured solution of Wallstedt and Guilkey (2008)
   * and Steffen et al. (2008) on the unit square/cube, for a compressible
   * neo-Hookean solid: u_i = A sin(pi X_i) sin(c pi t + phi_i),
   * phi = (0, 2 pi / 3, 4 pi / 3). The effect sets the initial velocity,
   * applies the body force that makes u exact, and gives u for the error
   * norms in the statistics. Its elastic constants and density must be the
   * material's (the scene in prm/ keeps them equal); every face of the unit
   * square/cube needs a slip condition (u_i = 0 where X_i = 0 or 1).
   */
  template <int dim>
  class ManufacturedSolution : public ExactSolution<dim>
  {
  public:
    ManufacturedSolution(const LameParameters &lame,
                         const double          density,
                         const double          amplitude,
                         const double          wave_speed);

    void
    initialize_particles(ParticleSet<dim> &particles) const override;


    Tensor<1, dim>
    exact_displacement(const Point<dim> &X, const double t) const override;

    Tensor<1, dim>
    body_force(const Point<dim> &X, const double t) const override;

  private:
    static double
    phase(const unsigned int i);

    LameParameters lame;
    double         density;
    double         amplitude;
    double         wave_speed;
  };

  /** Register "manufactured solution" in the effect table: its parameters
   * (section Manufactured solution), their reading and checks. */
  template <int dim>
  void
  add_manufactured_solution_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
