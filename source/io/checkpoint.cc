#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/io/checkpoint.h>
#include <dealmpm/io/output_file.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <regex>
#include <sstream>

#include "../base/parameter_text.h"

namespace dealmpm
{
  namespace fs = std::filesystem;

  void
  CheckpointSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.declare_entry("Steps between checkpoints",
                      "0",
                      Patterns::Integer(0),
                      "Save the run every this many steps (0: not by steps), "
                      "and at its end. Continue a saved run with 'dealmpm "
                      "scene.prm --resume' (after its end with a longer "
                      "'Time/End time').");
    prm.declare_entry("Seconds between checkpoints",
                      "0",
                      Patterns::Double(),
                      "Save the run every this many seconds of wall time "
                      "(0: not by time), and at its end.");
    prm.declare_entry("On stop signal",
                      "true",
                      Patterns::Bool(),
                      "Save the run when SIGTERM or SIGINT stop it (a batch "
                      "system's warning before its time limit).");
    prm.declare_entry("Keep",
                      "2",
                      Patterns::Integer(1),
                      "How many of the newest checkpoints are kept.");
    prm.declare_entry(
      "Directory",
      "",
      Patterns::Anything(),
      "Folder of the checkpoints (checkpoint-NNNNNNNN/ folders and the "
      "pointer file 'latest'); empty: 'checkpoints' in the output folder. A "
      "run that does not resume removes the checkpoints of an earlier run "
      "there.");
    prm.leave_subsection();
  }

  CheckpointSettings
  CheckpointSettings::read(SceneReader       &reader,
                           const std::string &output_directory)
  {
    CheckpointSettings s;
    SectionScope       section(reader, "Checkpoint");
    s.step_interval  = reader.get_integer("Steps between checkpoints");
    s.wall_interval  = reader.get_nonnegative("Seconds between checkpoints");
    s.on_stop_signal = reader.get_bool("On stop signal");
    s.keep           = reader.get_integer("Keep");
    s.directory      = reader.get("Directory");
    if (s.directory.empty())
      s.directory = output_directory + "/checkpoints";
    return s;
  }

  namespace
  {
    const char *header = "dealmpm checkpoint 1";

    std::string
    hex(const double x)
    {
      std::ostringstream out;
      out << std::hexfloat << x;
      return out.str();
    }

    /** The step of a folder named checkpoint-NNNNNNNN (@p temporary: with
     * ".tmp"), or -1. */
    long long
    checkpoint_step(const std::string &name, const bool temporary = false)
    {
      static const std::regex whole("checkpoint-([0-9]+)");
      static const std::regex partial("checkpoint-([0-9]+)\\.tmp");
      std::smatch             match;
      if (std::regex_match(name, match, temporary ? partial : whole))
        return std::stoll(match[1]);
      return -1;
    }

    /** Whether @p folder holds everything a checkpoint writes. */
    bool
    is_whole(const fs::path &folder)
    {
      for (const char *file : {"grid", "grid.info", "run_state.txt"})
        if (!fs::is_regular_file(folder / file))
          return false;
      try
        {
          CheckpointInfo::read((folder / "checkpoint.txt").string());
        }
      catch (const InputError &)
        {
          return false;
        }
      return true;
    }

    /** Rank 0's problem, thrown by every rank. */
    void
    agree(const std::string &problem, const MPI_Comm comm)
    {
      agree_on_output_error(problem, "", comm);
    }
  } // namespace

  void
  CheckpointInfo::write(const std::string &file) const
  {
    std::ostringstream out;
    out << header << '\n'
        << "dimension " << dim << '\n'
        << "ranks " << n_ranks << '\n'
        << "step " << step << '\n'
        << "time " << hex(time) << '\n'
        << "coarse-grid " << coarse_grid << '\n'
        << "mass-threshold " << hex(mass_threshold) << '\n'
        << "mean-particle-mass " << hex(mean_particle_mass) << '\n'
        << "max-signal-rate " << hex(max_signal_rate) << '\n'
        << "cfl-warned " << cfl_warned << '\n';
    for (const std::string &field : particle_layout)
      out << "layout " << field << '\n';
    for (const std::string &entry : scene)
      out << "entry " << entry << '\n';
    out << "end\n";
    OutputFile output(file);
    output.write(out.str());
    output.commit();
  }

  CheckpointInfo
  CheckpointInfo::read(const std::string &file)
  {
    std::ifstream in(file);
    const auto    damaged = [&](const std::string &what) {
      return InputError(file + ": not a whole checkpoint description (" + what +
                        ")");
    };
    std::string line;
    if (!in || !std::getline(in, line) || line != header)
      throw damaged("it does not start with '" + std::string(header) + "'");
    CheckpointInfo info;
    bool           ended = false;
    while (std::getline(in, line))
      {
        if (line == "end")
          {
            ended = true;
            break;
          }
        const std::size_t space = line.find(' ');
        const std::string key   = line.substr(0, space);
        const std::string value =
          space == std::string::npos ? "" : line.substr(space + 1);
        try
          {
            if (key == "dimension")
              info.dim = std::stoul(value);
            else if (key == "ranks")
              info.n_ranks = std::stoul(value);
            else if (key == "step")
              info.step = std::stoul(value);
            else if (key == "time")
              info.time = std::strtod(value.c_str(), nullptr);
            else if (key == "coarse-grid")
              info.coarse_grid = value;
            else if (key == "mass-threshold")
              info.mass_threshold = std::strtod(value.c_str(), nullptr);
            else if (key == "mean-particle-mass")
              info.mean_particle_mass = std::strtod(value.c_str(), nullptr);
            else if (key == "max-signal-rate")
              info.max_signal_rate = std::strtod(value.c_str(), nullptr);
            else if (key == "cfl-warned")
              info.cfl_warned = value == "1";
            else if (key == "layout")
              info.particle_layout.push_back(value);
            else if (key == "entry")
              info.scene.push_back(value);
            else
              throw damaged("unknown line '" + line + "'");
          }
        catch (const std::logic_error &)
          {
            throw damaged("bad line '" + line + "'");
          }
      }
    if (!ended)
      throw damaged("it has no 'end' line");
    if (info.dim < 2 || info.dim > 3 || info.n_ranks == 0)
      throw damaged("no dimension or ranks");
    return info;
  }

  std::vector<std::string>
  scene_entries(const ParameterHandler &prm)
  {
    std::ostringstream printed;
    prm.print_parameters(printed, ParameterHandler::ShortPRM);
    const std::vector<std::string> free_sections = {"Output/",
                                                    "Checkpoint/",
                                                    "Load balance/",
                                                    "Checks/"};
    const std::vector<std::string> free_entries  = {
       "Time/End time", "Time/Maximum number of steps"};
    std::vector<std::string> entries;
    std::istringstream       in(printed.str());
    walk_parameter_text(in, false, [&](const ParameterLine &line) {
      const std::string path   = line.section + line.name;
      const auto        starts = [&](const std::string &prefix) {
        return path.rfind(prefix, 0) == 0;
      };
      if (line.kind == ParameterLine::entry &&
          std::none_of(free_sections.begin(), free_sections.end(), starts) &&
          std::find(free_entries.begin(), free_entries.end(), path) ==
            free_entries.end())
        entries.push_back(path + " = " + line.value);
    });
    return entries;
  }

  std::string
  first_scene_change(const std::vector<std::string> &saved,
                     const std::vector<std::string> &now)
  {
    const auto split = [](const std::vector<std::string> &entries) {
      std::map<std::string, std::string> values;
      for (const std::string &e : entries)
        {
          const std::size_t at = e.find(" = ");
          values[e.substr(0, at)] =
            at == std::string::npos ? "" : e.substr(at + 3);
        }
      return values;
    };
    const auto before = split(saved);
    const auto after  = split(now);
    for (const auto &[path, value] : after)
      {
        const auto old = before.find(path);
        if (old == before.end())
          return "entry '" + path +
                 "' is new (the saved run had no such entry)";
        if (old->second != value)
          return "entry '" + path + "' = '" + value +
                 "' differs from the saved run's '" + old->second + "'";
      }
    for (const auto &[path, value] : before)
      if (after.find(path) == after.end())
        return "the saved run had entry '" + path + "' = '" + value +
               "', which this scene does not have";
    return "";
  }

  std::vector<std::string>
  layout_description(const PropertyLayout &layout)
  {
    std::vector<std::string> fields;
    for (const PropertyLayout::Field &f : layout.fields())
      fields.push_back(f.name + " " + std::to_string(f.offset) + " " +
                       std::to_string(f.n_components));
    return fields;
  }

  std::string
  checkpoint_name(const unsigned int step)
  {
    std::ostringstream name;
    name << "checkpoint-" << std::setw(8) << std::setfill('0') << step;
    return name.str();
  }

  std::string
  start_checkpoint(const std::string &directory,
                   const unsigned int step,
                   const MPI_Comm     comm)
  {
    const fs::path folder =
      fs::path(directory) / (checkpoint_name(step) + ".tmp");
    std::string problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          fs::create_directories(directory);
          // What interrupted writes left.
          for (const fs::directory_entry &entry :
               fs::directory_iterator(directory))
            if (checkpoint_step(entry.path().filename().string(), true) >= 0)
              fs::remove_all(entry.path());
          fs::create_directory(folder);
        }
      catch (const std::exception &e)
        {
          problem = "cannot make the checkpoint folder " + folder.string() +
                    ": " + e.what();
        }
    agree(problem, comm);
    return folder.string();
  }

  std::string
  publish_checkpoint(const std::string &directory,
                     const std::string &folder,
                     const unsigned int step,
                     const unsigned int keep,
                     const MPI_Comm     comm)
  {
    // Every rank has written its part.
    MPI_Barrier(comm);
    const fs::path final_folder = fs::path(directory) / checkpoint_name(step);
    std::string    problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          // A run resumed from this step saves it again.
          fs::remove_all(final_folder);
          fs::rename(folder, final_folder);
          OutputFile latest((fs::path(directory) / "latest").string());
          latest.write(checkpoint_name(step) + "\n");
          latest.commit();
          std::vector<std::pair<long long, fs::path>> saved;
          for (const fs::directory_entry &entry :
               fs::directory_iterator(directory))
            {
              const long long n =
                checkpoint_step(entry.path().filename().string());
              if (n >= 0 && entry.path() != final_folder)
                saved.emplace_back(n, entry.path());
            }
          std::sort(saved.begin(), saved.end());
          for (std::size_t i = 0; i + keep < saved.size() + 1; ++i)
            fs::remove_all(saved[i].second);
        }
      catch (const std::exception &e)
        {
          problem = "cannot publish the checkpoint " + final_folder.string() +
                    ": " + e.what();
        }
    agree(problem, comm);
    return final_folder.string();
  }

  std::string
  find_checkpoint(const std::string &path, std::string &warning)
  {
    const fs::path given(path);
    if (fs::exists(given / "checkpoint.txt"))
      {
        if (!is_whole(given))
          throw InputError(path + ": not a whole checkpoint (a file is "
                                  "missing or cut off)");
        return given.string();
      }
    if (!fs::is_directory(given))
      throw InputError(path + ": no such folder of checkpoints (expected "
                              "the 'Checkpoint/Directory' of a run, or one "
                              "of its checkpoint-NNNNNNNN folders)");
    std::string named;
    {
      std::ifstream latest(given / "latest");
      std::getline(latest, named);
    }
    if (!named.empty() && checkpoint_step(named) >= 0 &&
        is_whole(given / named))
      return (given / named).string();
    std::vector<std::pair<long long, fs::path>> saved;
    for (const fs::directory_entry &entry : fs::directory_iterator(given))
      {
        const long long n = checkpoint_step(entry.path().filename().string());
        if (n >= 0)
          saved.emplace_back(n, entry.path());
      }
    std::sort(saved.rbegin(), saved.rend());
    for (const auto &[n, folder] : saved)
      if (is_whole(folder))
        {
          warning = named.empty() ?
                      path +
                        "/latest is missing; resuming from the newest "
                        "whole checkpoint, " +
                        folder.filename().string() :
                      path + "/latest names " + named +
                        ", which is missing or damaged; resuming from " +
                        folder.filename().string();
          return folder.string();
        }
    throw InputError(path + ": no checkpoint to resume from (the run wrote "
                            "none: see the 'Checkpoint' section)");
  }

  unsigned int
  remove_checkpoints(const std::string &directory, const long long after)
  {
    unsigned int    n = 0;
    std::error_code missing;
    if (!fs::is_directory(directory, missing))
      return 0;
    try
      {
        for (const fs::directory_entry &entry :
             fs::directory_iterator(directory))
          {
            const std::string name = entry.path().filename().string();
            const long long   step =
              std::max(checkpoint_step(name), checkpoint_step(name, true));
            if (step >= 0 && step > after)
              {
                fs::remove_all(entry.path());
                ++n;
              }
          }
        // A pointer to a removed checkpoint goes too.
        const fs::path latest = fs::path(directory) / "latest";
        std::string    named;
        {
          std::ifstream in(latest);
          std::getline(in, named);
        }
        if (fs::exists(latest) &&
            (named.empty() || !fs::exists(fs::path(directory) / named)))
          fs::remove(latest);
      }
    catch (const std::exception &e)
      {
        throw OutputError("cannot remove the checkpoints in " + directory +
                          ": " + e.what());
      }
    return n;
  }

  void
  test_kill_in_checkpoint(const MPI_Comm comm)
  {
    static unsigned int n_written = 0;
    ++n_written;
    const char *when = std::getenv("DEALMPM_KILL_IN_CHECKPOINT");
    if (when != nullptr && Utilities::MPI::this_mpi_process(comm) == 0 &&
        std::strtoul(when, nullptr, 10) == n_written)
      std::raise(SIGKILL);
  }
} // namespace dealmpm
