#include <deal.II/base/mpi.h>

#include <dealmpm/base/warnings.h>

#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace dealmpm
{
  namespace
  {
    /** How often each kind was warned of, in the order of the first. */
    struct WarningCounts
    {
      std::map<std::string, unsigned int> count;
      std::vector<std::string>            order;
    };

    WarningCounts &
    counts()
    {
      static WarningCounts c;
      return c;
    }

    bool
    prints()
    {
      int initialized = 0;
      MPI_Initialized(&initialized);
      return !initialized ||
             dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    }
  } // namespace

  void
  warn(const std::string &kind, const std::string &text)
  {
    WarningCounts &c = counts();
    if (c.count[kind]++ > 0)
      return;
    c.order.push_back(kind);
    // One write of the whole line: mpirun forwards a rank's stderr and
    // stdout through separate pipes, and a line written in pieces came out
    // with the stdout line after it in the middle (checkpoint_kill.sh).
    if (prints())
      std::cerr << "dealmpm: warning: " + text + "\n" << std::flush;
  }

  void
  summarize_warnings()
  {
    WarningCounts &c = counts();
    for (const std::string &kind : c.order)
      if (c.count[kind] > 1 && prints())
        std::cerr << "dealmpm: warning: " + std::to_string(c.count[kind] - 1) +
                       " more '" + kind + "' warning" +
                       (c.count[kind] > 2 ? "s" : "") +
                       " after the first (above)\n"
                  << std::flush;
    c = WarningCounts();
  }
} // namespace dealmpm
