#include <deal.II/base/mpi.h>

#include <dealmpm/effects/base_shaking.h>
#include <dealmpm/effects/heat_conduction.h>
#include <dealmpm/fem/fem_regions.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <utility>

namespace dealmpm
{
  template <int dim>
  void
  FemRegions<dim>::declare_parameters(ParameterHandler  &prm,
                                      const unsigned int n_regions)
  {
    prm.declare_entry("Number of FEM regions",
                      "0",
                      Patterns::Integer(0, 1000),
                      "How many 'FEM region N' sections the scene has: "
                      "finite element solids beside the MPM bodies.");
    for (unsigned int r = 1; r <= n_regions; ++r)
      {
        prm.enter_subsection("FEM region " + std::to_string(r));
        FemRegionSettings<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
  }

  template <int dim>
  std::function<double(const Point<dim> &)>
  FemRegions<dim>::potential() const
  {
    return [this](const Point<dim> &x) {
      return dealmpm::potential_energy(effects, 1., x);
    };
  }

  template <int dim>
  bool
  FemRegions<dim>::potential_steady_from(const double t) const
  {
    return std::all_of(effects.begin(), effects.end(), [t](const auto &e) {
      return e->potential_steady_from(t);
    });
  }

  template <int dim>
  void
  FemRegions<dim>::make(
    SceneReader                                       &reader,
    const unsigned int                                 n_regions,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const unsigned int                                 n_bodies,
    const BackgroundGrid<dim>                         &grid,
    const bool                                         apic)
  {
    const BaseMotion<dim> *base = nullptr;
    for (const auto &effect : effects)
      if (const auto *shaking = dynamic_cast<BaseShaking<dim> *>(effect.get()))
        base = &shaking->base_motion();
    HeatConduction<dim> *heat = nullptr;
    for (const auto &effect : effects)
      if (auto *h = dynamic_cast<HeatConduction<dim> *>(effect.get()))
        heat = h;
    bool shaken = base && !base->ids.empty();
    for (unsigned int r = 0; r < n_regions; ++r)
      {
        regions.push_back(make_fem_region<dim>(
          reader, r, materials, n_bodies, grid, base, heat));
        shaken |= !regions.back().settings.conditions.shaken.empty();
        if (regions.back().heat)
          heat->add_partner(*regions.back().heat);
      }
    if (base && !shaken)
      {
        SectionScope section(reader, "Base shaking");
        reader.fail("Boundary ids",
                    "at least one boundary id, here or in an FEM region's "
                    "'Shaken boundaries'");
      }
    for (FemRegion<dim> &region : regions)
      region.solid->track_potential(potential(), false);
    for (FemRegion<dim> &region : regions)
      if (region.bonded && apic)
        region.bonded->use_affine();
  }

  template <int dim>
  void
  FemRegions<dim>::compute_forces(const double               time,
                                  const double               dt,
                                  const BackgroundGrid<dim> &grid,
                                  NodalFieldSet<dim>        &fields)
  {
    const BodyForce<dim> body_force = [&](const Point<dim>     &X,
                                          const Point<dim>     &x,
                                          const Tensor<1, dim> &v,
                                          const double          t) {
      Tensor<1, dim> b;
      for (const auto &effect : effects)
        b += effect->body_acceleration(X, x, v, t);
      return b;
    };
    const bool uniform =
      std::all_of(effects.begin(), effects.end(), [](const auto &e) {
        return e->body_acceleration_is_uniform();
      });
    // Where every potential is steady from now on, the nodes' potential
    // is the one the last step ended with: the work it would add is 0.
    const bool potential_steady = potential_steady_from(time);
    for (FemRegion<dim> &region : regions)
      {
        if (!potential_steady)
          region.solid->track_potential(potential(), true);
        region.solid->compute_forces(time, dt, body_force, uniform);
        // The heat conducted with the new F, before the bonded nodes send
        // it to the grid (the effect 'heat conduction' advances it).
        if (region.heat)
          region.heat->conduct(time, dt);
        if (region.bonded)
          region.bonded->deposit(grid, fields);
      }
  }

  template <int dim>
  void
  FemRegions<dim>::update(const double               time,
                          const double               dt,
                          const double               mass_threshold,
                          const BackgroundGrid<dim> &grid,
                          NodalFieldSet<dim>        &fields,
                          const ParticleSet<dim>    &particles,
                          const Stencil<dim>        &stencil)
  {
    for (FemRegion<dim> &region : regions)
      {
        if (region.bonded)
          region.bonded->read_back(grid, fields);
        if (region.contact)
          region.contact->apply(
            grid, fields, particles, stencil, mass_threshold, dt);
        region.solid->advance(time, dt);
        // Only for the next step's change in time (compute_forces()).
        if (!potential_steady_from(time + dt))
          region.solid->track_potential(potential(), false);
      }
  }

  template <int dim>
  double
  FemRegions<dim>::local_signal_rate() const
  {
    double rate = 0;
    for (const FemRegion<dim> &region : regions)
      rate = std::max(rate, region.solid->local_signal_rate());
    return rate;
  }

  template <int dim>
  std::vector<RegionTotals<dim>>
  FemRegions<dim>::totals(const MPI_Comm comm) const
  {
    std::vector<RegionTotals<dim>> all(regions.size());
    for (unsigned int r = 0; r < regions.size(); ++r)
      {
        const SolidRegion<dim> &solid = *regions[r].solid;
        RegionTotals<dim>      &t     = all[r];
        t.mass                        = solid.total_mass();
        t.momentum                    = solid.momentum();
        t.kinetic_energy              = solid.kinetic_energy();
        t.strain_energy               = solid.strain_energy();
        t.gravitational_energy        = solid.potential_energy(potential());
        t.dissipates                  = solid.get_material().dissipates();
        if (t.dissipates)
          t.dissipated_work = solid.dissipated_work();
        // The solid's sums are over the ranks already; the contact's not.
        const std::string prefix = "fem" + std::to_string(r + 1) + "_";
        const double      friction =
          regions[r].contact ?
                 Utilities::MPI::sum(regions[r].contact->friction_work(), comm) :
                 0.;
        for (const auto &[name, value] :
             {std::pair<std::string, double>{"kinetic_energy",
                                             t.kinetic_energy},
              {"strain_energy", t.strain_energy},
              {"gravitational_energy", t.gravitational_energy},
              {"friction_work", friction}})
          {
            t.columns.push_back(prefix + name);
            t.values.push_back(value);
          }
        if (solid.has_supports())
          {
            const Tensor<1, dim> R = solid.mean_support_force();
            for (unsigned int d = 0; d < dim; ++d)
              {
                t.columns.push_back(prefix + "support_force_" +
                                    std::string(1, "xyz"[d]));
                t.values.push_back(R[d]);
              }
          }
      }
    return all;
  }

  template <int dim>
  double
  FemRegions<dim>::external_work() const
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

  template <int dim>
  void
  FemRegions<dim>::start_statistics_row()
  {
    for (FemRegion<dim> &region : regions)
      region.solid->start_statistics_row();
  }

  template <int dim>
  std::string
  FemRegions<dim>::saved_state(const unsigned int r) const
  {
    std::ostringstream text;
    text << regions[r].solid->save_state();
    if (regions[r].contact)
      text << "contact " << std::hexfloat << regions[r].contact->work() << ' '
           << regions[r].contact->friction_work() << '\n';
    return text.str();
  }

  template <int dim>
  void
  FemRegions<dim>::restore_state(const unsigned int              r,
                                 const std::vector<std::string> &parts,
                                 const bool                      root)
  {
    // The contact's work is summed over the ranks that saved it.
    double work = 0, friction = 0;
    for (const std::string &part : parts)
      {
        std::istringstream lines(part);
        std::string        line;
        while (std::getline(lines, line))
          if (line.rfind("contact ", 0) == 0)
            {
              std::istringstream values(line.substr(8));
              std::string        a, b;
              values >> a >> b;
              work += std::strtod(a.c_str(), nullptr);
              friction += std::strtod(b.c_str(), nullptr);
            }
      }
    regions[r].solid->load_state(parts);
    if (regions[r].contact)
      regions[r].contact->restore_work(root ? work : 0., root ? friction : 0.);
    regions[r].solid->track_potential(potential(), false);
  }

  template <int dim>
  void
  FemRegions<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    for (FemRegion<dim> &region : regions)
      {
        if (region.bonded)
          region.bonded->grid_changed(grid);
        if (region.contact)
          region.contact->grid_changed(grid);
      }
  }

  template <int dim>
  void
  FemRegions<dim>::for_each_coupling(
    const std::function<void(NodesOnGrid<dim> &)> &f)
  {
    for (FemRegion<dim> &region : regions)
      {
        if (region.bonded)
          f(region.bonded->nodes_on_grid());
        if (region.contact)
          f(region.contact->nodes_on_grid());
      }
  }

  template <int dim>
  bool
  FemRegions<dim>::coupling_wants_publication()
  {
    bool wanted = false;
    for_each_coupling([&](NodesOnGrid<dim> &points) {
      wanted = wanted || points.publication_wanted();
    });
    return wanted;
  }

  template <int dim>
  void
  FemRegions<dim>::publish_coupling_at_next_step()
  {
    for_each_coupling(
      [](NodesOnGrid<dim> &points) { points.publish_at_next_step(); });
  }

  template <int dim>
  std::string
  FemRegions<dim>::coupling_failure()
  {
    std::string failure;
    for_each_coupling([&](NodesOnGrid<dim> &points) {
      if (failure.empty())
        failure = points.failure();
    });
    return failure;
  }

  template class FemRegions<2>;
  template class FemRegions<3>;
} // namespace dealmpm
