#include <dealmpm/base/run_messages.h>
#include <dealmpm/diagnostics/run_guards.h>
#include <dealmpm/diagnostics/statistics.h>

#include <iomanip>
#include <sstream>

namespace dealmpm
{
  template <int dim>
  std::string
  fastest_particle(const ParticleCheck<dim> &check,
                   const double              max_signal_rate,
                   const ParticleSet<dim>   &particles,
                   const MPI_Comm            comm)
  {
    const bool here = particles.handler.n_locally_owned_particles() > 0 &&
                      check.max_signal_rate == max_signal_rate;
    return first_message(here ?
                           "particle " + std::to_string(check.fastest) +
                             " at " + format_point(check.fastest_location) :
                           "",
                         comm);
  }

  std::string
  check_fixed_time_step(const double                        dt,
                        const double                        max_signal_rate,
                        const double                        cfl_warning,
                        const bool                          warned,
                        const std::function<std::string()> &where)
  {
    const double cfl = dt * max_signal_rate;
    if (cfl <= cfl_warning || (warned && cfl <= 1))
      return "";
    std::ostringstream text;
    text << std::setprecision(3) << where() << ": the fixed time step " << dt
         << " gives a particle CFL number dt (c + |v|) / h of " << cfl;
    if (cfl > 1)
      throw RunError(text.str() +
                     " > 1, which is unstable; the largest stable step "
                     "here is " +
                     short_number(1. / max_signal_rate) +
                     ": set a smaller 'Time/Time step' or 'Time/Time step "
                     "method = CFL'");
    text << " (above 'Checks/CFL warning' = " << cfl_warning
         << "; unstable above 1, at a step of "
         << short_number(1. / max_signal_rate) << "); warned once";
    return text.str();
  }

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
    const MPI_Comm                                     comm)
  {
    const EnergyGain<dim> local =
      largest_energy_gain(particles, materials, effects, initial_velocity);
    const double       largest = Utilities::MPI::max(local.gain, comm);
    std::ostringstream particle;
    particle << std::setprecision(3) << "particle " << local.particle << " at "
             << format_point(local.location) << " (+" << local.gain << " J)";
    std::ostringstream message;
    message << std::setprecision(3) << when << ": the total energy grew by "
            << 100 * drift << " % of " << scale
            << " (limit 'Checks/Energy growth limit' "
               "= "
            << 100 * limit << " %); the particle whose energy grew most: "
            << first_message(local.gain == largest ? particle.str() : "", comm)
            << ". Energy grows when particles cross cells and when nodes "
               "carry little mass: try a smaller 'Time/CFL number', "
               "'MPM/Stress update = MUSL' or a GIMP or CPDI 'MPM/Shape "
               "function'";
    return RunError(message.str());
  }

#define DEALMPM_INSTANTIATE(dim)                                    \
  template std::string fastest_particle(const ParticleCheck<dim> &, \
                                        const double,               \
                                        const ParticleSet<dim> &,   \
                                        const MPI_Comm);            \
  template RunError    energy_growth_error(                         \
       const ParticleSet<dim> &,                                    \
       const std::vector<std::unique_ptr<Material<dim>>> &,         \
       const std::vector<std::unique_ptr<Effect<dim>>> &,           \
       const std::vector<Tensor<1, dim>> &,                         \
       const double,                                                \
       const std::string &,                                         \
       const double,                                                \
       const std::string &,                                         \
       const MPI_Comm);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
