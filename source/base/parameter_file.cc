#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/parameter_file.h>

#include <fstream>
#include <regex>

namespace dealmpm
{
  std::string
  one_line(const std::exception &e)
  {
    std::string       text   = e.what();
    const std::string marker = "Additional information:";
    const auto        pos    = text.find(marker);
    if (pos != std::string::npos)
      text = text.substr(pos + marker.size());
    for (const char *end : {"Stacktrace:", "-----"})
      {
        const auto cut = text.find(end);
        if (cut != std::string::npos)
          text = text.substr(0, cut);
      }
    text = std::regex_replace(text, std::regex("\\s+"), " ");
    // deal.II quotes values in <...>: cut long ones (a 1 MB value).
    text =
      std::regex_replace(text, std::regex("<([^<>]{200})[^<>]+>"), "<$1...>");
    return Utilities::trim(text);
  }

  void
  check_scene_text(const std::string &file,
                   const unsigned int n_bodies,
                   const unsigned int n_materials)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError(file + ": cannot open the scene file");
    const std::regex numbered(
      "\\s*subsection\\s+(Body|Material)\\s+([0-9]+)\\s*");
    const std::regex setting("\\s*set\\s.*");
    bool             sets_something = false;
    std::string      line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        line = line.substr(0, line.find('#'));
        std::smatch match;
        sets_something = sets_something || std::regex_match(line, setting);
        if (!std::regex_match(line, match, numbered))
          continue;
        const bool         body  = match[1] == "Body";
        const unsigned int count = body ? n_bodies : n_materials;
        const std::string  entry =
          body ? "Number of bodies" : "Number of materials";
        if (std::stoul(match[2]) > count || std::stoul(match[2]) == 0)
          throw InputError(file + ": line " + std::to_string(number) +
                           ": section '" + std::string(match[1]) + " " +
                           std::string(match[2]) + "' but '" + entry +
                           "' = " + std::to_string(count) + ": expected " +
                           entry + " to count every " + std::string(match[1]) +
                           " section (sections are numbered from 1)");
      }
    if (!sets_something)
      throw InputError(file +
                       ": the scene sets nothing (no 'set' line): start from "
                       "a scene in prm/, or see 'dealmpm --print-parameters' "
                       "for every entry");
  }

  void
  parse_parameter_file(ParameterHandler  &prm,
                       const std::string &file,
                       const bool         skip_undefined)
  {
    if (!std::ifstream(file))
      throw InputError(file + ": cannot open the scene file");
    try
      {
        prm.parse_input(file,
                        "",
                        skip_undefined,
                        /*assert_mandatory_entries_are_found=*/false);
      }
    catch (const std::exception &e)
      {
        throw InputError(file + ": " + one_line(e));
      }
  }

} // namespace dealmpm
