#include <dealmpm/base/errors.h>
#include <dealmpm/io/statistics_file.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <unistd.h>

namespace dealmpm
{
  namespace
  {
    /** The column names: the core ones, the optional ones of this run,
     * the effects' and regions' columns. */
    std::string
    header_of(const unsigned int dim, const Statistics &first)
    {
      std::string header =
        "step,time,dt,n_particles,mass,momentum_x,momentum_y";
      if (dim == 3)
        header += ",momentum_z";
      header += ",kinetic_energy,strain_energy,gravitational_energy";
      if (first.has_dissipated_work)
        header += ",dissipated_work";
      header +=
        ",total_energy,"
        "external_work,energy_drift,momentum_drift,mass_loss,min_J,max_cfl,"
        "lost_particles,wall_time,particles_per_rank_min,"
        "particles_per_rank_max,particles_per_rank_mean";
      if (first.has_error)
        header += ",error_L2,error_max";
      for (const std::string &name : first.effect_columns)
        header += "," + name;
      return header + '\n';
    }

    /** The bytes of @p path a resumed run keeps: the header and the rows up
     * to its checkpoint's step, not those the interrupted run wrote after
     * it (0 for a new run or another header). */
    std::size_t
    bytes_kept(const std::string &path,
               const std::string &header,
               const long long    keep_up_to_step)
    {
      std::size_t kept = 0;
      if (keep_up_to_step < 0)
        return kept;
      std::ifstream in(path);
      std::string   line;
      if (std::getline(in, line) && line + '\n' == header)
        {
          kept = header.size();
          while (std::getline(in, line) && in.good())
            {
              const long long step = std::atoll(line.c_str());
              if (line.empty() || step > keep_up_to_step)
                break;
              kept += line.size() + 1;
            }
        }
      return kept;
    }
  } // namespace

  StatisticsFile::StatisticsFile(const std::string &path,
                                 const unsigned int dim,
                                 const Statistics  &first,
                                 const long long    keep_up_to_step)
    : path(path)
    , dim(dim)
    , errors(first.has_error)
    , dissipated_work(first.has_dissipated_work)
  {
    const std::string header = header_of(dim, first);
    const std::size_t kept   = bytes_kept(path, header, keep_up_to_step);
    fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0 || ::ftruncate(fd, kept) != 0 || ::lseek(fd, kept, SEEK_SET) < 0)
      throw OutputError("cannot write " + path + ": " + std::strerror(errno));
    size = kept;
    if (kept == 0)
      append(header);
  }

  StatisticsFile::~StatisticsFile()
  {
    if (fd >= 0)
      ::close(fd);
  }

  void
  StatisticsFile::append(const std::string &text)
  {
    std::size_t done = 0;
    while (done < text.size())
      {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR)
          continue;
        if (n < 0)
          {
            const int error = errno;
            // Cut a partly written row off again.
            if (::ftruncate(fd, size) == 0)
              ::lseek(fd, size, SEEK_SET);
            throw OutputError("cannot write " + path + ": " +
                              std::strerror(error));
          }
        done += static_cast<std::size_t>(n);
      }
    size += text.size();
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
    std::ostringstream out;
    out << std::setprecision(16) << step << ',' << time << ',' << dt << ','
        << s.n_particles << ',' << s.mass;
    for (unsigned int d = 0; d < dim; ++d)
      out << ',' << s.momentum[d];
    out << ',' << s.kinetic_energy << ',' << s.strain_energy << ','
        << s.gravitational_energy;
    if (dissipated_work)
      out << ',' << s.dissipated_work;
    out << ',' << s.total_energy() << ',' << external_work << ','
        << a.energy_drift << ',' << a.momentum_drift << ',' << a.mass_loss
        << ',' << a.min_J << ',' << a.max_cfl << ',' << n_lost_particles << ','
        << wall_time << ',' << s.particles_per_rank_min << ','
        << s.particles_per_rank_max << ',' << s.particles_per_rank_mean;
    if (errors)
      out << ',' << s.error_L2 << ',' << s.error_max;
    for (const double value : s.effect_values)
      out << ',' << value;
    out << '\n';
    append(out.str());
  }
} // namespace dealmpm
