#pragma once

#include <dealmpm/effects/effect.h>

#include <string>

namespace dealmpm
{
  /**
   * An effect that brings a known motion (a manufactured solution): the body
   * force that makes it exact, applied in a sweep over the particles, and
   * the exact displacement for the error norms. Subclasses give the two,
   * and the initial state in initialize_particles().
   */
  template <int dim>
  class ExactSolution : public Effect<dim>
  {
  public:
    /** Body force per unit mass at reference position X and time t. */
    virtual Tensor<1, dim>
    body_force(const Point<dim> &X, const double t) const = 0;

    void
    add_nodal_forces(const EffectContext<dim> &state,
                     NodalFields<dim>         &fields) override
    {
      work +=
        state.dt * add_particle_body_force(state,
                                           fields,
                                           [&](const Point<dim> &X,
                                               const Point<dim> &,
                                               const Tensor<1, dim> &) {
                                             return body_force(X, state.time);
                                           });
    }

    double
    work_done() const override
    {
      return work;
    }

    std::vector<double>
    saved_state() const override
    {
      return {work};
    }

    void
    restore_state(const std::vector<double> &state) override
    {
      work = state.at(0);
    }

    bool
    has_exact_solution() const override
    {
      return true;
    }

  private:
    /** Left-point sum of the power over the steps. */
    double work = 0;
  };

  /** The entries of an effect with a known motion: the neo-Hookean
   * material's constants (which must equal the material's), its
   * amplitude and its wave speed. */
  void
  declare_known_motion(ParameterHandler  &prm,
                       const double       youngs_modulus,
                       const std::string &density,
                       const std::string &amplitude,
                       const std::string &wave_speed,
                       const std::string &amplitude_doc,
                       const std::string &wave_speed_doc);
} // namespace dealmpm
