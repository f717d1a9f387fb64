#pragma once

#include <dealmpm/effects/exact_solution.h>
#include <dealmpm/materials/material.h>

namespace dealmpm
{
  /**
   * The generalized vortex (Brannon et al.; as in Steffen et al. 2008 and
   * Sadeghirad et al. 2011), 2D: rings of the annulus 0.75 < R < 1.25 turn
   * by alpha = A sin(c pi t) h(R), h = 1 - 32 (R - 1)^2 + 256 (R - 1)^4, a
   * large shear with J = 1 and traction-free rims. The effect sets the
   * initial tangential velocity, applies the body force that makes this
   * exact for a neo-Hookean solid, and gives the exact displacement for the
   * error norms. Its constants must be the material's.
   */
  template <int dim>
  class GeneralizedVortex : public ExactSolution<dim>
  {
  public:
    GeneralizedVortex(const double mu,
                      const double density,
                      const double amplitude,
                      const double wave_speed);

    void
    initialize_particles(ParticleSet<dim> &particles) const override;


    Tensor<1, dim>
    exact_displacement(const Point<dim> &X, const double t) const override;

    Tensor<1, dim>
    body_force(const Point<dim> &X, const double t) const override;

  private:
    double mu, density, amplitude, wave_speed;
  };

  /** Register "generalized vortex" in the effect table: its parameters (section
   * Generalized vortex), their reading and checks. */
  template <int dim>
  void
  add_generalized_vortex_effect(Registry<Effect<dim>> &registry);
} // namespace dealmpm
