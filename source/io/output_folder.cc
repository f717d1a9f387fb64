#include <dealmpm/base/errors.h>
#include <dealmpm/io/output_folder.h>

#include <filesystem>
#include <regex>
#include <system_error>
#include <vector>

namespace dealmpm
{
  bool
  is_run_output_file(const std::string &file_name)
  {
    static const std::regex pattern(
      "(((particles|grid|fem_region_[0-9]+|rigid_body_[0-9]+)_[0-9]+(\\.[0-9]+)?"
      "\\.(vtu|pvtu|h5))|"
      "particles_[0-9]+\\.csv|statistics\\.csv|.+\\.(pvd|xdmf))(\\.tmp)?");
    return std::regex_match(file_name, pattern);
  }

  namespace
  {
    /** The run output files (is_run_output_file()) in @p directory and its
     * step_folder. */
    std::vector<std::filesystem::path>
    run_output_files(const std::string &directory)
    {
      namespace fs = std::filesystem;
      std::vector<fs::path> files;
      for (const std::string &folder :
           {directory, directory + "/" + step_folder})
        {
          std::error_code error;
          if (!fs::is_directory(folder, error))
            continue;
          for (const fs::directory_entry &entry :
               fs::directory_iterator(folder, error))
            {
              std::error_code type_error;
              if (entry.is_regular_file(type_error) &&
                  is_run_output_file(entry.path().filename().string()))
                files.push_back(entry.path());
            }
          if (error)
            throw OutputError("cannot list " + folder + ": " + error.message());
        }
      return files;
    }
  } // namespace

  unsigned int
  remove_earlier_output(const std::string &directory)
  {
    namespace fs = std::filesystem;
    std::vector<fs::path> series, others;
    for (const fs::path &file : run_output_files(directory))
      {
        const std::string name = file.filename().string();
        (name.find(".pvd") != std::string::npos ||
             name.find(".xdmf") != std::string::npos ?
           series :
           others)
          .push_back(file);
      }
    // The series (.pvd, .xdmf) go first: a run killed while removing must not
    // leave a series that lists removed files.
    series.insert(series.end(), others.begin(), others.end());
    std::error_code error;
    for (const fs::path &file : series)
      if (!fs::remove(file, error) && error)
        throw OutputError("cannot remove " + file.string() +
                          " of an earlier run: " + error.message());
    return series.size();
  }

  unsigned int
  remove_later_output(const std::string &directory,
                      const unsigned int first_counter)
  {
    namespace fs = std::filesystem;
    static const std::regex numbered(
      "(particles|grid|fem_region_[0-9]+|rigid_body_[0-9]+)_([0-9]+)\\..*");
    std::vector<fs::path> later;
    for (const fs::path &file : run_output_files(directory))
      {
        const std::string name = file.filename().string();
        std::smatch       match;
        if (std::regex_match(name, match, numbered) &&
            std::stoul(match[2]) >= first_counter)
          later.push_back(file);
      }
    std::error_code error;
    for (const fs::path &file : later)
      if (!fs::remove(file, error) && error)
        throw OutputError("cannot remove " + file.string() + ": " +
                          error.message());
    return later.size();
  }
} // namespace dealmpm
