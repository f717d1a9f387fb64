// A finite element solid region alone (issue 15's first check): the
// axially vibrating bar, fixed at x = 0 and free at x = L, started in its
// first mode v(x, 0) = v0 sin(pi x / 2L), moves as v0 cos(w t) sin(pi x /
// 2L), w = pi c / 2L, c = sqrt(E / rho) (nu = 0: no lateral coupling).
// The free end's velocity over one period converges with h (second order)
// and with the degree k; after a period the energy is back (central
// differences conserve it to O(dt^2)); the lumped mass is the bar's.
//
// The region's force loop against a plain FEValues assembly of
// f_i = -int P(F) : grad N_i dV on curved (non-affine) cells, FE_Q(1) and
// FE_Q(2), 2D and 3D; and its signal rate against the rate recomputed
// from the cells' F.
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <dealmpm/base/smallest_stretch.h>
#include <dealmpm/fem/solid_region.h>
#include <dealmpm/materials/linear_elastic.h>
#include <dealmpm/materials/neo_hookean.h>

#include <gtest/gtest.h>

#include <cmath>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double L = 1, E = 100, rho = 1, v0 = 1e-3;

  class FirstMode : public Function<2>
  {
  public:
    FirstMode()
      : Function<2>(2)
    {}
    double
    value(const Point<2> &x, const unsigned int component) const override
    {
      return component == 0 ? v0 * std::sin(M_PI * x[0] / (2 * L)) : 0.;
    }
  };

  struct BarResult
  {
    double error; ///< largest |v_end - exact| over a period, / v0
    double drift; ///< |E(T) - E(0)| / E(0) after one period
    double mass;  ///< lumped mass over rho L H
  };

  BarResult
  vibrating_bar(const unsigned int cells, const unsigned int degree)
  {
    LinearElastic<2> material(LameParameters{0., E / 2.});
    material.density = rho;
    SolidRegion<2> region(MPI_COMM_WORLD, material, degree);
    const double   H = L / cells;
    GridGenerator::subdivided_hyper_rectangle(region.get_triangulation(),
                                              {cells, 1},
                                              Point<2>(0, 0),
                                              Point<2>(L, H),
                                              true);
    region.setup({0});
    region.set_velocity(FirstMode());
    const double c = std::sqrt(E / rho), w = M_PI * c / (2 * L);
    const double dt     = region.stable_time_step(0.2);
    const double period = 2 * M_PI / w;
    BarResult    result{0, 0, 0};
    double       mass = 0;
    for (unsigned int i = 0; i < region.get_mass().locally_owned_size(); ++i)
      mass += region.get_mass().local_element(i);
    result.mass = Utilities::MPI::sum(mass, MPI_COMM_WORLD) / 2 / (rho * L * H);
    const double e0 = region.kinetic_energy();
    double       t  = 0;
    while (t < period - 1e-12)
      {
        const double step = std::min(dt, period - t);
        region.step(step);
        t += step;
        // v is the half step's: compare at t - dt/2.
        const double exact = v0 * std::cos(w * (t - step / 2));
        result.error =
          std::max(result.error,
                   std::abs(region.node_velocity(Point<2>(L, 0), 0) - exact) /
                     v0);
      }
    // The kinetic energy is of the half step, the strain energy of t: at
    // the end of the period (all kinetic, its rate zero) their sum is the
    // energy to O(dt^2).
    result.drift =
      std::abs(region.kinetic_energy() + region.strain_energy() - e0) / e0;
    return result;
  }
} // namespace

TEST(SolidRegion, VibratingBarConvergesWithHAndK)
{
  const BarResult q1_coarse = vibrating_bar(8, 1);
  const BarResult q1_fine   = vibrating_bar(16, 1);
  const BarResult q2_coarse = vibrating_bar(8, 2);
  std::cout << "bar: Q1 h = 1/8 " << q1_coarse.error << ", h = 1/16 "
            << q1_fine.error << ", Q2 h = 1/8 " << q2_coarse.error
            << "; energy drift " << q1_coarse.drift << ", " << q1_fine.drift
            << ", " << q2_coarse.drift << std::endl;
  for (const BarResult &r : {q1_coarse, q1_fine, q2_coarse})
    EXPECT_NEAR(r.mass, 1., 1e-12);
  // Second order in h: halving h divides the error by about 4 (7.4e-3,
  // 1.87e-3 seen; Q2 on the coarse cells 9.3e-5).
  EXPECT_LT(q1_fine.error, 0.35 * q1_coarse.error);
  // The quadratic element on the same cells beats the linear one on cells
  // half their size.
  EXPECT_LT(q2_coarse.error, q1_fine.error);
  EXPECT_LT(q1_coarse.error, 0.05);
  // Energy after a period: 1.9e-3, 4.3e-4, 3.8e-4 seen; second order.
  for (const BarResult &r : {q1_coarse, q1_fine, q2_coarse})
    EXPECT_LT(r.drift, 3e-3);
  EXPECT_LT(q1_fine.drift, 0.35 * q1_coarse.drift);
}

