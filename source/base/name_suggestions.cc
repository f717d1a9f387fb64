#include "name_suggestions.h"

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <sstream>

#include "parameter_text.h"

namespace dealmpm
{
  DeclaredNames
  declared_names(const ParameterHandler &prm)
  {
    std::ostringstream printed;
    prm.print_parameters(printed, ParameterHandler::ShortPRM);
    DeclaredNames      names;
    std::istringstream in(printed.str());
    walk_parameter_text(in, false, [&](const ParameterLine &line) {
      if (line.kind == ParameterLine::subsection)
        names.sections.push_back(line.section + line.name);
      else if (line.kind == ParameterLine::entry)
        names.entries.push_back(line.section + line.name);
    });
    return names;
  }

  namespace
  {
    /** Levenshtein distance, case ignored. */
    std::size_t
    edit_distance(const std::string &a, const std::string &b)
    {
      std::vector<std::size_t> row(b.size() + 1);
      for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (std::size_t i = 1; i <= a.size(); ++i)
        {
          std::size_t diagonal = row[0];
          row[0]               = i;
          for (std::size_t j = 1; j <= b.size(); ++j)
            {
              const bool same =
                std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                std::tolower(static_cast<unsigned char>(b[j - 1]));
              const std::size_t next =
                std::min({row[j] + 1, row[j - 1] + 1, diagonal + !same});
              diagonal = row[j];
              row[j]   = next;
            }
        }
      return row[b.size()];
    }
  } // namespace

  std::string
  did_you_mean(const std::string &wrong, const std::vector<std::string> &names)
  {
    // A typo is a few characters of a name; longer input is no name.
    if (wrong.empty() || wrong.size() > 200)
      return "";
    std::size_t              best = std::string::npos;
    std::vector<std::string> nearest;
    for (const std::string &name : names)
      {
        const std::size_t d = edit_distance(wrong, name);
        if (d < best)
          best = d, nearest.clear();
        if (d == best && nearest.size() < 3 &&
            std::find(nearest.begin(), nearest.end(), name) == nearest.end())
          nearest.push_back(name);
      }
    // Near enough to be a typo: a third of the last name's characters (a
    // long path alone would let a far name pass).
    const std::size_t leaf = wrong.size() - (wrong.rfind('/') + 1);
    if (nearest.empty() || best > std::max<std::size_t>(2, leaf / 3))
      return "";
    std::string text = " (did you mean '" + nearest[0] + "'";
    for (std::size_t i = 1; i < nearest.size(); ++i)
      text += (i + 1 == nearest.size() ? " or '" : ", '") + nearest[i] + "'";
    return text + "?)";
  }

  std::string
  selection_choices(const std::string &description, const std::string &value)
  {
    const std::string head = "[Selection ";
    if (description.rfind(head, 0) != 0 || description.back() != ']')
      return "";
    const std::vector<std::string> choices = Utilities::split_string_list(
      description.substr(head.size(), description.size() - head.size() - 1),
      '|');
    std::string text = "one of ";
    for (std::size_t i = 0; i < choices.size(); ++i)
      text += (i == 0 ? "'" : ", '") + choices[i] + "'";
    return text + did_you_mean(Utilities::trim(value), choices);
  }
} // namespace dealmpm
