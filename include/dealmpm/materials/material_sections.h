#pragma once

#include <dealmpm/base/scene_reader.h>
#include <dealmpm/materials/material.h>

#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /** Declare the sections "Material 1" ... "Material n": a model from the
   * registry, its density, and each model's parameters in a subsection
   * named after it. */
  template <int dim>
  void
  declare_material_sections(ParameterHandler &prm, const unsigned int n);

  /** The scene's materials, in order. */
  template <int dim>
  struct MaterialSections
  {
    std::vector<std::unique_ptr<Material<dim>>> materials;
    /** The model each was made from ("neo-Hookean", ...). */
    std::vector<std::string> models;
  };

  /** Read "Material 1" ... "Material n" (the reader at the top level). */
  template <int dim>
  MaterialSections<dim>
  read_material_sections(SceneReader &reader, const unsigned int n);
} // namespace dealmpm
