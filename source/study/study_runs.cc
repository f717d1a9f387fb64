#include <deal.II/base/utilities.h>

#include <dealmpm/study/child_process.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <signal.h>
#include <sstream>

#include "study_plan.h"
#include "study_text.h"

namespace dealmpm
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /** The last data row of a CSV file, by column name. */
    std::map<std::string, double>
    last_row(const std::string &file)
    {
      std::ifstream                 in(file);
      std::string                   header, line, last;
      std::map<std::string, double> row;
      if (!std::getline(in, header))
        return row;
      while (std::getline(in, line))
        if (!line.empty())
          last = line;
      const auto names  = Utilities::split_string_list(header, ',');
      const auto values = Utilities::split_string_list(last, ',');
      for (unsigned int i = 0; i < names.size() && i < values.size(); ++i)
        row[names[i]] = std::stod(values[i]);
      return row;
    }

    std::string
    describe(const StudyRun &r)
    {
      std::ostringstream s;
      if (r.formulation != "updated Lagrangian")
        s << r.formulation << ", ";
      s << r.shape_function << ", " << r.stress_update << ", "
        << r.velocity_update << ", " << r.particles_per_cell
        << " ppc, refinement " << r.refinement
        << (r.adaptive ? " (adaptive)" : "") << ", CFL " << r.cfl_number;
      return s.str();
    }

    std::string
    clock(const double seconds)
    {
      std::ostringstream s;
      const long         total = std::lround(seconds);
      s << total / 60 << ':' << std::setw(2) << std::setfill('0') << total % 60;
      return s.str();
    }

    void
    collect(StudyRun &run, const ChildResult &child, const double wall_time)
    {
      run.wall_time   = wall_time;
      run.peak_memory = child.peak_memory;
      if (child.exit_code == 0)
        run.status = "ok";
      else
        {
          run.status = child.exit_code == 3 ? "stopped" : "failed";
          run.reason = child.exit_code < 0 ?
                         "killed by signal " + std::to_string(child.signal) :
                         reason_in(run.folder + "/stderr.txt");
          if (run.reason.empty())
            run.reason = "exit code " + std::to_string(child.exit_code);
        }
      const auto row   = last_row(run.folder + "/statistics.csv");
      const auto value = [&](const std::string &name) {
        const auto it = row.find(name);
        return it == row.end() ? nan : it->second;
      };
      run.error_L2       = value("error_L2");
      run.error_max      = value("error_max");
      run.steps          = value("step");
      run.particles      = value("n_particles");
      run.energy_drift   = value("energy_drift");
      run.momentum_drift = value("momentum_drift");
      run.min_J          = value("min_J");
      run.max_cfl        = value("max_cfl");
      run.particle_steps_per_second =
        value("wall_time") > 0 ?
          run.particles * run.steps / value("wall_time") :
          nan;
    }

    /** The command line of one run: the base scene, the common settings,
     * then the run's own (its folder and its point on every axis). */
    std::vector<std::string>
    run_arguments(const StudyPlan &plan, const StudyRun &r)
    {
      std::vector<std::string> settings = plan.common;
      settings.push_back("Output/Directory=" + r.folder);
      settings.push_back("Grid/Global refinements=" +
                         std::to_string(r.refinement));
      settings.push_back("MPM/Formulation=" + r.formulation);
      settings.push_back("MPM/Shape function=" + r.shape_function);
      settings.push_back("MPM/Stress update=" + r.stress_update);
      settings.push_back("MPM/Velocity update=" + r.velocity_update);
      settings.push_back("Time/CFL number=" + number(r.cfl_number, 12));
      if (r.adaptive)
        {
          settings.push_back("Adaptivity/Criteria=particles");
          settings.push_back("Adaptivity/Minimum level=" +
                             std::to_string(r.refinement));
          settings.push_back("Adaptivity/Maximum level=" +
                             std::to_string(r.refinement + 1));
        }
      for (unsigned int b = 1; b <= plan.n_bodies; ++b)
        settings.push_back(
          "Body " + std::to_string(b) +
          "/Particles per cell=" + std::to_string(r.particles_per_cell));
      std::vector<std::string> arguments = {plan.base_scene};
      for (const auto &s : settings)
        {
          arguments.push_back("-s");
          arguments.push_back(s);
        }
      return arguments;
    }

    using Clock = std::chrono::steady_clock;

    double
    seconds_since(const Clock::time_point t)
    {
      return std::chrono::duration<double>(Clock::now() - t).count();
    }

    /** The runs under way, each a child process: which run and since when,
     * and those killed for exceeding the time limit. */
    struct Running
    {
      std::map<pid_t, std::pair<unsigned int, Clock::time_point>> runs;
      std::set<pid_t>                                             timed_out;

      /** Seconds until the first run reaches @p time_limit (negative: no
       * limit, wait for a run to end). */
      double
      time_to_wait(const double time_limit) const
      {
        double wait = -1;
        if (time_limit > 0)
          for (const auto &[pid, run] : runs)
            wait = std::max(0.,
                            std::min(wait < 0 ? time_limit : wait,
                                     time_limit - seconds_since(run.second)));
        return wait;
      }

      /** Kill (once) the runs that have reached the limit; they are
       * collected as they end. */
      void
      stop_overdue(const double time_limit)
      {
        for (const auto &[pid, run] : runs)
          if (seconds_since(run.second) >= time_limit && !timed_out.count(pid))
            {
              kill(pid, SIGKILL);
              timed_out.insert(pid);
            }
      }
    };

    void
    start_run(const StudyPlan   &plan,
              const unsigned int index,
              const std::string &program,
              Running           &running)
    {
      const StudyRun &r = plan.runs[index];
      std::filesystem::create_directories(r.folder);
      const pid_t pid   = start_child(program,
                                    run_arguments(plan, r),
                                    r.folder + "/stdout.txt",
                                    r.folder + "/stderr.txt");
      running.runs[pid] = {index, Clock::now()};
    }

    /** Records how the run of process @p pid went; nullptr if that was not
     * one of the runs. */
    StudyRun *
    finish_run(StudyPlan         &plan,
               const pid_t        pid,
               const ChildResult &result,
               Running           &running)
    {
      const auto it = running.runs.find(pid);
      if (it == running.runs.end())
        return nullptr;
      StudyRun *finished = &plan.runs[it->second.first];
      collect(*finished, result, seconds_since(it->second.second));
      if (running.timed_out.count(pid))
        {
          finished->status = "stopped";
          finished->reason = "exceeded the time limit of " +
                             number(plan.time_limit) +
                             " s ('Study/Time limit per run')";
        }
      running.runs.erase(it);
      return finished;
    }

    /** One line per finished run, with an estimate of the time left. */
    void
    report_progress(const StudyRun    &r,
                    const unsigned int done,
                    const std::size_t  n_runs,
                    const double       elapsed)
    {
      std::cout << "dealmpm: study: " << done << " of " << n_runs
                << " done; run " << r.index << " (" << describe(r)
                << "): " << r.status;
      if (r.status == "ok" && std::isfinite(r.error_L2))
        std::cout << ", error " << number(r.error_L2, 3);
      std::cout << ", " << number(r.wall_time, 3) << " s; elapsed "
                << clock(elapsed) << ", ETA "
                << clock(elapsed / done * (n_runs - done)) << std::endl;
    }

  } // namespace

  std::string
  reason_in(const std::string &file)
  {
    std::ifstream in(file);
    std::string   line, reason;
    while (std::getline(in, line))
      if (!line.empty())
        reason = line;
    for (const std::string prefix :
         {"dealmpm: stopped: ", "dealmpm: error: ", "dealmpm: "})
      if (reason.rfind(prefix, 0) == 0)
        return reason.substr(prefix.size());
    return reason;
  }

  void
  run_all(StudyPlan &plan, const std::string &program)
  {
    const auto   start = Clock::now();
    Running      running;
    unsigned int next = 0, done = 0;
    while (done < plan.runs.size())
      {
        for (; running.runs.size() < plan.jobs && next < plan.runs.size();
             ++next)
          start_run(plan, next, program, running);
        // Wait until a run ends or the first one reaches the time limit.
        ChildResult result;
        const pid_t pid =
          wait_for_child(result, running.time_to_wait(plan.time_limit));
        if (pid == 0)
          {
            running.stop_overdue(plan.time_limit);
            continue;
          }
        const StudyRun *finished = finish_run(plan, pid, result, running);
        if (finished == nullptr)
          continue;
        ++done;
        report_progress(*finished,
                        done,
                        plan.runs.size(),
                        seconds_since(start));
      }
  }
} // namespace dealmpm
