#pragma once

#include <deal.II/base/parameter_handler.h>

#include <dealmpm/core/simulation.h>
#include <dealmpm/fem/solid_region.h>

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>

namespace dealmpm::test
{
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
} // namespace dealmpm::test
