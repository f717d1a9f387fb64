#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/run_messages.h>

#include <iomanip>
#include <sstream>

namespace dealmpm
{
  template <int dim>
  std::string
  format_point(const Point<dim> &x)
  {
    std::ostringstream s;
    s << std::setprecision(6) << '(';
    for (unsigned int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << x[d];
    s << ')';
    return s.str();
  }

  std::string
  step_and_time(const unsigned int step, const double time)
  {
    std::ostringstream text;
    text << std::setprecision(3) << "step " << step << " (t = " << time << ")";
    return text.str();
  }

  std::string
  short_number(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(3) << x;
    return s.str();
  }

  std::string
  first_message(const std::string &local, const MPI_Comm comm)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int root =
      Utilities::MPI::min(local.empty() ? n_ranks : rank, comm);
    if (root == n_ranks)
      return "";
    return Utilities::MPI::broadcast(comm, local, root);
  }

  template <int dim>
  void
  stop_on_particle(const bool                  failed_here,
                   const types::particle_index particle,
                   const Point<dim>           &location,
                   const std::string          &reason,
                   const unsigned int          step,
                   const double                time,
                   const MPI_Comm              comm)
  {
    const std::string failure =
      first_message(failed_here ?
                      "particle " + std::to_string(particle) + " at " +
                        format_point(location) + ": " + reason :
                      "",
                    comm);
    std::ostringstream message;
    message << "step " << step << " (t = " << time << "): " << failure;
    throw RunError(message.str());
  }

#define DEALMPM_INSTANTIATE(dim)                               \
  template std::string format_point(const Point<dim> &);       \
  template void        stop_on_particle(bool,                  \
                                        types::particle_index, \
                                        const Point<dim> &,    \
                                        const std::string &,   \
                                        unsigned int,          \
                                        double,                \
                                        MPI_Comm);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
