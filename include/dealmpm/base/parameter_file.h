#pragma once

#include <deal.II/base/parameter_handler.h>

#include <exception>
#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /** deal.II's multi-line exception text as one line: the part after
   * "Additional information:" with whitespace collapsed. */
  std::string
  one_line(const std::exception &e);

  /** The whole text of @p e with every run of whitespace made one space
   * (deal.II wraps its messages at spaces). */
  std::string
  collapsed_text(const std::exception &e);

  /**
   * Check a scene file's text before deal.II parses it, for mistakes whose
   * deal.II message does not say what to do: a scene that sets nothing
   * (empty or only comments) and "Body N" / "Material N" / "FEM region N"
   * sections beyond "Number of bodies" / "Number of materials" / "Number
   * of FEM regions". Throws InputError.
   */
  void
  check_scene_text(const std::string &file,
                   const unsigned int n_bodies,
                   const unsigned int n_materials,
                   const unsigned int n_fem_regions = 0);

  /**
   * What a typed pattern's description (Patterns::Double, Integer,
   * MultipleSelection, List of numbers) expects, in the words of the
   * program's other input messages ("a number >= 0", "a comma-separated list
   * of: a, b", "one of 'a', 'b' (did you mean 'b'?)"); empty for the
   * others. For a list, @p value decides whether the count is named (only
   * when the count is wrong); for a Selection, which choice is suggested.
   */
  std::string
  plain_pattern(const std::string &description, const std::string &value);

  /**
   * deal.II's "value does not match the pattern" for an entry of @p file, in
   * the words of SceneReader::fail: "file: entry 'Section/Entry' = 'value':
   * expected ..." (the section from the line deal.II names). Empty when @p e
   * is another error or its pattern has no plain form.
   */
  std::string
  entry_mismatch(const std::exception &e, const std::string &file);

  /** Parse a parameter file into @p prm; throws InputError naming the file
   * (and deal.II's line and entry) on failure. */
  void
  parse_parameter_file(ParameterHandler  &prm,
                       const std::string &file,
                       const bool         skip_undefined);

  /** The size of a scene, read before everything else is declared. */
  struct SceneShape
  {
    unsigned int dim           = 2;
    unsigned int n_bodies      = 1;
    unsigned int n_materials   = 1;
    unsigned int n_fem_regions = 0;
  };

  /** Read Dimension, Number of bodies and Number of materials (pass one of
   * two over the scene file, overrides applied). */
  SceneShape
  read_scene_shape(const std::string              &file,
                   const std::vector<std::string> &overrides);

  /** Apply "Section/Entry=value" overrides; throws InputError. */
  void
  apply_overrides(ParameterHandler               &prm,
                  const std::vector<std::string> &overrides);
} // namespace dealmpm
