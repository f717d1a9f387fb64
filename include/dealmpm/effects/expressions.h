#pragma once

#include <deal.II/base/function_parser.h>

#include <dealmpm/base/scene_reader.h>

#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /** "x,y" or "x,y,z", with ",t" for expressions of time. */
  std::string
  coordinate_names(int dim, bool with_time);

  /**
   * Parse @p expressions (muparser, with pi) of entry @p entry into
   * @p function, variables x, y (, z) (, t); a syntax error is the
   * entry's one-line failure, saying @p expected (muparser finds some
   * only when it first evaluates, and deal.II writes them to std::cerr:
   * they are evaluated once here, with std::cerr held back).
   */
  template <int dim>
  void
  parse_expressions(FunctionParser<dim>            &function,
                    const std::vector<std::string> &expressions,
                    bool                            with_time,
                    const SceneReader              &reader,
                    const std::string              &entry,
                    const std::string              &expected);
} // namespace dealmpm
