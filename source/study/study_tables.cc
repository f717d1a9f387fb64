#include <dealmpm/study/pareto.h>
#include <dealmpm/study/study.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>

#include "study_text.h"

namespace dealmpm
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    std::string
    csv_text(std::string text)
    {
      std::string quoted = "\"";
      for (const char c : text)
        quoted += (c == '"' ? std::string("\"\"") : std::string(1, c));
      return quoted + "\"";
    }

    /** Only finished runs compete: a stopped run's error says nothing. */
    void
    mark_pareto_optimal(std::vector<StudyRun> &runs)
    {
      std::vector<double> cost, error;
      for (const StudyRun &r : runs)
        {
          const bool usable = r.status == "ok";
          cost.push_back(usable ? r.wall_time : nan);
          error.push_back(usable ? r.error_L2 : nan);
        }
      const std::vector<bool> optimal = pareto_optimal(cost, error);
      for (unsigned int i = 0; i < runs.size(); ++i)
        runs[i].pareto_optimal = optimal[i];
    }

    void
    write_csv(const std::vector<StudyRun> &runs, const std::string &folder)
    {
      std::ofstream csv(folder + "/study.csv");
      csv << "run,status,formulation,shape_function,stress_update,"
             "velocity_update,"
             "particles_per_cell,refinement,h,cfl_number,error_L2,error_max,"
             "wall_time,steps,particles,particle_steps_per_second,"
             "peak_memory_MB,energy_drift,momentum_drift,min_J,max_cfl,"
             "pareto_optimal,reason,adaptivity\n";
      csv << std::setprecision(8);
      for (const StudyRun &r : runs)
        csv << r.index << ',' << r.status << ',' << r.formulation << ','
            << r.shape_function << ',' << r.stress_update << ','
            << r.velocity_update << ',' << r.particles_per_cell << ','
            << r.refinement << ',' << r.h << ',' << r.cfl_number << ','
            << number(r.error_L2, 8) << ',' << number(r.error_max, 8) << ','
            << number(r.wall_time, 6) << ',' << number(r.steps) << ','
            << number(r.particles, 10) << ','
            << number(r.particle_steps_per_second, 6) << ','
            << number(r.peak_memory, 6) << ',' << number(r.energy_drift, 6)
            << ',' << number(r.momentum_drift, 6) << ',' << number(r.min_J, 6)
            << ',' << number(r.max_cfl, 6) << ',' << (r.pareto_optimal ? 1 : 0)
            << ',' << csv_text(r.reason) << ',' << (r.adaptive ? "on" : "off")
            << '\n';
    }

    /** Finished runs by error, then the ones that stopped or failed: the
     * table is read from the top for the most accurate runs. */
    std::vector<const StudyRun *>
    by_error(const std::vector<StudyRun> &runs)
    {
      std::vector<const StudyRun *> order;
      for (const StudyRun &r : runs)
        order.push_back(&r);
      const auto key = [](const StudyRun *r) {
        return r->status == "ok" && std::isfinite(r->error_L2) ?
                 r->error_L2 :
                 std::numeric_limits<double>::infinity();
      };
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const StudyRun *a, const StudyRun *b) {
                         return key(a) < key(b);
                       });
      return order;
    }

    void
    write_markdown(const std::vector<StudyRun> &runs,
                   const std::string           &folder,
                   const std::string           &title)
    {
      std::ofstream md(folder + "/study.md");
      md << "# Study: " << title << "\n\n"
         << "Runs sorted by the L2 displacement error; **Pareto** marks the "
            "runs that no other run beats in both error and wall time (the "
            "cheapest way to each accuracy). Wall time is the whole process "
            "on one core.\n\n"
         << "| run | formulation | shape function | stress | velocity | ppc | "
            "h | CFL | error L2 | error max | wall s | M p-steps/s | MB | "
            "energy drift | Pareto |\n"
         << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
      for (const StudyRun *r : by_error(runs))
        {
          md << "| " << r->index << " | " << r->formulation
             << (r->adaptive ? ", adaptive" : "") << " | " << r->shape_function
             << " | " << r->stress_update << " | " << r->velocity_update
             << " | " << r->particles_per_cell << " | " << number(r->h, 3)
             << " | " << r->cfl_number << " | ";
          if (r->status == "ok")
            md << number(r->error_L2, 3) << " | " << number(r->error_max, 3)
               << " | " << number(r->wall_time, 3) << " | "
               << number(r->particle_steps_per_second / 1e6, 3) << " | "
               << number(r->peak_memory, 3) << " | "
               << number(r->energy_drift, 2) << " | "
               << (r->pareto_optimal ? "**Pareto**" : "") << " |\n";
          else
            md << r->status << ": " << r->reason << " | | | | | | |\n";
        }
    }
  } // namespace

  void
  write_study_tables(std::vector<StudyRun> &runs,
                     const std::string     &folder,
                     const std::string     &title)
  {
    mark_pareto_optimal(runs);
    write_csv(runs, folder);
    write_markdown(runs, folder, title);
  }
} // namespace dealmpm
