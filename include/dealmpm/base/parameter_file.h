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

  /**
   * Check a scene file's text before deal.II parses it, for mistakes whose
   * deal.II message does not say what to do: a scene that sets nothing
   * (empty or only comments) and "Body N" / "Material N" sections beyond
   * "Number of bodies" / "Number of materials". Throws InputError.
   */
  void
  check_scene_text(const std::string &file,
                   const unsigned int n_bodies,
                   const unsigned int n_materials);

  /** Parse a parameter file into @p prm; throws InputError naming the file
   * (and deal.II's line and entry) on failure. */
  void
  parse_parameter_file(ParameterHandler  &prm,
                       const std::string &file,
                       const bool         skip_undefined);
} // namespace dealmpm
