#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /**
   * Warn (warn(), once per section) for each entry a scene sets, in its
   * file or with -s, in a section the scene does not use, which would
   * otherwise be ignored silently: an effect's section while the effect is
   * not in 'Effects' (-s "Gravity/Acceleration=0, -9.81" without gravity),
   * a material model's subsection other than the material's 'Model'.
   * Body, material and FEM region sections beyond their counts are errors
   * already (check_scene_text(), and deal.II for overrides).
   */
  template <int dim>
  void
  warn_unused_sections(const ParameterHandler         &prm,
                       const std::string              &file,
                       const std::vector<std::string> &overrides,
                       const unsigned int              n_materials);
} // namespace dealmpm
