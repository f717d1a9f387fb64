#pragma once

#include <functional>
#include <istream>
#include <string>

namespace dealmpm
{
  /** One line of deal.II parameter text as walk_parameter_text() sees it. */
  struct ParameterLine
  {
    enum Kind
    {
      subsection, ///< "subsection <name>"
      end,        ///< "end"
      entry,      ///< "set <name> = <value>"
      other       ///< blank, comment or anything else
    };
    Kind         kind   = other;
    unsigned int number = 0; ///< 1-based
    /** The sections open around the line, "A/B/" ("" at the top; for a
     * subsection line, those around it, not the one it opens). */
    std::string section;
    std::string name;  ///< the subsection's or the entry's name, trimmed
    std::string value; ///< an entry's value, trimmed
  };

  /**
   * Calls @p visit for every line of the parameter text in @p in, with the
   * sections open around it, so that the walks over a scene (its entries,
   * the declared names, where a line is) are written once. With
   * @p cut_comments, text from '#' on is dropped first (a scene file);
   * without, '#' is kept (deal.II's printed values may hold one). String
   * operations only: std::regex recurses once per character of a long
   * value.
   */
  void
  walk_parameter_text(std::istream &in,
                      const bool    cut_comments,
                      const std::function<void(const ParameterLine &)> &visit);
} // namespace dealmpm
