#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/scene_reader.h>

#include <array>
#include <string>

namespace dealmpm
{
  using namespace dealii;

  /** Friction angle, Dilation angle and Cohesion of a frictional
   * model (Drucker-Prager, Mohr-Coulomb). */
  void
  declare_friction_parameters(ParameterHandler  &prm,
                              const std::string &friction_default,
                              const std::string &friction_documentation,
                              const std::string &cohesion_documentation);

  /** The friction and dilation angles, checked, in radians. */
  std::array<double, 2>
  read_friction_angles(SceneReader &reader);
} // namespace dealmpm
