#pragma once

#include <dealmpm/adaptivity/adaptivity.h>
#include <dealmpm/base/scene_reader.h>
#include <dealmpm/effects/effect.h>
#include <dealmpm/materials/material.h>
#include <dealmpm/particles/body.h>
#include <dealmpm/schemes/method_settings.h>

#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /** What a scene chose, as read: the parts whose combinations
   * check_compatibility() judges. */
  template <int dim>
  struct SceneChoices
  {
    const MethodSettings                              &method;
    const AdaptivitySettings<dim>                     &adaptivity;
    const std::vector<std::unique_ptr<Material<dim>>> &materials;
    const std::vector<std::string>                    &material_models;
    const std::vector<std::unique_ptr<Effect<dim>>>   &effects;
    const std::vector<std::string>                    &effect_names;
    const std::vector<Body<dim>>                      &bodies;
    unsigned int                                       n_fem_regions = 0;
  };

  /**
   * Every refusal of a combination of choices (method x materials x effects
   * x FEM regions x adaptivity x formulation), one rule each, run once
   * after the scene is read and before anything is built. A rule asks the
   * parts what they can do (Effect::needs_body_fields(),
   * ShapeFunction::needs_uniform_grid(), Material::resets_deformation())
   * rather than comparing names. The first broken rule fails through
   * @p reader with the entry to change. Checks of a single entry's value
   * stay with the part that reads it; checks that need the built state
   * (bodies that start apart under total Lagrangian, a geostatic stress a
   * material cannot carry) stay where that state is made.
   */
  template <int dim>
  void
  check_compatibility(SceneReader &reader, const SceneChoices<dim> &scene);

  /**
   * 'MPM/Anti-locking = automatic' made a choice, before the checks: F-bar
   * when a body's material takes it (Material::particles_take_f_bar():
   * plastic, or nu >= 0.45, but not Johnson-Cook) and the formulation
   * (updated Lagrangian) and particle update (explicit) allow F-bar, none
   * otherwise; what it chose and why in method.anti_locking_reason.
   */
  template <int dim>
  void
  choose_anti_locking(
    MethodSettings                                    &method,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const std::vector<std::string>                    &material_models,
    const std::vector<Body<dim>>                      &bodies);

  /** The uniform acceleration of the effects with a potential at t = 0
   * (gravity; zero without): minus the potential's gradient per unit
   * mass. */
  template <int dim>
  Tensor<1, dim>
  uniform_acceleration(
    const std::vector<std::unique_ptr<Effect<dim>>> &effects);
} // namespace dealmpm
