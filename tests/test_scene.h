#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <dealmpm/core/simulation.h>
#include <dealmpm/fem/solid_region.h>

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

namespace dealmpm::test
{
  /** The curved mesh: the unit box's interior points moved by a smooth
   * map, so that no cell is a parallelogram. */
  template <int dim>
  void
  make_curved_mesh(Triangulation<dim> &tria, const unsigned int cells)
  {
    std::vector<unsigned int> repetitions(dim, cells);
    repetitions[0] = cells + 1;
    Point<dim> upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = 1.;
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              repetitions,
                                              Point<dim>(),
                                              upper);
    GridTools::transform(
      [](const Point<dim> &x) {
        Point<dim> y = x;
        for (unsigned int d = 0; d < dim; ++d)
          y[d] += 0.08 * std::sin(3. * x[(d + 1) % dim] + d) * x[d];
        return y;
      },
      tria);
  }

  /** A Simulation from scene text, quiet (no progress line, no output). */
  template <int dim>
  std::unique_ptr<Simulation<dim>>
  make_simulation(const std::string &text,
                  const unsigned int n_bodies      = 1,
                  const unsigned int n_materials   = 1,
                  const unsigned int n_fem_regions = 0)
  {
    SceneShape shape;
    shape.dim           = dim;
    shape.n_bodies      = n_bodies;
    shape.n_materials   = n_materials;
    shape.n_fem_regions = n_fem_regions;
    ParameterHandler prm;
    Simulation<dim>::declare_parameters(prm, shape);
    prm.parse_input_from_string(text);
    return std::make_unique<Simulation<dim>>(prm,
                                             "test.prm",
                                             shape,
                                             MPI_COMM_WORLD);
  }

  /** Advance to time @p end (the last step shortened to land on it). */
  template <int dim>
  Statistics
  run_to(Simulation<dim> &simulation, const double end)
  {
    while (simulation.time() < end - 1e-12)
      simulation.advance(
        std::min(simulation.time_step(), end - simulation.time()));
    return simulation.statistics();
  }

  /** An effect's statistics column by name (a test failure if none). */
  /** The 3 x 3 Kirchhoff stress J sigma of a particle of @p simulation
   * (sigma_zz from its material in 2D). */
  template <int dim, class Particle>
  SymmetricTensor<2, 3>
  kirchhoff_stress(Simulation<dim> &simulation, const Particle &particle)
  {
    const ParticleSet<dim> &particles = simulation.particle_set();
    const auto              props     = particle.get_properties();
    const unsigned int      m         = particles.material_of(props);
    const auto              F =
      read_tensor<dim>(&props[particles.fields.deformation_gradient]);
    const ArrayView<const double> internal(&props[0] +
                                             particles.internal_offset[m],
                                           particles.n_internal[m]);
    return determinant(F) * full_stress<dim>(simulation.material(m),
                                             F,
                                             read_symmetric<dim>(
                                               &props[particles.fields.stress]),
                                             internal);
  }

  inline double
  effect_column(const Statistics &s, const std::string &name)
  {
    for (unsigned int c = 0; c < s.effect_columns.size(); ++c)
      if (s.effect_columns[c] == name)
        return s.effect_values[c];
    ADD_FAILURE() << "no statistics column " << name;
    return 0;
  }

  /** Mean sigma_xx of an FE region's cells with centre x in (a, b), over
   * all ranks. */
  inline double
  region_stress(const SolidRegion<2> &region, const double a, const double b)
  {
    std::vector<SymmetricTensor<2, 3>> stress;
    std::vector<double>                von_mises;
    std::vector<std::vector<double>>   internal;
    region.cell_means(stress, von_mises, internal);
    double      sum = 0, n = 0;
    std::size_t c = 0;
    for (const auto &cell : region.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (cell->center()[0] > a && cell->center()[0] < b)
            {
              sum += stress[c][0][0];
              n += 1;
            }
          ++c;
        }
    sum = Utilities::MPI::sum(sum, MPI_COMM_WORLD);
    n   = Utilities::MPI::sum(n, MPI_COMM_WORLD);
    EXPECT_GT(n, 0);
    return sum / n;
  }

  /** Move every particle to a random point of its cell. */
  template <int dim>
  void
  scatter_particles_in_cells(Simulation<dim> &simulation, std::mt19937 &rng)
  {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto &c : simulation.background_grid().cells)
      for (auto &p :
           simulation.particle_set().handler.particles_in_cell(c.cell))
        {
          Point<dim> xi;
          for (unsigned int d = 0; d < dim; ++d)
            xi[d] = unit(rng);
          p.set_reference_location(xi);
          p.set_location(c.real_point(xi));
        }
  }

  /** Each particle's location, reference location and properties. */
  template <int dim>
  std::vector<double>
  particle_state(const ParticleSet<dim> &particles)
  {
    std::vector<double> state;
    for (const auto &p : particles.handler)
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            state.push_back(p.get_location()[d]);
            state.push_back(p.get_reference_location()[d]);
          }
        for (const double value : p.get_properties())
          state.push_back(value);
      }
    return state;
  }

  /** Put back a state particle_state() took. */
  template <int dim>
  void
  set_particle_state(ParticleSet<dim> &particles, const std::vector<double> &s)
  {
    std::size_t i = 0;
    for (auto &p : particles.handler)
      {
        Point<dim> x, xi;
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d]  = s[i++];
            xi[d] = s[i++];
          }
        p.set_location(x);
        p.set_reference_location(xi);
        for (double &value : p.get_properties())
          value = s[i++];
      }
  }

  /** Random mass (+-50 %), velocity, stress (+-@p stress) and F (I +-0.1)
   * on the particles; random nodal velocity, increment and light-node
   * weight (0 to 1) on the grid. */
  template <int dim>
  void
  randomize_state(ParticleSet<dim>          &particles,
                  const BackgroundGrid<dim> &grid,
                  NodalFields<dim>          &fields,
                  std::mt19937              &rng,
                  const double               stress = 100.)
  {
    std::uniform_real_distribution<double> r(-1., 1.);
    const CoreFields                      &f = particles.fields;
    for (auto &p : particles.handler)
      {
        auto props = p.get_properties();
        props[f.mass] += 0.5 * r(rng) * props[f.mass];
        for (unsigned int d = 0; d < dim; ++d)
          props[f.velocity + d] = r(rng);
        for (unsigned int i = 0;
             i < SymmetricTensor<2, dim>::n_independent_components;
             ++i)
          props[f.stress + i] = stress * r(rng);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            props[f.deformation_gradient + i * dim + j] =
              (i == j ? 1. : 0.) + 0.1 * r(rng);
        // APIC's B = sum N v (x) (x_i - x_p): of order v h.
        if (f.affine_velocity != numbers::invalid_unsigned_int)
          for (unsigned int i = 0; i < dim * dim; ++i)
            props[f.affine_velocity + i] = 0.1 * r(rng);
      }
    fields.increment_weight.reinit(grid.partitioner);
    for (unsigned int i = 0; i < fields.mass.locally_owned_size() +
                                   grid.partitioner->n_ghost_indices();
         ++i)
      {
        fields.increment_weight.local_element(i) = 0.5 + 0.5 * r(rng);
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields.velocity[d].local_element(i)           = r(rng);
            fields.velocity_increment[d].local_element(i) = 0.1 * r(rng);
          }
      }
    fields.has_light_nodes = true;
  }
} // namespace dealmpm::test
