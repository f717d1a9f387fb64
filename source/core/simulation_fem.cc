// The simulation's FEM regions: made from the scene, in the time step,
// the statistics and the energy balance.
#include <deal.II/base/mpi.h>

#include <dealmpm/core/simulation.h>
#include <dealmpm/io/output_file.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
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
    for (FemRegion<dim> &region : regions)
      region.solid->track_potential(
        [this](const Point<dim> &x) {
          return dealmpm::potential_energy(effects, 1., x);
        },
        false);
    for (FemRegion<dim> &region : regions)
      if (region.bonded && run_settings.method.apic)
        region.bonded->use_affine();
    for (const FemRegion<dim> &region : regions)
      {
        if (!region.bonded && !region.contact)
          continue;
        SectionScope      section(reader, region.name);
        const std::string entry =
          region.bonded ? "Bonded boundaries" : "Contact boundaries";
        const MethodSettings &method = run_settings.method;
        if (method.scheme != UpdateScheme::USL ||
            method.particle_update.newmark || total_lagrangian())
          reader.fail(entry,
                      "none unless 'MPM/Stress update = USL' with the "
                      "updated Lagrangian formulation and the explicit "
                      "particle update (the bonded nodes take one grid "
                      "velocity per step)");
      }
  }

  namespace
  {
    std::string
    region_file(const std::string &folder,
                const unsigned int region,
                const unsigned int rank)
    {
      return folder + "/fem_region_" + std::to_string(region + 1) + "." +
             std::to_string(rank) + ".txt";
    }
  } // namespace

  template <int dim>
  void
  Simulation<dim>::save_fem_regions(const std::string &folder) const
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    std::string        problem;
    for (unsigned int r = 0; r < regions.size(); ++r)
      {
        std::ostringstream text;
        text << regions[r].solid->save_state();
        if (regions[r].contact)
          text << "contact " << std::hexfloat << regions[r].contact->work()
               << ' ' << regions[r].contact->friction_work() << '\n';
        try
          {
            OutputFile file(region_file(folder, r, rank));
            file.write(text.str());
            file.commit();
          }
        catch (const OutputError &e)
          {
            problem = e.what();
          }
      }
    agree_on_output_error(problem, "", comm);
  }

  template <int dim>
  void
  Simulation<dim>::restore_fem_regions(const CheckpointInfo &saved)
  {
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    for (unsigned int r = 0; r < regions.size(); ++r)
      {
        std::vector<std::string> parts;
        double                   work = 0, friction = 0;
        for (unsigned int rank = 0; rank < saved.n_ranks; ++rank)
          {
            const std::string file = region_file(resumed_checkpoint, r, rank);
            std::ifstream     in(file);
            if (!in)
              throw InputError(file +
                               ": cannot be read (the checkpoint "
                               "has no state of " +
                               regions[r].name + ")");
            std::ostringstream text;
            text << in.rdbuf();
            parts.push_back(text.str());
            std::istringstream lines(parts.back());
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
          regions[r].contact->restore_work(root ? work : 0.,
                                           root ? friction : 0.);
        regions[r].solid->track_potential(
          [this](const Point<dim> &x) {
            return dealmpm::potential_energy(effects, 1., x);
          },
          false);
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
        if (solid.has_supports())
          {
            const Tensor<1, dim> R = solid.mean_support_force();
            for (unsigned int d = 0; d < dim; ++d)
              {
                s.effect_columns.push_back(prefix + "support_force_" +
                                           std::string(1, "xyz"[d]));
                s.effect_values.push_back(R[d]);
              }
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

#define DEALMPM_INSTANTIATE(dim)                                                \
  template void   Simulation<dim>::create_fem_regions(SceneReader &,            \
                                                    const SceneShape &);      \
  template double Simulation<dim>::fem_signal_rate() const;                     \
  template void   Simulation<dim>::add_fem_statistics(Statistics &) const;      \
  template double Simulation<dim>::fem_external_work() const;                   \
  template void   Simulation<dim>::save_fem_regions(const std::string &) const; \
  template void   Simulation<dim>::restore_fem_regions(const CheckpointInfo &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
