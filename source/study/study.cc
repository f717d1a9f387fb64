#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/parameter_file.h>
#include <dealmpm/base/scene_reader.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/study/child_process.h>
#include <dealmpm/study/pareto.h>
#include <dealmpm/study/study.h>
#include <dealmpm/transfer/kernel.h>

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

namespace dealmpm
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    std::vector<std::string>
    list(const std::string &value, const char separator = ',')
    {
      std::vector<std::string> items;
      for (const auto &item : Utilities::split_string_list(value, separator))
        if (!item.empty())
          items.push_back(item);
      return items;
    }

    /** Smallest cell size of the base scene's rectangle grid with the
     * study's settings (0 for mesh files: the study then reports h
     * relative to the base grid). */
    template <int dim>
    double
    base_cell_size(const std::string              &scene,
                   const std::vector<std::string> &settings,
                   const SceneShape               &shape)
    {
      ParameterHandler prm;
      Simulation<dim>::declare_parameters(prm, shape);
      parse_parameter_file(prm, scene, false);
      apply_overrides(prm, settings);
      SceneReader  reader(prm, scene);
      SectionScope grid(reader, "Grid");
      if (reader.get("Type") != "rectangle")
        return 0;
      const Point<dim> lower = reader.get_point<dim>("Lower corner");
      const Point<dim> upper = reader.get_point<dim>("Upper corner");
      const auto       cells = list(reader.get("Cells"));
      double           h     = std::numeric_limits<double>::max();
      for (unsigned int d = 0; d < dim && d < cells.size(); ++d)
        h = std::min(h, (upper[d] - lower[d]) / std::stod(cells[d]));
      return h / std::pow(2., reader.get_integer("Global refinements"));
    }

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

    /** The line of a run's stderr that says why it ended, without the
     * program's prefix. */
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

    std::string
    describe(const StudyRun &r)
    {
      std::ostringstream s;
      s << r.shape_function << ", " << r.stress_update << ", "
        << r.velocity_update << ", " << r.particles_per_cell
        << " ppc, refinement " << r.refinement << ", CFL " << r.cfl_number;
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

    std::string
    csv_text(std::string text)
    {
      std::string quoted = "\"";
      for (const char c : text)
        quoted += (c == '"' ? std::string("\"\"") : std::string(1, c));
      return quoted + "\"";
    }

    /** A number for the tables: empty when not known. */
    std::string
    number(const double x, const int precision = 4)
    {
      if (!std::isfinite(x))
        return "";
      std::ostringstream s;
      s << std::setprecision(precision) << x;
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
  } // namespace

  void
  declare_study_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Study");
    prm.declare_entry("Base scene",
                      "",
                      Patterns::Anything(),
                      "The scene every run starts from (relative to the "
                      "study file): best one with an exact solution (the "
                      "manufactured solutions, the generalized vortex), so "
                      "that the runs have error norms.");
    prm.declare_entry("Output directory",
                      "study",
                      Patterns::Anything(),
                      "Where study.csv, study.md, the plots and runs/NNN "
                      "(each run's statistics.csv, stdout and stderr) go.");
    prm.declare_entry("Refinements",
                      "0",
                      Patterns::List(Patterns::Integer(0, 12)),
                      "Axis: values of the scene's 'Grid/Global refinements'; "
                      "each halves the cell size.");
    prm.declare_entry("Particles per cell",
                      "2",
                      Patterns::List(Patterns::Integer(1, 20)),
                      "Axis: particles per cell and direction, every body.");
    prm.declare_entry("Shape functions",
                      "linear",
                      Patterns::List(
                        Patterns::Selection(shape_function_pattern())),
                      "Axis: 'MPM/Shape function'.");
    prm.declare_entry("Stress updates",
                      "USL",
                      Patterns::List(Patterns::Selection("USL|USF|MUSL")),
                      "Axis: 'MPM/Stress update'.");
    prm.declare_entry("Velocity updates",
                      "FLIP",
                      Patterns::List(
                        Patterns::Selection("FLIP|PIC|blend|APIC")),
                      "Axis: 'MPM/Velocity update'.");
    prm.declare_entry("CFL numbers",
                      "0.2",
                      Patterns::List(Patterns::Double(0, 1)),
                      "Axis: 'Time/CFL number' (the runs use the CFL time "
                      "step).");
    prm.declare_entry("Settings",
                      "",
                      Patterns::Anything(),
                      "Entries set in every run, 'Section/Entry=value' "
                      "separated by ';', e.g. 'Time/End time=0.02'.");
    prm.declare_entry("Jobs",
                      "1",
                      Patterns::Integer(1, 256),
                      "Runs at once (each one process on one core; more "
                      "than the cores distorts the wall times).");
    prm.declare_entry("Time limit per run",
                      "0",
                      Patterns::Double(0),
                      "Seconds after which a run is stopped and recorded as "
                      "such (0: no limit).");
    prm.declare_entry("Write particles",
                      "false",
                      Patterns::Bool(),
                      "Particle output of every run (off: it would count "
                      "in the wall time).");
    prm.leave_subsection();
  }

  void
  write_study_tables(std::vector<StudyRun> &runs,
                     const std::string     &folder,
                     const std::string     &title)
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

    std::ofstream csv(folder + "/study.csv");
    csv << "run,status,shape_function,stress_update,velocity_update,"
           "particles_per_cell,refinement,h,cfl_number,error_L2,error_max,"
           "wall_time,steps,particles,particle_steps_per_second,"
           "peak_memory_MB,energy_drift,momentum_drift,min_J,max_cfl,"
           "pareto_optimal,reason\n";
    csv << std::setprecision(8);
    for (const StudyRun &r : runs)
      csv << r.index << ',' << r.status << ',' << r.shape_function << ','
          << r.stress_update << ',' << r.velocity_update << ','
          << r.particles_per_cell << ',' << r.refinement << ',' << r.h << ','
          << r.cfl_number << ',' << number(r.error_L2, 8) << ','
          << number(r.error_max, 8) << ',' << number(r.wall_time, 6) << ','
          << number(r.steps) << ',' << number(r.particles, 10) << ','
          << number(r.particle_steps_per_second, 6) << ','
          << number(r.peak_memory, 6) << ',' << number(r.energy_drift, 6) << ','
          << number(r.momentum_drift, 6) << ',' << number(r.min_J, 6) << ','
          << number(r.max_cfl, 6) << ',' << (r.pareto_optimal ? 1 : 0) << ','
          << csv_text(r.reason) << '\n';

    // study.md: finished runs by error, then the ones that stopped or failed.
    std::vector<const StudyRun *> order;
    for (const StudyRun &r : runs)
      order.push_back(&r);
    std::stable_sort(order.begin(),
                     order.end(),
                     [](const StudyRun *a, const StudyRun *b) {
                       const auto key = [](const StudyRun *r) {
                         return r->status == "ok" &&
                                    std::isfinite(r->error_L2) ?
                                  r->error_L2 :
                                  std::numeric_limits<double>::infinity();
                       };
                       return key(a) < key(b);
                     });
    std::ofstream md(folder + "/study.md");
    md << "# Study: " << title << "\n\n"
       << "Runs sorted by the L2 displacement error; **Pareto** marks the "
          "runs that no other run beats in both error and wall time (the "
          "cheapest way to each accuracy). Wall time is the whole process "
          "on one core.\n\n"
       << "| run | shape function | stress | velocity | ppc | h | CFL | "
          "error L2 | error max | wall s | M p-steps/s | MB | energy drift "
          "| Pareto |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const StudyRun *r : order)
      {
        md << "| " << r->index << " | " << r->shape_function << " | "
           << r->stress_update << " | " << r->velocity_update << " | "
           << r->particles_per_cell << " | " << number(r->h, 3) << " | "
           << r->cfl_number << " | ";
        if (r->status == "ok")
          md << number(r->error_L2, 3) << " | " << number(r->error_max, 3)
             << " | " << number(r->wall_time, 3) << " | "
             << number(r->particle_steps_per_second / 1e6, 3) << " | "
             << number(r->peak_memory, 3) << " | " << number(r->energy_drift, 2)
             << " | " << (r->pareto_optimal ? "**Pareto**" : "") << " |\n";
        else
          md << r->status << ": " << r->reason << " | | | | | | |\n";
      }
  }

  int
  run_study(const std::string &study_file,
            const unsigned int jobs_option,
            const std::string &program,
            const std::string &plot_script)
  {
    std::vector<StudyRun>    runs;
    std::string              folder, base_scene;
    unsigned int             jobs       = 1;
    double                   time_limit = 0;
    unsigned int             n_bodies   = 1;
    std::vector<std::string> common;
    try
      {
        ParameterHandler prm;
        declare_study_parameters(prm);
        parse_parameter_file(prm, study_file, false);
        SceneReader  reader(prm, study_file);
        SectionScope study(reader, "Study");
        if (reader.get("Base scene").empty())
          reader.fail("Base scene", "the scene file every run starts from");
        base_scene = reader.get_file("Base scene", "a readable scene file");
        folder     = reader.get("Output directory");
        jobs       = jobs_option > 0 ? jobs_option : reader.get_integer("Jobs");
        time_limit = reader.get_nonnegative("Time limit per run");
        for (const auto &item : list(reader.get("Settings"), ';'))
          common.push_back(item);
        common.push_back("Time/Time step method=CFL");
        common.push_back("Output/Progress interval=0");
        common.push_back(
          std::string("Output/Write particles=") +
          (reader.get_bool("Write particles") ? "true" : "false"));

        // The base scene must run with the settings: check it here, once,
        // rather than in every run.
        const SceneShape shape = read_scene_shape(base_scene, common);
        n_bodies               = shape.n_bodies;
        double h               = 0;
        try
          {
            h = shape.dim == 2 ? base_cell_size<2>(base_scene, common, shape) :
                                 base_cell_size<3>(base_scene, common, shape);
          }
        catch (const InputError &e)
          {
            reader.fail("Settings",
                        std::string("settings the base scene accepts (") +
                          e.what() + ")");
          }
        for (const auto &kernel : list(reader.get("Shape functions")))
          for (const auto &scheme : list(reader.get("Stress updates")))
            for (const auto &velocity : list(reader.get("Velocity updates")))
              for (const auto &ppc : list(reader.get("Particles per cell")))
                for (const auto &cfl : list(reader.get("CFL numbers")))
                  for (const auto &level : list(reader.get("Refinements")))
                    {
                      StudyRun r;
                      r.index              = runs.size() + 1;
                      r.shape_function     = kernel;
                      r.stress_update      = scheme;
                      r.velocity_update    = velocity;
                      r.particles_per_cell = std::stoi(ppc);
                      r.cfl_number         = std::stod(cfl);
                      r.refinement         = std::stoi(level);
                      r.h = (h > 0 ? h : 1.) / std::pow(2., r.refinement);
                      std::ostringstream name;
                      name << folder << "/runs/" << std::setw(3)
                           << std::setfill('0') << r.index;
                      r.folder = name.str();
                      runs.push_back(r);
                    }
        std::filesystem::create_directories(folder + "/runs");
      }
    catch (const InputError &e)
      {
        std::cerr << "dealmpm: error: " << e.what() << std::endl;
        return 2;
      }
    catch (const std::filesystem::filesystem_error &e)
      {
        std::cerr << "dealmpm: error: " << study_file
                  << ": entry 'Study/Output directory' = '" << folder
                  << "': expected a folder that can be created (" << e.what()
                  << ")" << std::endl;
        return 2;
      }

    std::cout << "dealmpm: study of " << base_scene << ": " << runs.size()
              << " runs, " << jobs << " at a time, in " << folder << "/"
              << std::endl;
    using Clock      = std::chrono::steady_clock;
    const auto start = Clock::now();
    const auto since = [](const Clock::time_point t) {
      return std::chrono::duration<double>(Clock::now() - t).count();
    };
    std::map<pid_t, std::pair<unsigned int, Clock::time_point>> running;
    std::set<pid_t>                                             timed_out;
    unsigned int next = 0, done = 0;
    while (done < runs.size())
      {
        while (running.size() < jobs && next < runs.size())
          {
            StudyRun &r = runs[next];
            std::filesystem::create_directories(r.folder);
            std::vector<std::string> arguments = {base_scene};
            std::vector<std::string> settings  = common;
            settings.push_back("Output/Directory=" + r.folder);
            settings.push_back("Grid/Global refinements=" +
                               std::to_string(r.refinement));
            settings.push_back("MPM/Shape function=" + r.shape_function);
            settings.push_back("MPM/Stress update=" + r.stress_update);
            settings.push_back("MPM/Velocity update=" + r.velocity_update);
            settings.push_back("Time/CFL number=" + number(r.cfl_number, 12));
            for (unsigned int b = 1; b <= n_bodies; ++b)
              settings.push_back(
                "Body " + std::to_string(b) +
                "/Particles per cell=" + std::to_string(r.particles_per_cell));
            for (const auto &s : settings)
              {
                arguments.push_back("-s");
                arguments.push_back(s);
              }
            const pid_t pid = start_child(program,
                                          arguments,
                                          r.folder + "/stdout.txt",
                                          r.folder + "/stderr.txt");
            running[pid]    = {next, Clock::now()};
            ++next;
          }
        // Wait until a run ends or the first one reaches the time limit.
        double wait = -1;
        if (time_limit > 0)
          for (const auto &[pid, run] : running)
            wait = std::max(0.,
                            std::min(wait < 0 ? time_limit : wait,
                                     time_limit - since(run.second)));
        ChildResult result;
        const pid_t pid = wait_for_child(result, wait);
        if (pid == 0)
          {
            for (const auto &[id, run] : running)
              if (since(run.second) >= time_limit && !timed_out.count(id))
                {
                  kill(id, SIGKILL);
                  timed_out.insert(id);
                }
            continue;
          }
        const auto it = running.find(pid);
        if (it == running.end())
          continue;
        StudyRun &r = runs[it->second.first];
        collect(r, result, since(it->second.second));
        if (timed_out.count(pid))
          {
            r.status = "stopped";
            r.reason = "exceeded the time limit of " + number(time_limit) +
                       " s ('Study/Time limit per run')";
          }
        running.erase(it);
        ++done;
        const double elapsed = since(start);
        std::cout << "dealmpm: study: " << done << " of " << runs.size()
                  << " done; run " << r.index << " (" << describe(r)
                  << "): " << r.status;
        if (r.status == "ok" && std::isfinite(r.error_L2))
          std::cout << ", error " << number(r.error_L2, 3);
        std::cout << ", " << number(r.wall_time, 3) << " s; elapsed "
                  << clock(elapsed) << ", ETA "
                  << clock(elapsed / done * (runs.size() - done)) << std::endl;
      }

    write_study_tables(runs, folder, study_file);
    std::cout << "dealmpm: study written to " << folder
              << "/study.csv and study.md" << std::endl;
    if (!plot_script.empty())
      {
        ChildResult result;
        result.exit_code = -1;
        try
          {
            start_child("/usr/bin/python3",
                        {plot_script, folder + "/study.csv", folder},
                        folder + "/plot_stdout.txt",
                        folder + "/plot_stderr.txt");
            wait_for_child(result);
          }
        catch (const std::exception &)
          {}
        if (result.exit_code == 0)
          std::cout << "dealmpm: plots in " << folder
                    << "/study.png, study.svg, convergence.png, "
                       "convergence.svg"
                    << std::endl;
        else
          std::cout << "dealmpm: warning: no plots (" << plot_script
                    << " failed: " << reason_in(folder + "/plot_stderr.txt")
                    << "); python3 with matplotlib "
                       "(Debian: python3-matplotlib) draws them"
                    << std::endl;
      }
    return 0;
  }
} // namespace dealmpm
