#include <dealmpm/materials/cell_size_dependent.h>
#include <dealmpm/schemes/compatibility.h>
#include <dealmpm/transfer/kernel.h>

#include <utility>

namespace dealmpm
{
  namespace
  {
    template <int dim>
    bool
    total_lagrangian(const SceneChoices<dim> &scene)
    {
      return scene.method.formulation == Formulation::total_lagrangian;
    }

    /** An effect with a nodal field per body (contact) needs the updated
     * Lagrangian formulation (total Lagrangian keeps bodies bonded where
     * they share nodes) and the explicit particle update, and no effect
     * that acts on the common velocity, which the bodies' own fields do
     * not see. */
    template <int dim>
    void
    body_fields_rules(SceneReader &reader, const SceneChoices<dim> &scene)
    {
      for (unsigned int e = 0; e < scene.effects.size(); ++e)
        {
          if (!scene.effects[e]->needs_body_fields())
            continue;
          const std::string &name = scene.effect_names[e];
          {
            SectionScope      mpm(reader, "MPM");
            const std::string why = " with '" + name +
                                    "', which gives each body its own "
                                    "nodal fields";
            if (total_lagrangian(scene))
              reader.fail("Formulation",
                          "'updated Lagrangian'" + why +
                            " (total Lagrangian keeps bodies bonded where "
                            "they share grid nodes)");
            if (scene.method.particle_update.newmark)
              reader.fail("Particle update", "'explicit'" + why);
          }
          for (unsigned int other = 0; other < scene.effects.size(); ++other)
            if (scene.effects[other]->changes_core_velocity())
              reader.fail("Effects",
                          "'" + name + "' without '" +
                            scene.effect_names[other] +
                            "': it acts on the grid's common velocity, "
                            "which each body's own does not see yet");
        }
    }

    /** Bonded and contact boundaries of FEM regions take one grid
     * velocity per step: USL, updated Lagrangian, explicit update. */
    template <int dim>
    void
    region_coupling_rule(SceneReader &reader, const SceneChoices<dim> &scene)
    {
      const MethodSettings &method = scene.method;
      if (method.scheme == UpdateScheme::USL &&
          !method.particle_update.newmark && !total_lagrangian(scene))
        return;
      for (unsigned int r = 1; r <= scene.n_fem_regions; ++r)
        {
          SectionScope section(reader, "FEM region " + std::to_string(r));
          for (const std::string entry :
               {"Bonded boundaries", "Contact boundaries"})
            if (!Utilities::trim(reader.get(entry)).empty())
              reader.fail(entry,
                          "none unless 'MPM/Stress update = USL' with the "
                          "updated Lagrangian formulation and the explicit "
                          "particle update (the bonded nodes take one grid "
                          "velocity per step)");
        }
    }

    /** Total Lagrangian keeps every particle's neighbours; a fluid's
     * particles flow past theirs. */
    template <int dim>
    void
    total_lagrangian_rule(SceneReader &reader, const SceneChoices<dim> &scene)
    {
      if (!total_lagrangian(scene))
        return;
      SectionScope mpm(reader, "MPM");
      for (unsigned int m = 0; m < scene.materials.size(); ++m)
        if (scene.materials[m]->resets_deformation())
          reader.fail(
            "Formulation",
            "'updated Lagrangian' for a scene with a fluid ('Material " +
              std::to_string(m + 1) + "' is a '" + scene.material_models[m] +
              "', whose particles flow past their neighbours; total "
              "Lagrangian keeps every particle's neighbours)");
    }

    /** F-bar averages the step's volume change over the particles a cell
     * holds now: the updated Lagrangian sweeps, and not Newmark's. */
    template <int dim>
    void
    anti_locking_rule(SceneReader &reader, const SceneChoices<dim> &scene)
    {
      if (scene.method.anti_locking == AntiLocking::none)
        return;
      SectionScope mpm(reader, "MPM");
      if (total_lagrangian(scene))
        reader.fail("Anti-locking",
                    "'none' or 'automatic' under 'MPM/Formulation = total "
                    "Lagrangian' (F "
                    "advances there from the reference cell's gradient, and "
                    "an F-bar would have to average the total volume change "
                    "over the reference cell: not built)");
      if (scene.method.particle_update.newmark)
        reader.fail("Anti-locking",
                    "'none' or 'automatic' with 'MPM/Particle update = "
                    "Newmark' (not built)");
    }

    /** Refined cells make hanging nodes and move particles between
     * cells of other sizes. */
    template <int dim>
    void
    adaptivity_rules(SceneReader &reader, const SceneChoices<dim> &scene)
    {
      if (!scene.adaptivity.enabled())
        return;
      SectionScope section(reader, "Adaptivity");
      if (total_lagrangian(scene))
        reader.fail("Criteria",
                    "none under 'MPM/Formulation = total Lagrangian' (its "
                    "stencil belongs to the grid it starts on)");
      const auto        &shapes = shape_function_registry<dim>();
      const std::string &shape  = scene.method.shape_function;
      if (shapes.has(shape) && shapes.get(shape).create()->needs_uniform_grid())
        reader.fail("Criteria",
                    "none with 'MPM/Shape function = " + shape +
                      "', which needs a uniform grid (refined cells make "
                      "hanging nodes): use linear, uGIMP, cpGIMP or CPDI");
      // A surface particle's area is neither shared by its parts nor an
      // average of its group's.
      for (unsigned int e = 0; e < scene.effects.size(); ++e)
        if (!scene.effects[e]->particle_fields().empty())
          for (const auto &[asked, entry] :
               {std::pair{scene.adaptivity.split, "Split particles"},
                std::pair{scene.adaptivity.merge, "Merge particles"}})
            if (asked)
              reader.fail(entry,
                          "false with '" + scene.effect_names[e] +
                            "', whose particle fields (a surface particle's "
                            "area) cannot be shared or averaged");
    }

