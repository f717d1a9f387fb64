#pragma once

#include <dealmpm/base/errors.h>
#include <dealmpm/effects/effect.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/stress_update.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /** "particle N at (x, y)": the particle whose signal rate is the largest
   * over all ranks, @p max_signal_rate (collective). */
  template <int dim>
  std::string
  fastest_particle(const ParticleCheck<dim> &check,
                   const double              max_signal_rate,
                   const ParticleSet<dim>   &particles,
                   const MPI_Comm            comm);

  /**
   * A fixed time step against the particle CFL limit dt (c + |v|) / h:
   * above 1 it throws RunError (unstable), above @p cfl_warning it returns
   * a warning to print once (@p warned: it was printed already), else "".
   * @p where: "step N (t = T): particle P at (x)", asked for (collectively)
   * only when there is something to say.
   */
  std::string
  check_fixed_time_step(const double                        dt,
                        const double                        max_signal_rate,
                        const double                        cfl_warning,
                        const bool                          warned,
                        const std::function<std::string()> &where);

  /** The stop of a run whose energy grew by @p drift of the energy put in,
   * past @p limit, naming the particle whose energy grew most (its body's
   * initial velocity in @p initial_velocity). Collective. */
  template <int dim>
  RunError
  energy_growth_error(
    const ParticleSet<dim>                            &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const std::vector<std::unique_ptr<Effect<dim>>>   &effects,
    const std::vector<Tensor<1, dim>>                 &initial_velocity,
    const double                                       drift,
    const std::string                                 &scale,
    const double                                       limit,
    const std::string                                 &when,
    const MPI_Comm                                     comm);
} // namespace dealmpm
