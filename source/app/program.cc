#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/app/program.h>
#include <dealmpm/base/errors.h>
#include <dealmpm/base/parameter_file.h>
#include <dealmpm/base/warnings.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/study/study.h>

#include <algorithm>
#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>

#include "run_log.h"
#include "unused_sections.h"

namespace dealmpm
{
  namespace
  {
    const char *usage =
      "usage: dealmpm [options] scene.prm\n"
      "       mpirun -np N dealmpm [options] scene.prm\n"
      "\n"
      "Runs an explicit Material Point Method scene described by a deal.II\n"
      "parameter file. Output (ParaView .pvd/.pvtu/.vtu, statistics.csv) goes\n"
      "to the folder 'Output/Directory'.\n"
      "\n"
      "options:\n"
      "  -h, --help              this text\n"
      "  --print-parameters      every entry with its default and documentation\n"
      "                          (for the scene's Dimension and numbers of bodies\n"
      "                          and materials when a scene is given)\n"
      "  -s 'Section/Entry=value'  override an entry (repeatable), e.g.\n"
      "                          -s 'Grid/Cells=40, 40' -s 'Time/End time=0.5'\n"
      "  --resume [folder]       continue the run saved in the scene's\n"
      "                          'Checkpoint/Directory' (or in folder: a\n"
      "                          folder of checkpoints or one of them),\n"
      "                          on any number of ranks; the output goes on\n"
      "                          where the saved run's stopped\n"
      "  --study study.prm [--jobs N]\n"
      "                          run every combination of a study's axes on\n"
      "                          its base scene (N at a time; without\n"
      "                          mpirun: it starts the runs itself); writes\n"
      "                          study.csv, study.md and plots (see\n"
      "                          benchmarks/accuracy-cost/README.md)\n"
      "\n"
      "SIGTERM or SIGINT (Ctrl-C) end a run after its current step with a\n"
      "last output and a checkpoint; a second one ends it at once.\n"
      "\n"
      "exit codes: 0 done, 1 bad command line, 2 bad scene input,\n"
      "            3 run stopped (instability, particles lost), 4 internal error,\n"
      "            5 output could not be written (the file and the reason are\n"
      "              printed; the series on disk stay consistent),\n"
      "            130 / 143 stopped by SIGINT / SIGTERM (output complete)\n";

    /** Returns the signal that stopped the run, or 0. */
    template <int dim>
    int
    run_scene(const std::string                &file,
              const std::vector<std::string>   &overrides,
              const SceneShape                 &shape,
              const std::optional<std::string> &resume)
    {
      ParameterHandler prm;
      Simulation<dim>::declare_parameters(prm, shape);
      parse_parameter_file(prm, file, false);
      apply_overrides(prm, overrides);
      // Let the simulation (and its MPI-aware timer) die before an error
      // leaves this function.
      std::exception_ptr error;
      int                signal = 0;
      {
        Simulation<dim> simulation(
          prm, file, shape, MPI_COMM_WORLD, overrides, resume);
        // After the scene was read whole: bad input gets its one line alone,
        // and an output folder only a scene that runs.
        start_run_files(prm,
                        prm.get({"Output"}, "Directory"),
                        file,
                        overrides,
                        resume.has_value());
        warn_unused_sections<dim>(prm, file, overrides, shape.n_materials);
        try
          {
            simulation.run();
            signal = simulation.stop_signal_received();
          }
        catch (...)
          {
            error = std::current_exception();
          }
      }
      summarize_warnings();
      if (error)
        std::rethrow_exception(error);
      return signal;
    }

    /** Where the library was loaded from (dladdr on an object of its own). */
    const char library_anchor = 0;

    /**
     * The study's plot script: an installed library finds the installed copy
     * at DEALMPM_PLOT_SCRIPT_FROM_LIBRARY, relative to its own folder
     * (lib/ -> share/dealmpm/, wherever the prefix was moved); a library in
     * its build tree uses the source tree's DEALMPM_PLOT_SCRIPT. Empty when
     * there is neither (no plots).
     */
    std::string
    plot_script()
    {
      Dl_info info;
      if (dladdr(&library_anchor, &info) != 0 && info.dli_fname != nullptr)
        {
          const std::filesystem::path installed =
            std::filesystem::path(info.dli_fname).parent_path() /
            DEALMPM_PLOT_SCRIPT_FROM_LIBRARY;
          std::error_code error;
          if (std::filesystem::is_regular_file(installed, error))
            return std::filesystem::canonical(installed, error).string();
        }
      const std::string source_tree = DEALMPM_PLOT_SCRIPT;
      return std::filesystem::exists(source_tree) ? source_tree : "";
    }

