#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/parameter_file.h>
#include <dealmpm/base/scene_reader.h>

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <regex>
#include <vector>

#include "name_suggestions.h"
#include "parameter_text.h"

namespace dealmpm
{
  namespace
  {
    // No std::regex on user text here or anywhere: libstdc++'s matcher
    // recurses once per character, and a value of some 20 KB overflowed
    // the stack (a SIGSEGV instead of an error line).
    std::string
    collapse_whitespace(const std::string &text)
    {
      std::string out;
      out.reserve(text.size());
      bool in_space = false;
      for (const char c : text)
        {
          const bool space = std::isspace(static_cast<unsigned char>(c));
          if (!space)
            out += c;
          else if (!in_space)
            out += ' ';
          in_space = space;
        }
      return out;
    }

    /** deal.II quotes values in <...>: cut those over @p most characters
     * (a 1 MB value) to their first @p most and "...". */
    std::string
    shorten_quoted(const std::string &text, const std::size_t most)
    {
      std::string out;
      std::size_t i = 0;
      while (i < text.size())
        {
          const std::size_t open  = text.find('<', i);
          const std::size_t close = open == std::string::npos ?
                                      open :
                                      text.find_first_of("<>", open + 1);
          if (close == std::string::npos)
            return out + text.substr(i);
          if (text[close] == '<' || close - open - 1 <= most)
            {
              out += text.substr(i, close - i);
              i = close;
              if (text[close] == '>')
                out += '>', ++i;
              continue;
            }
          out += text.substr(i, open + 1 + most - i) + "...>";
          i = close + 1;
        }
      return out;
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
    return Utilities::trim(shorten_quoted(collapse_whitespace(text), 200));
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
      std::ifstream in(file);
      std::string   path;
      walk_parameter_text(in, true, [&](const ParameterLine &l) {
        if (l.number == line)
          path = l.section;
      });
      return path;
    }
  } // namespace

  std::string
  plain_pattern(const std::string &description, const std::string &value)
  {
    const std::string number = number_pattern(description, false);
    if (!number.empty())
      return number;
    const std::string choice = selection_choices(description, value);
    if (!choice.empty())
      return choice;
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

  namespace
  {
    /** The number N of deal.II's "Line <N> of file", or 0. */
    unsigned int
    line_of(const std::string &text)
    {
      const std::size_t at = text.find("Line <");
      return at == std::string::npos ?
               0 :
               std::strtoul(text.c_str() + at + 6, nullptr, 10);
    }

    /** The text after @p marker up to @p end (or the end), or "". */
    std::string
    after(const std::string &text, const std::string &marker, const char end)
    {
      const std::size_t at = text.find(marker);
      if (at == std::string::npos)
        return "";
      const std::size_t from = at + marker.size();
      return Utilities::trim(text.substr(from, text.find(end, from) - from));
    }

    /** deal.II's "no entry with name X" / "no such subsection X" for a
     * line of @p file, as one line with the nearest declared names; "" for
     * other errors. */
    std::string
    unknown_name_in_file(const std::exception   &e,
                         const ParameterHandler &prm,
                         const std::string      &file)
    {
      const std::string  text  = one_line(e);
      const unsigned int line  = line_of(text);
      const std::string  entry = after(text, "No entry with name <", '>');
      const std::string  section =
        after(text, "There is no such subsection to be entered:", '\n');
      if (line == 0 || (entry.empty() && section.empty()))
        return "";
      const DeclaredNames names = declared_names(prm);
      const std::string   where = file + ": line " + std::to_string(line);
      const std::string   path  = section_at_line(file, line);
      if (!entry.empty())
        return where + ": '" + path + entry + "' is not an entry of this " +
               "scene" + did_you_mean(path + entry, names.entries);
      return where + ": 'subsection " + section + "'" +
             (path.empty() ? "" :
                             " in '" + path.substr(0, path.size() - 1) + "'") +
             " is not a section of this scene" +
             did_you_mean(path + section, names.sections);
    }

    /** The longest line of a parameter file and the longest -s override.
     * A scene's lines are short (the longest shipped one is 122
     * characters); bounding them keeps every path that formats user text
     * (deal.II's messages and ours) on known sizes. */
    constexpr std::size_t most_characters = 10000;

    /** What deal.II's parser lets through unchecked: lines longer than
     * most_characters, and values with '{', which deal.II takes for a
     * parameter loop's variants and leaves unchecked (a Dimension of
     * "2{" then failed as an internal error when read). */
    void
    check_lines(const std::string &file)
    {
      std::ifstream in(file, std::ios::binary);
      std::string   line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          const std::string where = file + ": line " + std::to_string(number);
          if (line.size() > most_characters)
            throw InputError(where + " has " + std::to_string(line.size()) +
                             " characters: expected at most " +
                             std::to_string(most_characters) +
                             " (is it a parameter file?)");
          const std::string text =
            Utilities::trim(line.substr(0, line.find('#')));
          const std::size_t equal = text.find('=');
          if (text.rfind("set ", 0) == 0 && equal != std::string::npos &&
              text.find('{', equal) != std::string::npos)
            throw InputError(where + ": '" +
                             quote_value(Utilities::trim(text.substr(4))) +
                             "': expected a value without '{'");
        }
    }
  } // namespace

  void
  parse_parameter_file(ParameterHandler  &prm,
                       const std::string &file,
                       const bool         skip_undefined)
  {
    if (!std::ifstream(file))
      throw InputError(file + ": cannot open the scene file");
    check_lines(file);
    try
      {
        prm.parse_input(file,
                        "",
                        skip_undefined,
                        /*assert_mandatory_entries_are_found=*/false);
      }
    catch (const std::exception &e)
      {
        std::string plain = entry_mismatch(e, file);
        if (plain.empty())
          plain = unknown_name_in_file(e, prm, file);
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
        if (item.size() > most_characters)
          throw InputError("command line: -s '" + quote_value(item) + "' has " +
                           std::to_string(item.size()) +
                           " characters: expected at most " +
                           std::to_string(most_characters));
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
            const std::string name = override_path(item);
            if (collapsed_text(e).find("you have not yet declared") !=
                std::string::npos)
              throw InputError("command line: -s '" + quote_value(item) +
                               "': '" + name +
                               "' is not an entry of this scene" +
                               did_you_mean(name, declared_names(prm).entries));
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