    /** A geostatic start needs a uniform force field and a reference
     * configuration that is stress-free. */
    template <int dim>
    void
    geostatic_rules(SceneReader &reader, const SceneChoices<dim> &scene)
    {
      const Tensor<1, dim> g = uniform_acceleration(scene.effects);
      for (unsigned int b = 0; b < scene.bodies.size(); ++b)
        {
          if (!scene.bodies[b].geostatic)
            continue;
          SectionScope section(reader, "Body " + std::to_string(b + 1));
          if (!(g.norm() > 0))
            reader.fail("Initial stress",
                        "'none' in a scene without gravity (no listed "
                        "effect has a uniform force field at t = 0; a "
                        "gravity ramp starts from none)");
          // Total Lagrangian's stencil is taken where F = I; a body filled
          // at rest under stress has no such configuration on record.
          if (total_lagrangian(scene))
            reader.fail("Initial stress",
                        "'none' under 'MPM/Formulation = total Lagrangian' "
                        "(its reference configuration is the stress-free "
                        "one)");
        }
    }

    /** A regularised softening scales with one cell size, the grid's
     * smallest edge at set-up: not a grid that changes, not an FEM
     * region's cells. */
    template <int dim>
    void
    cell_size_rule(SceneReader &reader, const SceneChoices<dim> &scene)
    {
      for (unsigned int m = 0; m < scene.materials.size(); ++m)
        {
          if (needing_cell_size(*scene.materials[m]) == nullptr)
            continue;
          const std::string material = "Material " + std::to_string(m + 1);
          const auto        refuse   = [&](const std::string &why) {
            SectionScope section(reader, material);
            SectionScope model(reader, scene.material_models[m]);
            reader.fail("Regularisation length", "0 " + why);
          };
          if (scene.adaptivity.enabled())
            refuse("with adaptivity (it scales the softening with one cell "
                   "size, the grid's smallest at set-up)");
          for (unsigned int r = 1; r <= scene.n_fem_regions; ++r)
            {
              long used = 0;
              {
                SectionScope region(reader, "FEM region " + std::to_string(r));
                used = reader.get_integer("Material");
              }
              if (used == m + 1)
                refuse("in a material an FEM region uses ('FEM region " +
                       std::to_string(r) +
                       "': it scales with the background grid's cells; "
                       "give the region a material of its own)");
            }
        }
    }
  } // namespace

  template <int dim>
  void
  check_compatibility(SceneReader &reader, const SceneChoices<dim> &scene)
  {
    geostatic_rules(reader, scene);
    adaptivity_rules(reader, scene);
    body_fields_rules(reader, scene);
    region_coupling_rule(reader, scene);
    total_lagrangian_rule(reader, scene);
    anti_locking_rule(reader, scene);
    cell_size_rule(reader, scene);
  }

  template <int dim>
  Tensor<1, dim>
  uniform_acceleration(const std::vector<std::unique_ptr<Effect<dim>>> &effects)
  {
    Tensor<1, dim> g;
    for (const auto &effect : effects)
      for (unsigned int d = 0; d < dim; ++d)
        g[d] -= effect->potential_energy(1., Point<dim>::unit_vector(d)) -
                effect->potential_energy(1., Point<dim>());
    return g;
  }

  template <int dim>
  void
  choose_anti_locking(
    MethodSettings                                    &method,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const std::vector<std::string>                    &material_models,
    const std::vector<Body<dim>>                      &bodies)
  {
    if (method.anti_locking != AntiLocking::automatic)
      return;
    method.anti_locking = AntiLocking::none;
    if (method.formulation != Formulation::updated_lagrangian ||
        method.particle_update.newmark)
      return;
    const auto named = [&](const unsigned int material) {
      return "Material " + std::to_string(material + 1) + " (" +
             material_models[material] + ")";
    };
    for (const Body<dim> &body : bodies)
      if (materials[body.material]->particles_take_f_bar())
        {
          method.anti_locking        = AntiLocking::f_bar;
          method.anti_locking_reason = "anti-locking F-bar ('MPM/Anti-locking "
                                       "= automatic': " +
                                       named(body.material) +
                                       " locks in linear cells without it)";
          return;
        }
    for (const Body<dim> &body : bodies)
      if (materials[body.material]->locks_in_linear_cells())
        {
          method.anti_locking_reason =
            "anti-locking none ('MPM/Anti-locking = automatic': " +
            named(body.material) +
            " locks in linear cells, but its measured cases gain nothing "
            "from F-bar; 'MPM/Anti-locking = F-bar' applies it)";
          return;
        }
  }

#define DEALMPM_INSTANTIATE(dim)                                               \
  template void check_compatibility(SceneReader &, const SceneChoices<dim> &); \
  template void choose_anti_locking(                                           \
    MethodSettings &,                                                          \
    const std::vector<std::unique_ptr<Material<dim>>> &,                       \
    const std::vector<std::string> &,                                          \
    const std::vector<Body<dim>> &);                                           \
  template Tensor<1, dim> uniform_acceleration(                                \
    const std::vector<std::unique_ptr<Effect<dim>>> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
