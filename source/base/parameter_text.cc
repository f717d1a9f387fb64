#include "parameter_text.h"

#include <deal.II/base/utilities.h>

#include <cctype>
#include <vector>

namespace dealmpm
{
  namespace
  {
    /** Whether @p text starts with the word @p word (then whitespace or its
     * end), and if so the trimmed rest in @p rest. */
    bool
    starts_with_word(const std::string &text,
                     const std::string &word,
                     std::string       &rest)
    {
      if (text.compare(0, word.size(), word) != 0 ||
          (text.size() > word.size() &&
           !std::isspace(static_cast<unsigned char>(text[word.size()]))))
        return false;
      rest = dealii::Utilities::trim(text.substr(word.size()));
      return true;
    }
  } // namespace

  void
  walk_parameter_text(std::istream &in,
                      const bool    cut_comments,
                      const std::function<void(const ParameterLine &)> &visit)
  {
    std::vector<std::string> open;
    std::string              raw, rest;
    for (unsigned int number = 1; std::getline(in, raw); ++number)
      {
        ParameterLine line;
        line.number = number;
        for (const std::string &s : open)
          line.section += s + "/";
        const std::string text = dealii::Utilities::trim(
          cut_comments ? raw.substr(0, raw.find('#')) : raw);
        if (starts_with_word(text, "subsection", rest) && !rest.empty())
          {
            line.kind = ParameterLine::subsection;
            line.name = rest;
          }
        else if (text == "end")
          line.kind = ParameterLine::end;
        else if (starts_with_word(text, "set", rest) &&
                 rest.find('=') != std::string::npos)
          {
            line.kind = ParameterLine::entry;
            line.name = dealii::Utilities::trim(rest.substr(0, rest.find('=')));
            line.value =
              dealii::Utilities::trim(rest.substr(rest.find('=') + 1));
          }
        visit(line);
        if (line.kind == ParameterLine::subsection)
          open.push_back(line.name);
        else if (line.kind == ParameterLine::end && !open.empty())
          open.pop_back();
      }
  }
} // namespace dealmpm