namespace
{
  /** A smooth velocity field, not polynomial: every node moves its own
   * way. */
  template <int dim>
  class Swirl : public Function<dim>
  {
  public:
    Swirl()
      : Function<dim>(dim)
    {}
    double
    value(const Point<dim> &x, const unsigned int component) const override
    {
      return 0.3 * std::sin(2. * x[0] + 3. * x[1] + component) +
             0.2 * std::cos(5. * x[dim - 1] - 2. * component);
    }
  };


  /** The force and the signal rate of a plain assembly, after one step
   * with the swirl's velocity; their largest difference from the
   * region's, relative to the largest force and the rate. */
  template <int dim>
  std::pair<double, double>
  force_and_rate_errors(const unsigned int degree, const bool curved)
  {
    NeoHookean<dim> material(LameParameters{2e3, 1e3});
    material.density = 1;
    SolidRegion<dim> region(MPI_COMM_WORLD, material, degree);
    if (curved)
      test::make_curved_mesh(region.get_triangulation(), 2);
    else
      {
        // A box whose cells' sizes are not binary fractions (0.7 / 3).
        Point<dim> upper;
        for (unsigned int d = 0; d < dim; ++d)
          upper[d] = 0.7;
        GridGenerator::subdivided_hyper_rectangle(region.get_triangulation(),
                                                  std::vector<unsigned int>(dim,
                                                                            3),
                                                  Point<dim>(),
                                                  upper);
      }
    region.setup(std::set<types::boundary_id>{});
    // The force loop reads the cells' gradients from shared sets: a box's
    // cells are translates of one another, a curved mesh's are not (the
    // sets of a rank's own cells).
    const std::size_t n_cells =
      region.get_triangulation().n_locally_owned_active_cells();
    if (curved)
      EXPECT_EQ(region.n_gradient_sets(), n_cells);
    else
      EXPECT_EQ(region.n_gradient_sets(), std::min<std::size_t>(n_cells, 1));
    region.set_velocity(Swirl<dim>());
    const double dt = 0.05; // strains of a few percent
    region.step(dt);
    region.compute_forces(dt, dt);

    LinearAlgebra::distributed::Vector<double> u(region.get_displacement());
    u.update_ghost_values();
    LinearAlgebra::distributed::Vector<double> f(region.get_mass());
    f                                         = 0;
    const auto                          &dofs = region.get_dof_handler();
    const QGauss<dim>                    gauss(degree + 1);
    FEValues<dim>                        values(dofs.get_fe(),
                         gauss,
                         update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     vector(0);
    std::vector<Tensor<2, dim>>          grad_u(gauss.size());
    std::vector<types::global_dof_index> cell_dofs(values.dofs_per_cell);
    double                               rate   = 0;
    const double                         lambda = 2e3, mu = 1e3;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          values[vector].get_function_gradients(u, grad_u);
          cell->get_dof_indices(cell_dofs);
          double wave_speed = 0, stretch = 1;
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + grad_u[q];
              const double         J = determinant(F);
              const Tensor<2, dim> sigma =
                mu / J * (F * transpose(F) - unit_symmetric_tensor<dim>()) +
                lambda * std::log(J) / J * unit_symmetric_tensor<dim>();
              const Tensor<2, dim> P = J * sigma * transpose(invert(F));
              for (unsigned int i = 0; i < values.dofs_per_cell; ++i)
                f(cell_dofs[i]) -=
                  scalar_product(P, values[vector].gradient(i, q)) *
                  values.JxW(q);
              wave_speed = std::max(wave_speed, material.wave_speed(F));
              stretch    = std::min(stretch, smallest_stretch(F));
            }
          rate = std::max(rate,
                          wave_speed * degree /
                            (stretch * cell->minimum_vertex_distance()));
        }
    f.compress(VectorOperation::add);
    double largest = 0, error = 0;
    for (const auto &node : region.get_nodes())
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double exact = f.local_element(node.dof[d]);
          largest            = std::max(largest, std::abs(exact));
          error = std::max(error, std::abs(region.force_of(node)[d] - exact));
        }
    return {error / largest,
            std::abs(region.local_signal_rate() - rate) / rate};
  }
} // namespace

// The force loop reads the cell's gradients in its own order and sums in
// its own arrays; this is the textbook assembly it must equal. Round-off
// only: the sums over nodes and points run in different orders (1e-12 of
// the largest force leaves room for about 1e4 ulps). On a curved mesh
// (a set of gradients a cell) and a box (one set all cells share).
TEST(SolidRegion, ForceLoopMatchesPlainAssembly)
{
  for (const bool curved : {true, false})
    for (const unsigned int degree : {1u, 2u})
      {
        const auto [force2, rate2] = force_and_rate_errors<2>(degree, curved);
        const auto [force3, rate3] = force_and_rate_errors<3>(degree, curved);
        std::cout << (curved ? "curved" : "box") << " Q" << degree
                  << ": force error " << force2 << " (2D), " << force3
                  << " (3D); signal rate " << rate2 << ", " << rate3
                  << std::endl;
        EXPECT_LT(force2, 1e-12);
        EXPECT_LT(force3, 1e-12);
        EXPECT_LT(rate2, 1e-14);
        EXPECT_LT(rate3, 1e-14);
      }
}
