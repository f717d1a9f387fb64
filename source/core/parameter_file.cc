#include <deal.II/base/utilities.h>

#include <dealmpm/core/errors.h>
#include <dealmpm/core/parameter_file.h>

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
    return Utilities::trim(text);
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
