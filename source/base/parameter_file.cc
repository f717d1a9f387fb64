#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/parameter_file.h>
#include <dealmpm/base/scene_reader.h>

#include <fstream>
#include <limits>
#include <regex>
#include <vector>

namespace dealmpm
{
  namespace
  {
    std::string
    collapse_whitespace(const std::string &text)
    {
      return std::regex_replace(text, std::regex("\\s+"), " ");
    }
  } // namespace

  std::string
  collapsed_text(const std::exception &e)
  {
    return collapse_whitespace(e.what());
  }

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
    text = collapse_whitespace(text);
    // deal.II quotes values in <...>: cut long ones (a 1 MB value).
    text =
      std::regex_replace(text, std::regex("<([^<>]{200})[^<>]+>"), "<$1...>");
    return Utilities::trim(text);
  }

  namespace
  {
    /** deal.II's pattern descriptions write "MAX_DOUBLE" or the int and
     * unsigned int limits for no bound. */
    bool
    is_bound(const std::string &text)
    {
      return text.find("MAX_") == std::string::npos &&
             text != std::to_string(std::numeric_limits<int>::max()) &&
             text != std::to_string(std::numeric_limits<int>::min()) &&
             text != std::to_string(std::numeric_limits<unsigned int>::max());
    }

    /** "a number >= 0", or in the plural "numbers >= 0"; "positive
     * integers" for integers from 1. */
    std::string
    number_words(const bool         integer,
                 const std::string &lower,
                 const std::string &upper,
                 const bool         plural)
    {
      std::string kind = integer ? (plural ? "integers" : "an integer") :
                                   (plural ? "numbers" : "a number");
      if (integer && lower == "1" && !is_bound(upper))
        return plural ? "positive integers" : "a positive integer";
      if (is_bound(lower) && is_bound(upper))
        return kind + " from " + lower + " to " + upper;
      if (is_bound(lower))
        return kind + " >= " + lower;
      if (is_bound(upper))
        return kind + " <= " + upper;
      return kind;
    }

    const std::string bounds = "(\\S+)\\.\\.\\.(\\S+) \\(inclusive\\)";

    /** A number pattern's words, or "" for another pattern. */
    std::string
    number_pattern(const std::string &description, const bool plural)
    {
      std::smatch match;
      if (std::regex_match(description,
                           match,
                           std::regex("\\[Double " + bounds + "\\]")))
        return number_words(false, match[1], match[2], plural);
      if (std::regex_match(description,
                           match,
                           std::regex("\\[Integer range " + bounds + "\\]")))
        return number_words(true, match[1], match[2], plural);
      if (description == "[Integer]")
        return plural ? "integers" : "an integer";
      return "";
    }

    /** The subsections open at @p line of a parameter file, as "A/B/". */
    std::string
    section_at_line(const std::string &file, const unsigned int line)
    {
      std::ifstream            in(file);
      std::vector<std::string> open;
      std::string              text;
      const std::regex         subsection("\\s*subsection\\s+(.*\\S)\\s*");
      const std::regex         end("\\s*end\\s*");
      for (unsigned int number = 1; number < line && std::getline(in, text);
           ++number)
        {
          text = text.substr(0, text.find('#'));
          std::smatch match;
          if (std::regex_match(text, match, subsection))
            open.push_back(match[1]);
          else if (std::regex_match(text, end) && !open.empty())
            open.pop_back();
        }
      std::string path;
      for (const auto &s : open)
        path += s + "/";
      return path;
    }
  } // namespace

  std::string
  plain_pattern(const std::string &description, const std::string &value)
  {
    const std::string number = number_pattern(description, false);
    if (!number.empty())
      return number;
    std::smatch match;
    if (std::regex_match(description,
                         match,
                         std::regex("\\[MultipleSelection (.*) \\]")))
      return "a comma-separated list of: " +
             std::regex_replace(std::string(match[1]), std::regex("\\|"), ", ");
    if (!std::regex_match(description,
                          match,
                          std::regex("\\[List of <(.*)> of length " + bounds +
                                     "( separated by <,>)?\\]")))
      return "";
    const std::string elements = number_pattern(match[1], true);
    if (elements.empty())
      return "";
    // Say the count only when the count is what is wrong.
    const auto n = Utilities::split_string_list(value, ',').size();
    if (match[2] == match[3] && n != std::stoul(match[2]))
      return std::string(match[2]) + " " + elements + ", comma-separated";
    const bool open_ended = !is_bound(match[3]);
    if (n < std::stoul(match[2]) || (!open_ended && n > std::stoul(match[3])))
      return (open_ended ?
                "at least " + std::string(match[2]) :
                std::string(match[2]) + " to " + std::string(match[3])) +
             " " + elements + ", comma-separated";
    return elements;
  }

  std::string
  entry_mismatch(const std::exception &e, const std::string &file)
  {
    const std::string text = collapsed_text(e);
    std::smatch       match;
    if (!std::regex_search(
          text,
          match,
          std::regex("Line <([0-9]+)> of file <[^>]*>: The entry value (.*?) "
                     "for the entry named (.*?) does not match the given "
                     "pattern: (\\[.*?\\])(?= |$)")))
      return "";
    const std::string expected = plain_pattern(match[4], match[2]);
    if (expected.empty())
      return "";
    const std::string path =
      section_at_line(file, std::stoul(match[1])) + std::string(match[3]);
    return file + ": entry '" + path + "' = '" + quote_value(match[2]) +
           "': expected " + expected;
  }

  void
  check_scene_text(const std::string &file,
                   const unsigned int n_bodies,
                   const unsigned int n_materials,
                   const unsigned int n_fem_regions)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError(file + ": cannot open the scene file");
    const std::regex numbered(
      "\\s*subsection\\s+(Body|Material|FEM region)\\s+([0-9]+)\\s*");
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
        const std::string  kind  = match[1];
        const unsigned int count = kind == "Body"     ? n_bodies :
                                   kind == "Material" ? n_materials :
                                                        n_fem_regions;
        const std::string  entry = kind == "Body"     ? "Number of bodies" :
                                   kind == "Material" ? "Number of materials" :
                                                        "Number of FEM regions";
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
        const std::string plain = entry_mismatch(e, file);
        throw InputError(plain.empty() ? file + ": " + one_line(e) : plain);
      }
  }

  namespace
  {
    /** Why prm.set refused a value: what the entry's typed pattern expects,
     * or deal.II's text (a Selection's lists its choices). */
    std::string
    override_mismatch(const std::exception &e, const std::string &value)
    {
      const std::string text = collapsed_text(e);
      std::smatch       match;
      if (std::regex_search(
            text,
            match,
            std::regex("does not match the given pattern <(\\[.*?\\])>\\.")))
        {
          const std::string expected = plain_pattern(match[1], value);
          if (!expected.empty())
            return "expected " + expected;
        }
      return one_line(e);
    }
  } // namespace

  void
  apply_overrides(ParameterHandler               &prm,
                  const std::vector<std::string> &overrides)
  {
    for (const auto &item : overrides)
      {
        const auto equal = item.find('=');
        if (equal == std::string::npos)
          throw InputError("command line: -s '" + quote_value(item) +
                           "': expected 'Section/Entry=value'");
        const auto path =
          Utilities::split_string_list(item.substr(0, equal), '/');
        if (path.empty() ||
            std::any_of(path.begin(), path.end(), [](const std::string &p) {
              return p.empty();
            }))
          throw InputError("command line: -s '" + quote_value(item) +
                           "': expected 'Section/Entry=value'");
        const std::string value = Utilities::trim(item.substr(equal + 1));
        for (unsigned int i = 0; i + 1 < path.size(); ++i)
          prm.enter_subsection(path[i]);
        try
          {
            prm.set(path.back(), value);
          }
        catch (const std::exception &e)
          {
            for (unsigned int i = 0; i + 1 < path.size(); ++i)
              prm.leave_subsection();
            throw InputError("command line: -s '" + quote_value(item) +
                             "': " + override_mismatch(e, value));
          }
        for (unsigned int i = 0; i + 1 < path.size(); ++i)
          prm.leave_subsection();
      }
  }

  SceneShape
  read_scene_shape(const std::string              &file,
                   const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3));
    prm.declare_entry("Number of bodies", "1", Patterns::Integer(1, 10000));
    prm.declare_entry("Number of materials", "1", Patterns::Integer(1, 10000));
    prm.declare_entry("Number of FEM regions", "0", Patterns::Integer(0, 1000));
    if (!file.empty())
      parse_parameter_file(prm, file, true);
    std::vector<std::string> top_level;
    for (const auto &item : overrides)
      for (const std::string name : {"Dimension",
                                     "Number of bodies",
                                     "Number of materials",
                                     "Number of FEM regions"})
        if (item.rfind(name + "=", 0) == 0 || item.rfind(name + " =", 0) == 0)
          top_level.push_back(item);
    apply_overrides(prm, top_level);
    SceneShape shape;
    shape.dim           = prm.get_integer("Dimension");
    shape.n_bodies      = prm.get_integer("Number of bodies");
    shape.n_materials   = prm.get_integer("Number of materials");
    shape.n_fem_regions = prm.get_integer("Number of FEM regions");
    return shape;
  }

} // namespace dealmpm
