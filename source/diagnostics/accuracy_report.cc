#include <dealmpm/diagnostics/accuracy_report.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace dealmpm
{
  void
  AccuracyMonitor::start(const Statistics &s, const double floor)
  {
    initial             = s;
    energy_floor        = floor;
    max_energy_supplied = 0;
    max_kinetic_energy  = 0;
    current             = AccuracyReport();
    observe(s, 0.);
  }

  void
  AccuracyMonitor::observe_step(const double min_J, const double cfl)
  {
    current.min_J   = std::min(current.min_J, min_J);
    current.max_cfl = std::max(current.max_cfl, cfl);
  }

  void
  AccuracyMonitor::observe(const Statistics &s, const double external_work)
  {
    max_energy_supplied =
      std::max(max_energy_supplied,
               std::abs(external_work) + std::max(0.,
                                                  initial.gravitational_energy -
                                                    s.gravitational_energy));
    max_kinetic_energy     = std::max(max_kinetic_energy, s.kinetic_energy);
    const double energy_in = std::max(energy_put_in(), energy_floor);
    current.of_floor       = energy_put_in() < energy_floor;
    current.energy_drift =
      energy_in > 0 ?
        (s.total_energy() - external_work - initial.total_energy()) /
          energy_in :
        0.;
    double change = 0;
    for (unsigned int d = 0; d < 3; ++d)
      change += std::pow(s.momentum[d] + s.removed_momentum[d] -
                           initial.momentum[d] - initial.removed_momentum[d],
                         2);
    const double momentum_scale = std::sqrt(2 * s.mass * max_kinetic_energy);
    current.momentum_drift =
      momentum_scale > 0 ? std::sqrt(change) / momentum_scale : 0.;
    current.mass_loss =
      initial.mass > 0 ?
        (initial.mass + initial.removed_mass - s.mass - s.removed_mass) /
          initial.mass :
        0.;
    // The same masses summed in another order (particles change ranks and
    // cells) differ by round-off, not by a lost particle.
    if (std::abs(current.mass_loss) < 1e-12)
      current.mass_loss = 0;
    current.has_error = s.has_error;
    current.error_L2  = s.error_L2;
    current.error_max = s.error_max;
  }

  double
  AccuracyMonitor::energy_put_in() const
  {
    return initial.kinetic_energy + initial.strain_energy + max_energy_supplied;
  }

  std::string
  AccuracyMonitor::energy_scale() const
  {
    if (!current.of_floor)
      return "the energy put in";
    std::ostringstream s;
    s << std::setprecision(3) << "(m |g| + F) h / 1000 = " << energy_floor
      << " J, the work of gravity and the loads over a thousandth of a cell "
         "(larger than "
         "the energy put in, "
      << energy_put_in() << " J)";
    return s.str();
  }

  std::ostream &
  operator<<(std::ostream &out, const AccuracyReport &r)
  {
    const auto flags     = out.flags();
    const auto precision = out.precision();
    out << std::setprecision(3) << "accuracy: energy drift "
        << 100 * r.energy_drift << " % of "
        << (r.of_floor ? "(m |g| + F) h / 1000" : "the energy put in")
        << ", momentum drift ";
    if (r.momentum_conserved)
      out << 100 * r.momentum_drift << " %";
    else
      out << "n/a (walls, loads or body forces act)";
    out << ", mass loss " << 100 * r.mass_loss << " %, smallest J " << r.min_J
        << ", largest particle CFL " << r.max_cfl;
    if (r.has_error)
      out << ", displacement error L2 " << r.error_L2 << " max " << r.error_max;
    out.flags(flags);
    out.precision(precision);
    return out;
  }
} // namespace dealmpm
