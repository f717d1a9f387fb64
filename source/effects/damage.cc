#include <deal.II/base/mpi.h>

#include <dealmpm/effects/damage.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>

namespace dealmpm
{
  template <int dim>
  Damage<dim>::Damage(const Settings &settings)
    : settings(settings)
    , eroded(eroded_momentum + dim, 0.)
  {}

  template <int dim>
  void
  Damage<dim>::wrap_materials(MaterialSections<dim> &sections,
                              SceneReader           &reader)
  {
    const unsigned int n = sections.materials.size();
    for (const unsigned int m : settings.materials)
      if (m >= n)
        reader.fail("Materials",
                    "material numbers from 1 to the scene's 'Number of "
                    "materials' (" +
                      std::to_string(n) + "), not " + std::to_string(m + 1));
    damaged.assign(n, nullptr);
    // Each damaged model keeps its own block of internal variables.
    std::vector<std::string> models;
    for (unsigned int m = 0; m < n; ++m)
      {
        if (!settings.materials.empty() && settings.materials.count(m) == 0)
          continue;
        const std::string model = sections.models[m] + " with damage";
        unsigned int      k     = 0;
        while (k < models.size() && models[k] != model)
          ++k;
        if (k == models.size())
          models.push_back(model);
        auto wrapped = std::make_unique<DamagedMaterial<dim>>(
          std::move(sections.materials[m]),
          settings.law,
          k == 0 ? "" : "_" + std::to_string(k + 1));
        damaged[m]            = wrapped.get();
        sections.materials[m] = std::move(wrapped);
        sections.models[m]    = model;
      }
  }

  template <int dim>
  void
  Damage<dim>::after_g2p(const EffectContext<dim> &state,
                         ParticleSet<dim>         &particles)
  {
    unsigned int newly_failed = 0;
    for (const DamagedMaterial<dim> *material : damaged)
      if (material != nullptr)
        newly_failed += material->take_newly_failed();
    if (!settings.erode)
      {
        failed_kept += newly_failed;
        return;
      }
    // remove_particles() updates the handler's global counts, a collective
    // call: every rank makes it, or none; and only in steps where some
    // particle failed is there a sweep.
    if (!Utilities::MPI::logical_or(newly_failed > 0, state.grid.comm))
      return;
    const CoreFields &f = particles.fields;
    // Summed in the step's order (not deal.II's lists'), removed by id.
    std::vector<types::particle_index> failed_ids;
    for_each_particle_in_stencil_order(
      state.grid,
      particles,
      [&](const std::size_t, const auto &p, const GridCell<dim> &) {
        const auto                  props    = p.get_properties();
        const unsigned int          m        = particles.material_of(props);
        const DamagedMaterial<dim> *material = damaged[m];
        if (material == nullptr ||
            props[particles.internal_offset[m] + material->damage_index()] < 1.)
          return;
        const double                  mass = props[f.mass];
        const Tensor<1, dim>          v = read_vector<dim>(&props[f.velocity]);
        const ArrayView<const double> internal(
          &props[particles.internal_offset[m]], particles.n_internal[m]);
        eroded[eroded_particles] += 1;
        eroded[eroded_mass] += mass;
        // Its strain energy is (1 - D) = 0 times the model's.
        eroded[eroded_energy] +=
          0.5 * mass * v.norm_square() +
          state.potential_energy(mass, p.get_location()) +
          props[f.initial_volume] *
            material->dissipated_energy_density(internal);
        for (unsigned int d = 0; d < dim; ++d)
          eroded[eroded_momentum + d] += mass * v[d];
        failed_ids.push_back(p.get_id());
      });
    std::sort(failed_ids.begin(), failed_ids.end());
    std::vector<typename Particles::ParticleHandler<dim>::particle_iterator>
      failed;
    for (auto p = particles.handler.begin(); p != particles.handler.end(); ++p)
      if (std::binary_search(failed_ids.begin(), failed_ids.end(), p->get_id()))
        failed.push_back(p);
    particles.handler.remove_particles(failed);
    particles.changed();
  }

  template <int dim>
  std::vector<std::pair<std::string, double>>
  Damage<dim>::statistics_columns() const
  {
    const char                                 *axes[]  = {"x", "y", "z"};
    std::vector<std::pair<std::string, double>> columns = {
      {"failed_particles", failed_kept},
      {"eroded_particles", eroded[eroded_particles]},
      {"eroded_mass", eroded[eroded_mass]},
      {"eroded_energy", eroded[eroded_energy]}};
    for (unsigned int d = 0; d < dim; ++d)
      columns.emplace_back(std::string("eroded_momentum_") + axes[d],
                           eroded[eroded_momentum + d]);
    return columns;
  }

  template <int dim>
  void
  add_damage_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "damage",
      "materials that fail at a strain or stress threshold, softening to "
      "no stress; failed particles removed or kept (section Damage: "
      "Materials, Measure, Onset, Failure, Failed particles).",
      [](ParameterHandler &prm) {
        prm.declare_entry("Materials",
                          "",
                          Patterns::List(Patterns::Integer(1)),
                          "The materials that fail, e.g. '1, 3' (empty: "
                          "all).");
        prm.declare_entry(
          "Measure",
          "principal strain",
          Patterns::Selection("principal strain|principal stress"),
          "What fails the material: 'principal strain' (the largest "
          "principal stretch - 1, tension) or 'principal stress' (the "
          "largest principal effective stress, Pa, out-of-plane included).");
        prm.declare_entry("Onset",
                          "0.1",
                          Patterns::Double(),
                          "The measure where damage D starts to grow.");
        prm.declare_entry("Failure",
                          "0.1",
                          Patterns::Double(),
                          "The measure where D reaches 1 (>= Onset; equal: "
                          "brittle). Between the two D grows linearly and "
                          "never heals; the stress is (1 - D) times the "
                          "model's.");
        prm.declare_entry("Failed particles",
                          "remove",
                          Patterns::Selection("remove|keep"),
                          "What becomes of a particle at D = 1: 'remove' "
                          "(erosion: the statistics count what it carried) "
                          "or 'keep' (stress-free; mass and momentum stay).");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        typename Damage<dim>::Settings s;
        for (const double m : reader.get_doubles("Materials"))
          s.materials.insert(static_cast<unsigned int>(m) - 1);
        s.law.measure = reader.get("Measure") == "principal stress" ?
                          DamageLaw::Measure::principal_stress :
                          DamageLaw::Measure::principal_strain;
        s.law.onset   = reader.get_double("Onset");
        s.law.failure = reader.get_double("Failure");
        if (s.law.measure == DamageLaw::Measure::principal_strain &&
            !(s.law.onset > 0))
          reader.fail("Onset", "a strain > 0 (a tension that fails)");
        if (!(s.law.failure >= s.law.onset))
          reader.fail("Failure",
                      "a value >= 'Onset' (" + reader.get("Onset") + ")");
        s.erode = reader.get("Failed particles") == "remove";
        return std::make_unique<Damage<dim>>(s);
      });
  }

  template class Damage<2>;
  template class Damage<3>;
  template void
  add_damage_effect(Registry<Effect<2>> &);
  template void
  add_damage_effect(Registry<Effect<3>> &);
} // namespace dealmpm
