#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /** Every entry ("Section/Sub/Name") and section ("Section/Sub") that
   * @p prm declares. */
  struct DeclaredNames
  {
    std::vector<std::string> entries;
    std::vector<std::string> sections;
  };

  DeclaredNames
  declared_names(const ParameterHandler &prm);

  /** " (did you mean 'a'?)" or " (did you mean 'a' or 'b'?)": the names of
   * @p names nearest to @p wrong (edit distance, ignoring case), when they
   * are near enough to be a typo; else "". */
  std::string
  did_you_mean(const std::string &wrong, const std::vector<std::string> &names);

  /** What a Selection's description ("[Selection a|b|c ]") accepts, with
   * the choice nearest @p value: "one of 'a', 'b', 'c' (did you mean
   * 'b'?)"; "" for another pattern. */
  std::string
  selection_choices(const std::string &description, const std::string &value);
} // namespace dealmpm
