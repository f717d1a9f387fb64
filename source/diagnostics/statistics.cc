#include <deal.II/base/mpi.h>

#include <dealmpm/diagnostics/statistics.h>

#include <cmath>

namespace dealmpm
{
  namespace
  {
    /** The effect whose exact solution the displacement is measured
     * against (the last that has one), or nullptr. */
    template <int dim>
    const Effect<dim> *
    exact_solution_effect(
      const std::vector<std::unique_ptr<Effect<dim>>> &effects)
    {
      const Effect<dim> *exact = nullptr;
      for (const auto &effect : effects)
        if (effect->has_exact_solution())
          exact = effect.get();
      return exact;
    }

    /** Whether some material dissipates: only then is the dissipated work a
     * column (and worth a call per particle). */
    template <int dim>
    bool
    some_material_dissipates(
      const std::vector<std::unique_ptr<Material<dim>>> &materials)
    {
      bool dissipates = false;
      for (const auto &material : materials)
        dissipates = dissipates || material->dissipates();
      return dissipates;
    }

    /** The sums over the particles and effects, summed over the ranks in
     * one reduction: n, mass, momentum (3), kinetic, strain, gravitational,
     * dissipated work, the mass and momentum (3) effects removed. */
    using Sums = std::array<double, 13>;

    /** Adds the mass and momentum the effects removed to @p sums. */
    template <int dim>
    void
    add_removed(const std::vector<std::unique_ptr<Effect<dim>>> &effects,
                Sums                                            &sums)
    {
      for (const auto &effect : effects)
        {
          sums[9] += effect->removed_mass();
          const Tensor<1, dim> P = effect->removed_momentum();
          for (unsigned int d = 0; d < dim; ++d)
            sums[10 + d] += P[d];
        }
    }

    /** Adds particle @p p's count, mass, momentum and energies to @p sums
     * (its dissipated work only if @p dissipates). */
    template <int dim, typename Particle>
    void
    add_particle(const Particle                                    &p,
                 const ParticleSet<dim>                            &particles,
                 const std::vector<std::unique_ptr<Material<dim>>> &materials,
                 const std::vector<std::unique_ptr<Effect<dim>>>   &effects,
                 const bool                                         dissipates,
                 Sums                                              &sums)
    {
      const CoreFields    &f     = particles.fields;
      const auto           props = p.get_properties();
      const double         m     = props[f.mass];
      const Tensor<1, dim> v     = read_vector<dim>(&props[f.velocity]);
      const unsigned int   mat   = particles.material_of(props);
      sums[0] += 1;
      sums[1] += m;
      for (unsigned int d = 0; d < dim; ++d)
        sums[2 + d] += m * v[d];
      sums[5] += 0.5 * m * v.norm_square();
      sums[6] +=
        props[f.initial_volume] *
        materials[mat]->strain_energy_density(
          read_tensor<dim>(&props[f.deformation_gradient]),
          read_symmetric<dim>(&props[f.stress]),
          ArrayView<const double>(&props[0] + particles.internal_offset[mat],
                                  particles.n_internal[mat]));
      if (dissipates)
        sums[8] +=
          props[f.initial_volume] *
          materials[mat]->dissipated_energy_density(
            ArrayView<const double>(&props[0] + particles.internal_offset[mat],
                                    particles.n_internal[mat]));
      for (const auto &effect : effects)
        sums[7] += effect->potential_energy(m, p.get_location());
    }

    /** The displacement error against an exact solution on this rank: the
     * volume-weighted sum of its squares, the volume, its maximum. */
    struct ErrorSums
    {
      double squared_error = 0, volume = 0, max_error = 0;

      /** Adds particle @p p's error against @p exact at @p time. */
      template <int dim, typename Particle>
      void
      add(const Particle    &p,
          const CoreFields  &f,
          const Effect<dim> &exact,
          const double       time)
      {
        const auto           props = p.get_properties();
        const Tensor<1, dim> u     = read_vector<dim>(&props[f.displacement]);
        const double         error =
          (u - exact.exact_displacement(p.get_location() - u, time)).norm();
        squared_error += props[f.initial_volume] * error * error;
        volume += props[f.initial_volume];
        max_error = std::max(max_error, error);
      }
    };

    /** The statistics of the reduced @p sums. */
    Statistics
    statistics_of(const Sums &sums, const bool dissipates)
    {
      Statistics s;
      s.n_particles          = sums[0];
      s.mass                 = sums[1];
      s.momentum             = {{sums[2], sums[3], sums[4]}};
      s.kinetic_energy       = sums[5];
      s.strain_energy        = sums[6];
      s.gravitational_energy = sums[7];
      s.has_dissipated_work  = dissipates;
      s.dissipated_work      = sums[8];
      s.removed_mass         = sums[9];
      s.removed_momentum     = {{sums[10], sums[11], sums[12]}};
      return s;
    }

