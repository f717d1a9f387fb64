#pragma once

#include <dealmpm/base/scene_reader.h>
#include <dealmpm/effects/effect.h>
#include <dealmpm/materials/material_sections.h>

#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /** Declare "Effects" and the section of every registered effect. */
  template <int dim>
  void
  declare_effect_parameters(ParameterHandler &prm);

  /** The effects a scene lists, in its order, with their names. */
  template <int dim>
  struct EffectList
  {
    std::vector<std::unique_ptr<Effect<dim>>> effects;
    std::vector<std::string>                  names;
  };

  /**
   * Read "Effects" and make each listed effect from its section (the reader
   * at the top level). An effect with a known motion checks that the
   * scene's materials are the neo-Hookean ones its body force is computed
   * for: a different material would give silently wrong error norms.
   * Effects may replace materials (Effect::wrap_materials()).
   */
  template <int dim>
  EffectList<dim>
  read_effects(SceneReader &reader, MaterialSections<dim> &materials);
} // namespace dealmpm
