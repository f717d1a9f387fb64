#pragma once

#include <deal.II/base/parameter_handler.h>

#include <exception>
#include <string>

namespace dealmpm
{
  using namespace dealii;

  /** deal.II's multi-line exception text as one line: the part after
   * "Additional information:" with whitespace collapsed. */
  std::string
  one_line(const std::exception &e);

  /** Parse a parameter file into @p prm; throws InputError naming the file
   * (and deal.II's line and entry) on failure. */
  void
  parse_parameter_file(ParameterHandler  &prm,
                       const std::string &file,
                       const bool         skip_undefined);
} // namespace dealmpm
