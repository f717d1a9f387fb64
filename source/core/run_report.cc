#include <deal.II/base/array_view.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/base/run_messages.h>
#include <dealmpm/core/run_report.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <utility>

namespace dealmpm
{
  std::string
  SetupClock::report(const MPI_Comm comm) const
  {
    std::vector<double> seconds;
    for (const auto &stage : stages)
      seconds.push_back(stage.second);
    std::vector<double> slowest(seconds.size());
    Utilities::MPI::max(make_array_view(std::as_const(seconds)),
                        comm,
                        make_array_view(slowest));
    seconds      = slowest;
    double total = 0;
    for (const double t : seconds)
      total += t;
    std::ostringstream line;
    line << std::fixed << std::setprecision(total < 10 ? 2 : 1)
         << "set-up took " << total << " s (slowest rank per stage):";
    for (unsigned int i = 0; i < stages.size(); ++i)
      line << (i == 0 ? " " : ", ") << stages[i].first << " " << seconds[i]
           << " s";
    return line.str();
  }

  namespace
  {
    /** What an output cost: the timer's "output" section per call, on the
     * slowest rank. */
    void
    print_output_time(ConditionalOStream &pcout,
                      const TimerOutput  &timer,
                      const MPI_Comm      comm)
    {
      const auto calls = timer.get_summary_data(TimerOutput::n_calls);
      const auto found = calls.find("output");
      if (found == calls.end() || found->second == 0)
        return;
      const double seconds = Utilities::MPI::max(
        timer.get_summary_data(TimerOutput::total_wall_time).at("output"),
        comm);
      pcout << "dealmpm: " << found->second << " output(s), "
            << std::setprecision(3) << seconds / found->second
            << " s each (slowest rank)" << std::endl;
    }
  } // namespace

  void
  print_run_summary(ConditionalOStream      &pcout,
                    TimerOutput             &timer,
                    const RunState          &loop,
                    const unsigned long long n_active_cells,
                    const MPI_Comm           comm)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    if (n_ranks == 1)
      timer.print_summary();
    else
      timer.print_wall_time_statistics(comm);
    pcout << "dealmpm: " << loop.accuracy.report() << std::endl;
    print_output_time(pcout, timer, comm);
    const double rate =
      loop.stepping_time > 0 ? loop.particle_steps / loop.stepping_time : 0;
    pcout << "dealmpm: " << loop.step << " steps to t = " << loop.time << ", "
          << std::setprecision(4) << rate / 1e6 << " M particle-steps/s on "
          << n_ranks << " rank(s) (" << rate / 1e6 / n_ranks << " M per core)";
    Utilities::System::MemoryStats used;
    Utilities::System::get_memory_stats(used);
    pcout << ", peak memory " << used.VmHWM / 1024 << " MB on rank 0";
    if (loop.repartitions > 0)
      pcout << ", " << static_cast<long long>(loop.repartitions)
            << " repartition(s) for load balance";
    if (loop.adaptations > 0)
      pcout << ", " << static_cast<long long>(loop.adaptations)
            << " grid adaptation(s) (" << n_active_cells << " cells now)";
    if (loop.split_particles > 0)
      pcout << ", " << static_cast<long long>(loop.split_particles)
            << " particle(s) split";
    if (loop.merged_particles > 0)
      pcout << ", " << static_cast<long long>(loop.merged_particles)
            << " particle(s) merged away";
    if (loop.held_particles > 0)
      pcout << ", " << static_cast<long long>(loop.held_particles)
            << " time(s) a particle was put back on a wall";
    if (loop.lost_particles > 0)
      pcout << ", " << static_cast<long long>(loop.lost_particles)
            << " particle(s) left the grid ("
            << short_number(100 * loop.lost_mass /
                            std::max(loop.accuracy.initial_mass(), 1e-300))
            << " % of the mass)";
    pcout << std::endl;
  }
} // namespace dealmpm
