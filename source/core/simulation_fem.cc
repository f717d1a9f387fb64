// The simulation's FEM regions: made from the scene, in the time step,
// the statistics and the energy balance.
#include <deal.II/base/mpi.h>

#include <dealmpm/core/simulation.h>

#include <algorithm>
#include <string>
#include <utility>

namespace dealmpm
{
  template <int dim>
  void
  Simulation<dim>::create_fem_regions(SceneReader      &reader,
                                      const SceneShape &shape)
  {
    for (unsigned int r = 0; r < shape.n_fem_regions; ++r)
      regions.push_back(make_fem_region<dim>(
        reader, r, materials, static_cast<unsigned int>(bodies.size()), grid));
    if (regions.empty())
      return;
    CheckpointSettings &checkpoint = run_settings.checkpoint;
    if (checkpoint.step_interval > 0 || checkpoint.wall_interval > 0)
      {
        SectionScope section(reader, "Checkpoint");
        reader.fail(checkpoint.step_interval > 0 ?
                      "Steps between checkpoints" :
                      "Seconds between checkpoints",
                    "0 in a scene with FEM regions (their state is not "
                    "saved in checkpoints yet)");
      }
    checkpoint.on_stop_signal = false;
    for (FemRegion<dim> &region : regions)
      region.solid->track_potential(
        [this](const Point<dim> &x) {
          return dealmpm::potential_energy(effects, 1., x);
        },
        false);
    for (const FemRegion<dim> &region : regions)
      {
        if (!region.bonded && !region.contact)
          continue;
        SectionScope      section(reader, region.name);
        const std::string entry =
          region.bonded ? "Bonded boundaries" : "Contact boundaries";
        const MethodSettings &method = run_settings.method;
        if (region.contact && nodal.has_body_fields())
          reader.fail("Contact boundaries",
                      "none in a scene with per-body fields ('frictional "
                      "contact' between MPM bodies): the region meets the "
                      "MPM material as one field yet");
        if (method.scheme != UpdateScheme::USL ||
            method.particle_update.newmark || total_lagrangian())
          reader.fail(entry,
                      "none unless 'MPM/Stress update = USL' with the "
                      "updated Lagrangian formulation and the explicit "
                      "particle update (the bonded nodes take one grid "
                      "velocity per step)");
      }
  }

  template <int dim>
  double
  Simulation<dim>::fem_signal_rate() const
  {
    double rate = 0;
    for (const FemRegion<dim> &region : regions)
      rate = std::max(rate, region.solid->signal_rate());
    return rate;
  }

  template <int dim>
  void
  Simulation<dim>::add_fem_statistics(Statistics &s) const
  {
    for (unsigned int r = 0; r < regions.size(); ++r)
      {
        const SolidRegion<dim> &solid   = *regions[r].solid;
        const double            mass    = solid.total_mass();
        const Tensor<1, dim>    p       = solid.momentum();
        const double            kinetic = solid.kinetic_energy();
        const double            strain  = solid.strain_energy();
        const double            potential =
          solid.potential_energy([this](const Point<dim> &x) {
            return dealmpm::potential_energy(effects, 1., x);
          });
        s.mass += mass;
        for (unsigned int d = 0; d < dim; ++d)
          s.momentum[d] += p[d];
        s.kinetic_energy += kinetic;
        s.strain_energy += strain;
        s.gravitational_energy += potential;
        if (solid.get_material().dissipates())
          {
            s.has_dissipated_work = true;
            s.dissipated_work += solid.dissipated_work();
          }
        // Already sums over the ranks.
        const std::string prefix = "fem" + std::to_string(r + 1) + "_";
        const double      friction =
          regions[r].contact ?
                 Utilities::MPI::sum(regions[r].contact->friction_work(), comm) :
                 0.;
        for (const auto &[name, value] :
             {std::pair<std::string, double>{"kinetic_energy", kinetic},
              {"strain_energy", strain},
              {"gravitational_energy", potential},
              {"friction_work", friction}})
          {
            s.effect_columns.push_back(prefix + name);
            s.effect_values.push_back(value);
          }
      }
  }

  template <int dim>
  double
  Simulation<dim>::fem_external_work() const
  {
    double work = 0;
    for (const FemRegion<dim> &region : regions)
      {
        work += region.solid->external_work();
        if (region.contact)
          work += region.contact->work();
      }
    return work;
  }

#define DEALMPM_INSTANTIATE(dim)                                           \
  template void   Simulation<dim>::create_fem_regions(SceneReader &,       \
                                                    const SceneShape &); \
  template double Simulation<dim>::fem_signal_rate() const;                \
  template void   Simulation<dim>::add_fem_statistics(Statistics &) const; \
  template double Simulation<dim>::fem_external_work() const;
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