    /** The effects' own columns, their values summed over the ranks. */
    template <int dim>
    void
    add_effect_columns(const std::vector<std::unique_ptr<Effect<dim>>> &effects,
                       const MPI_Comm                                   comm,
                       Statistics                                      &s)
    {
      for (const auto &effect : effects)
        for (const auto &[name, value] : effect->statistics_columns())
          {
            s.effect_columns.push_back(name);
            s.effect_values.push_back(value);
          }
      if (!s.effect_values.empty())
        Utilities::MPI::sum(ArrayView<const double>(s.effect_values.data(),
                                                    s.effect_values.size()),
                            comm,
                            ArrayView<double>(s.effect_values.data(),
                                              s.effect_values.size()));
    }
  } // namespace

  template <int dim>
  Statistics
  compute_statistics(
    const BackgroundGrid<dim>                         &grid,
    const ParticleSet<dim>                            &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const std::vector<std::unique_ptr<Effect<dim>>>   &effects,
    const double                                       time,
    const MPI_Comm                                     comm)
  {
    const Effect<dim> *exact = exact_solution_effect(effects);
    Sums               sums{};
    add_removed(effects, sums);
    const bool                dissipates = some_material_dissipates(materials);
    ErrorSums                 error;
    const ParticleOrder<dim> &order = particles.order_over(grid);
    const PoolArrays<dim>     pool(particles.handler.get_property_pool());
    for (const auto handle : order.handles)
      {
        const PooledParticle<dim, true> p(pool, handle);
        add_particle(p, particles, materials, effects, dissipates, sums);
        if (exact != nullptr)
          error.add(p, particles.fields, *exact, time);
      }
    Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()),
                        comm,
                        ArrayView<double>(sums.data(), sums.size()));
    Statistics s = statistics_of(sums, dissipates);
    add_effect_columns(effects, comm, s);
    if (exact != nullptr)
      {
        s.has_error = true;
        s.error_L2  = std::sqrt(Utilities::MPI::sum(error.squared_error, comm) /
                               Utilities::MPI::sum(error.volume, comm));
        s.error_max = Utilities::MPI::max(error.max_error, comm);
      }
    const ParticleBalance balance = particle_balance(particles.handler, comm);
    s.particles_per_rank_min      = balance.min;
    s.particles_per_rank_max      = balance.max;
    s.particles_per_rank_mean     = balance.mean;
    return s;
  }

  template <int dim>
  EnergyGain<dim>
  largest_energy_gain(
    const ParticleSet<dim>                            &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const std::vector<std::unique_ptr<Effect<dim>>>   &effects,
    const std::vector<Tensor<1, dim>>                 &initial_velocity)
  {
    const CoreFields &f = particles.fields;
    EnergyGain<dim>   largest;
    for (const auto &p : particles.handler)
      {
        const auto           props = p.get_properties();
        const double         m     = props[f.mass];
        const unsigned int   mat   = particles.material_of(props);
        const Tensor<1, dim> v     = read_vector<dim>(&props[f.velocity]);
        const Tensor<1, dim> v0    = initial_velocity[particles.body_of(props)];
        const Point<dim>     x     = p.get_location();
        const Point<dim>     X = x - read_vector<dim>(&props[f.displacement]);
        const ArrayView<const double> internal(&props[0] +
                                                 particles.internal_offset[mat],
                                               particles.n_internal[mat]);
        // The plastic work counts as the particle's: the balance closes
        // with it.
        double gain = 0.5 * m * (v.norm_square() - v0.norm_square()) +
                      props[f.initial_volume] *
                        (materials[mat]->strain_energy_density(
                           read_tensor<dim>(&props[f.deformation_gradient]),
                           read_symmetric<dim>(&props[f.stress]),
                           internal) +
                         materials[mat]->dissipated_energy_density(internal));
        for (const auto &effect : effects)
          gain +=
            effect->potential_energy(m, x) - effect->potential_energy(m, X);
        if (gain > largest.gain)
          largest = {gain, p.get_id(), x};
      }
    return largest;
  }

#define DEALMPM_INSTANTIATE(dim)                         \
  template EnergyGain<dim> largest_energy_gain(          \
    const ParticleSet<dim> &,                            \
    const std::vector<std::unique_ptr<Material<dim>>> &, \
    const std::vector<std::unique_ptr<Effect<dim>>> &,   \
    const std::vector<Tensor<1, dim>> &);                \
  template Statistics compute_statistics(                \
    const BackgroundGrid<dim> &,                         \
    const ParticleSet<dim> &,                            \
    const std::vector<std::unique_ptr<Material<dim>>> &, \
    const std::vector<std::unique_ptr<Effect<dim>>> &,   \
    double,                                              \
    MPI_Comm);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE

} // namespace dealmpm
