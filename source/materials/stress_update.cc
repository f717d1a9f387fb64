#include <dealmpm/materials/stress_update.h>

#include <cmath>

namespace dealmpm
{
  namespace
  {
    /** Signal rate of one particle, or record why its state is unusable. */
    template <int dim, typename Accessor>
    inline void
    inspect(const Accessor &               p,
            const Tensor<1, dim> &         v,
            const Tensor<2, dim> &         F,
            const SymmetricTensor<2, dim> &stress,
            const Material<dim> &          material,
            const double                   h,
            ParticleCheck<dim> &           check)
    {
      const double J   = determinant(F);
      double       sum = J + v.norm_square();
      for (unsigned int i = 0; i < SymmetricTensor<2, dim>::n_independent_components; ++i)
        sum += stress.access_raw_entry(i);
      for (unsigned int d = 0; d < dim; ++d)
        sum += p.get_location()[d];
      const char *reason = nullptr;
      if (!std::isfinite(sum))
        reason = "non-finite position, velocity, deformation gradient or stress";
      else if (!(J > 0.))
        reason = "deformation gradient with J <= 0 (the particle turned "
                 "inside out: time step too large or a kernel too weak for "
                 "the deformation)";
      if (reason != nullptr)
        {
          if (!check.failed)
            {
              check.failed   = true;
              check.particle = p.get_id();
              check.location = p.get_location();
              check.reason   = reason;
            }
          return;
        }
      const double rate = (material.wave_speed(F) + v.norm()) / h;
      check.max_signal_rate = std::max(check.max_signal_rate, rate);
    }
  } // namespace

  template <int dim>
  ParticleCheck<dim>
  update_stresses(const BackgroundGrid<dim> &                        grid,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials,
                  const std::vector<Tensor<2, dim>> &velocity_gradient,
                  const double                       dt,
                  ParticleSet<dim> &                 particles)
  {
    ParticleCheck<dim> check;
    const CoreFields & f = particles.fields;
    std::size_t        k = 0;
    for (const GridCell<dim> &c : grid.cells)
      for (auto &p : particles.handler.particles_in_cell(c.cell))
        {
          const ArrayView<double> props = p.get_properties();
          const unsigned int      m     = static_cast<unsigned int>(props[f.material]);
          const Material<dim> &   material = *materials[m];
          SymmetricTensor<2, dim> stress = read_symmetric<dim>(&props[f.stress]);
          material.update_stress(
            velocity_gradient[k],
            read_tensor<dim>(&props[f.deformation_gradient]),
            dt,
            stress,
            ArrayView<double>(&props[0] + particles.internal_offset[m],
                              particles.n_internal[m]));
          write_symmetric<dim>(&props[f.stress], stress);
          inspect(p,
                  read_vector<dim>(&props[f.velocity]),
                  read_tensor<dim>(&props[f.deformation_gradient]),
                  stress,
                  material,
                  c.h,
                  check);
          ++k;
        }
    return check;
  }

  template <int dim>
  ParticleCheck<dim>
  check_particles(const BackgroundGrid<dim> &                        grid,
                  const std::vector<std::unique_ptr<Material<dim>>> &materials,
                  const ParticleSet<dim> &                           particles)
  {
    ParticleCheck<dim> check;
    const CoreFields & f = particles.fields;
    for (const GridCell<dim> &c : grid.cells)
      for (const auto &p : particles.handler.particles_in_cell(c.cell))
        {
          const auto props = p.get_properties();
          inspect(p,
                  read_vector<dim>(&props[f.velocity]),
                  read_tensor<dim>(&props[f.deformation_gradient]),
                  read_symmetric<dim>(&props[f.stress]),
                  *materials[static_cast<unsigned int>(props[f.material])],
                  c.h,
                  check);
        }
    return check;
  }

  template ParticleCheck<2>
  update_stresses(const BackgroundGrid<2> &, const std::vector<std::unique_ptr<Material<2>>> &, const std::vector<Tensor<2, 2>> &, double, ParticleSet<2> &);
  template ParticleCheck<3>
  update_stresses(const BackgroundGrid<3> &, const std::vector<std::unique_ptr<Material<3>>> &, const std::vector<Tensor<2, 3>> &, double, ParticleSet<3> &);
  template ParticleCheck<2>
  check_particles(const BackgroundGrid<2> &, const std::vector<std::unique_ptr<Material<2>>> &, const ParticleSet<2> &);
  template ParticleCheck<3>
  check_particles(const BackgroundGrid<3> &, const std::vector<std::unique_ptr<Material<3>>> &, const ParticleSet<3> &);
} // namespace dealmpm
