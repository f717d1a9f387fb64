#include <dealmpm/io/statistics_file.h>

#include <iomanip>

namespace dealmpm
{
  StatisticsFile::StatisticsFile(const std::string &path,
                                 const unsigned int dim,
                                 const bool         errors,
                                 const bool         writer)
    : dim(dim)
    , errors(errors)
  {
    if (!writer)
      return;
    out.open(path);
    out << "step,time,dt,n_particles,mass,momentum_x,momentum_y";
    if (dim == 3)
      out << ",momentum_z";
    out << ",kinetic_energy,strain_energy,gravitational_energy,total_energy,"
           "external_work,energy_drift,momentum_drift,mass_loss,min_J,max_cfl,"
           "lost_particles,wall_time";
    if (errors)
      out << ",error_L2,error_max";
    out << '\n';
    out << std::setprecision(16);
  }

  void
  StatisticsFile::write_row(const unsigned int    step,
                            const double          time,
                            const double          dt,
                            const Statistics     &s,
                            const double          external_work,
                            const AccuracyReport &a,
                            const double          n_lost_particles,
                            const double          wall_time)
  {
    if (!out.is_open())
      return;
    out << step << ',' << time << ',' << dt << ',' << s.n_particles << ','
        << s.mass;
    for (unsigned int d = 0; d < dim; ++d)
      out << ',' << s.momentum[d];
    out << ',' << s.kinetic_energy << ',' << s.strain_energy << ','
        << s.gravitational_energy << ',' << s.total_energy() << ','
        << external_work << ',' << a.energy_drift << ',' << a.momentum_drift
        << ',' << a.mass_loss << ',' << a.min_J << ',' << a.max_cfl << ','
        << n_lost_particles << ',' << wall_time;
    if (errors)
      out << ',' << s.error_L2 << ',' << s.error_max;
    out << '\n' << std::flush;
  }
} // namespace dealmpm