    int
    run_study_command(int argc, char **argv)
    {
      std::string  file;
      unsigned int jobs = 0;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--study" && i + 1 < argc && file.empty())
            file = argv[++i];
          else if (arg == "--jobs" && i + 1 < argc &&
                   std::atoi(argv[i + 1]) > 0)
            jobs = std::atoi(argv[++i]);
          else
            {
              std::cerr << "dealmpm: unknown or incomplete option '" << arg
                        << "' with --study\n\n"
                        << usage;
              return 1;
            }
        }
      if (file.empty())
        {
          std::cerr << "dealmpm: --study needs a study file\n\n" << usage;
          return 1;
        }
      return run_study(file,
                       jobs,
                       std::filesystem::read_symlink("/proc/self/exe"),
                       plot_script());
    }

    /** What a command line without --study asks for. */
    struct CommandLine
    {
      std::string              file;
      std::vector<std::string> overrides;
      bool                     print_parameters = false;
      /** --resume: the folder given, or "" (the scene's). */
      std::optional<std::string> resume;
    };

    /**
     * Reads the options into @p command. Returns the exit code when the
     * program ends here: 0 after the help, 1 after the usage for a wrong
     * command line; -1 to go on. Only rank 0 prints.
     */
    int
    read_command_line(int          argc,
                      char       **argv,
                      const bool   root,
                      CommandLine &command)
    {
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "-h" || arg == "--help")
            {
              if (root)
                std::cout << usage;
              return 0;
            }
          else if (arg == "--print-parameters")
            command.print_parameters = true;
          else if (arg == "-s" && i + 1 < argc)
            command.overrides.push_back(argv[++i]);
          else if (arg == "--resume")
            {
              // The folder is optional: a folder after it is its, a scene
              // file is not.
              command.resume = "";
              std::error_code error;
              if (i + 1 < argc &&
                  std::filesystem::is_directory(argv[i + 1], error))
                command.resume = argv[++i];
            }
          else if (arg.rfind("-", 0) == 0 || !command.file.empty())
            {
              if (root)
                std::cerr << "dealmpm: unknown option or second scene file '"
                          << arg << "'\n\n"
                          << usage;
              return 1;
            }
          else
            command.file = arg;
        }
      if (command.file.empty() && !command.print_parameters)
        {
          if (root)
            std::cerr << "dealmpm: no scene file given\n\n" << usage;
          return 1;
        }
      return -1;
    }

    /** --print-parameters: every entry for the scene's shape, with the
     * scene's values (the defaults without a scene). */
    void
    print_parameters(const CommandLine &command,
                     const SceneShape  &shape,
                     const bool         root)
    {
      ParameterHandler prm;
      if (shape.dim == 2)
        Simulation<2>::declare_parameters(prm, shape);
      else
        Simulation<3>::declare_parameters(prm, shape);
      if (!command.file.empty())
        parse_parameter_file(prm, command.file, false);
      apply_overrides(prm, command.overrides);
      if (root)
        prm.print_parameters(std::cout, ParameterHandler::Text);
    }

    /** Runs the scene, or prints its parameters; the exit code unless
     * an error ends it (run_program turns those into exit codes). */
    int
    run_command(const CommandLine &command, const bool root)
    {
      const SceneShape shape =
        read_scene_shape(command.file, command.overrides);
      if (!command.file.empty())
        check_scene_text(command.file,
                         shape.n_bodies,
                         shape.n_materials,
                         shape.n_fem_regions);
      if (command.print_parameters)
        {
          print_parameters(command, shape, root);
          return 0;
        }
      const int signal =
        shape.dim == 2 ?
          run_scene<2>(command.file, command.overrides, shape, command.resume) :
          run_scene<3>(command.file, command.overrides, shape, command.resume);
      return signal != 0 ? 128 + signal : 0;
    }
  } // namespace

  int
  run_program(int argc, char **argv)
  {
    // A study starts dealmpm processes of its own: it runs before (and
    // without) MPI, which does not like its processes to fork.
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]) == "--study")
        return run_study_command(argc, argv);
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const bool  root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    CommandLine command;
    if (const int code = read_command_line(argc, argv, root, command);
        code >= 0)
      return code;
    try
      {
        return run_command(command, root);
      }
    catch (const InputError &e)
      {
        if (root)
          std::cerr << "dealmpm: error: " << e.what() << std::endl;
        return 2;
      }
    catch (const RunError &e)
      {
        if (root)
          std::cerr << "dealmpm: stopped: " << e.what() << std::endl;
        return 3;
      }
    catch (const OutputError &e)
      {
        // Every rank throws it with the same text.
        if (root)
          std::cerr << "dealmpm: output error: " << e.what() << std::endl;
        return 5;
      }
    catch (const std::exception &e)
      {
        std::cerr << "dealmpm: internal error: " << one_line(e) << std::endl;
        return 4;
      }
  }
} // namespace dealmpm
