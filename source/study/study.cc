#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/parameter_file.h>
#include <dealmpm/base/scene_reader.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/study/child_process.h>
#include <dealmpm/study/study.h>
#include <dealmpm/transfer/kernel.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include "study_plan.h"

namespace dealmpm
{
  namespace
  {
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

    /** The study's own settings, then those every run needs: the CFL time
     * step (the runs vary its number), no progress lines, particle output
     * only when asked (it would count in the wall time). */
    std::vector<std::string>
    common_settings(const SceneReader &reader)
    {
      std::vector<std::string> common = list(reader.get("Settings"), ';');
      common.push_back("Time/Time step method=CFL");
      common.push_back("Output/Progress interval=0");
      common.push_back(std::string("Output/Write particles=") +
                       (reader.get_bool("Write particles") ? "true" : "false"));
      return common;
    }

    /** The base scene's cell size with the common settings. The base scene
     * must run with them: checked here, once, rather than in every run. */
    double
    checked_cell_size(const SceneReader &reader,
                      const StudyPlan   &plan,
                      const SceneShape  &shape)
    {
      try
        {
          return shape.dim == 2 ?
                   base_cell_size<2>(plan.base_scene, plan.common, shape) :
                   base_cell_size<3>(plan.base_scene, plan.common, shape);
        }
      catch (const InputError &e)
        {
          reader.fail("Settings",
                      std::string("settings the base scene accepts (") +
                        e.what() + ")");
        }
    }

    /** Every combination of the axes, numbered from 1, each with its
     * folder; @p h the base grid's cell size (0: not known). */
    std::vector<StudyRun>
    make_runs(const SceneReader &reader,
              const double       h,
              const std::string &folder)
    {
      std::vector<StudyRun> runs;
      for (const auto &adaptivity : list(reader.get("Adaptivity")))
        for (const auto &formulation : list(reader.get("Formulations")))
          for (const auto &kernel : list(reader.get("Shape functions")))
            for (const auto &scheme : list(reader.get("Stress updates")))
              for (const auto &velocity : list(reader.get("Velocity updates")))
                for (const auto &ppc : list(reader.get("Particles per cell")))
                  for (const auto &cfl : list(reader.get("CFL numbers")))
                    for (const auto &level : list(reader.get("Refinements")))
                      {
                        StudyRun r;
                        r.index              = runs.size() + 1;
                        r.formulation        = formulation;
                        r.adaptive           = adaptivity == "on";
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
      return runs;
    }

    /** Reads the study file into @p plan (throws InputError); @p
     * jobs_option, when not 0, overrides its number of jobs. */
    void
    read_study(const std::string &study_file,
               const unsigned int jobs_option,
               StudyPlan         &plan)
    {
      ParameterHandler prm;
      declare_study_parameters(prm);
      parse_parameter_file(prm, study_file, false);
      SceneReader  reader(prm, study_file);
      SectionScope study(reader, "Study");
      if (reader.get("Base scene").empty())
        reader.fail("Base scene", "the scene file every run starts from");
      plan.base_scene = reader.get_file("Base scene", "a readable scene file");
      plan.folder     = reader.get("Output directory");
      plan.jobs = jobs_option > 0 ? jobs_option : reader.get_integer("Jobs");
      plan.time_limit        = reader.get_nonnegative("Time limit per run");
      plan.common            = common_settings(reader);
      const SceneShape shape = read_scene_shape(plan.base_scene, plan.common);
      plan.n_bodies          = shape.n_bodies;
      plan.runs =
        make_runs(reader, checked_cell_size(reader, plan, shape), plan.folder);
    }

    /** The study read and its folder made; false (after saying why) when
     * the study file is wrong. */
    bool
    prepare_study(const std::string &study_file,
                  const unsigned int jobs_option,
                  StudyPlan         &plan)
    {
      try
        {
          read_study(study_file, jobs_option, plan);
          std::filesystem::create_directories(plan.folder + "/runs");
          return true;
        }
      catch (const InputError &e)
        {
          std::cerr << "dealmpm: error: " << e.what() << std::endl;
        }
      catch (const std::filesystem::filesystem_error &e)
        {
          std::cerr << "dealmpm: error: " << study_file
                    << ": entry 'Study/Output directory' = '" << plan.folder
                    << "': expected a folder that can be created (" << e.what()
                    << ")" << std::endl;
        }
      return false;
    }

    /** The plots, by @p plot_script (python3 with matplotlib); a warning
     * rather than an error without them: the tables are what matters. */
    void
    draw_plots(const std::string &plot_script, const std::string &folder)
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
  } // namespace

  void
  declare_study_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Study");
    prm.declare_entry("Base scene",
                      "",
                      Patterns::FileName(),
                      "The scene every run starts from (relative to the "
                      "study file): best one with an exact solution (the "
                      "manufactured solutions, the generalized vortex), so "
                      "that the runs have error norms.");
    prm.declare_entry("Output directory",
                      "study",
                      Patterns::DirectoryName(),
                      "Where study.csv, study.md, the plots and runs/NNN "
                      "(each run's statistics.csv, stdout and stderr) go.");
    prm.declare_entry("Refinements",
                      "0",
                      Patterns::List(Patterns::Integer(0, 12)),
                      "Axis: values of the scene's 'Grid/Global refinements'; "
                      "each halves the cell size.");
    prm.declare_entry("Formulations",
                      "updated Lagrangian",
                      Patterns::List(
                        Patterns::Selection(formulation_pattern())),
                      "Axis: 'MPM/Formulation'.");
    prm.declare_entry(
      "Adaptivity",
      "off",
      Patterns::List(Patterns::Selection("off|on")),
      "Axis: 'on' adapts the grid to the particles ('Adaptivity/Criteria = "
      "particles'): cells with particles (and one cell around them) one "
      "level finer than the run's refinement, the others at it; compare "
      "with the uniform grid one refinement finer.");
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

  int
  run_study(const std::string &study_file,
            const unsigned int jobs_option,
            const std::string &program,
            const std::string &plot_script)
  {
    StudyPlan plan;
    if (!prepare_study(study_file, jobs_option, plan))
      return 2;
    std::cout << "dealmpm: study of " << plan.base_scene << ": "
              << plan.runs.size() << " runs, " << plan.jobs << " at a time, in "
              << plan.folder << "/" << std::endl;
    run_all(plan, program);
    write_study_tables(plan.runs, plan.folder, study_file);
    std::cout << "dealmpm: study written to " << plan.folder
              << "/study.csv and study.md" << std::endl;
    if (!plot_script.empty())
      draw_plots(plot_script, plan.folder);
    return 0;
  }
} // namespace dealmpm
