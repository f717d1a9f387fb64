// Shape functions: partition of unity and zero gradient sum at random points,
// on uniform cells and next to hanging nodes; the Q1 map of a distorted cell.
#include <dealmpm/transfer/stencil.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  template <int dim>
  std::string
  refined_scene()
  {
    const std::string lower = dim == 2 ? "0, 0" : "0, 0, 0";
    const std::string cells = dim == 2 ? "4, 4" : "3, 3, 3";
    const std::string half  = dim == 2 ? "0.5, 0.5" : "0.5, 0.5, 0.5";
    const std::string upper = dim == 2 ? "1, 1" : "1, 1, 1";
    return "set Dimension = " + std::to_string(dim) +
           "\nsubsection Grid\n set Lower corner = " + lower +
           "\n set Upper corner = " + upper + "\n set Cells = " + cells +
           "\n subsection Local refinement\n  set Levels = 1\n"
           "  set Lower corner = " +
           lower + "\n  set Upper corner = " + half +
           "\n end\nend\nsubsection Body 1\n set Shape = box\n set Lower corner = " +
           lower + "\n set Upper corner = " + upper +
           "\n set Particles per cell = 2\nend\n";
  }

  template <int dim>
  void
  check_partition_of_unity()
  {
    auto         simulation = test::make_simulation<dim>(refined_scene<dim>());
    std::mt19937 rng(42);
    test::scatter_particles_in_cells(*simulation, rng);

    unsigned int constrained_cells = 0;
    for (const auto &c : simulation->background_grid().cells)
      if (c.first_weight != numbers::invalid_unsigned_int)
        {
          ++constrained_cells;
          ASSERT_GT(
            simulation->particle_set().handler.n_particles_in_cell(c.cell), 0u);
        }
    ASSERT_GT(constrained_cells, 0u) << "the grid must have hanging nodes";

    Stencil<dim> stencil;
    compute_linear_stencil(simulation->background_grid(),
                           simulation->particle_set(),
                           stencil);
    ASSERT_EQ(stencil.n_particles(),
              simulation->particle_set().handler.n_locally_owned_particles());
    for (std::size_t k = 0; k < stencil.n_particles(); ++k)
      {
        double         sum = 0;
        Tensor<1, dim> gradient_sum;
        double         gradient_scale = 0;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          {
            sum += stencil.N[e];
            gradient_sum += stencil.grad_N[e];
            gradient_scale = std::max(gradient_scale, stencil.grad_N[e].norm());
            EXPECT_GE(stencil.N[e], -1e-14);
          }
        EXPECT_NEAR(sum, 1., 1e-14);
        EXPECT_LT(gradient_sum.norm(), 1e-13 * gradient_scale);
      }
  }
} // namespace

TEST(Stencil, PartitionOfUnityWithHangingNodes2D)
{
  check_partition_of_unity<2>();
}

TEST(Stencil, PartitionOfUnityWithHangingNodes3D)
{
  check_partition_of_unity<3>();
}

TEST(GridCell, DistortedCellMapRoundTrip)
{
  GridCell<2> c;
  c.vertices = {{Point<2>(0, 0),
                 Point<2>(1.2, 0.1),
                 Point<2>(-0.1, 0.9),
                 Point<2>(1.4, 1.3)}};
  c.affine   = false;
  c.h        = 0.9;
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> unit(0., 1.);
  for (unsigned int i = 0; i < 100; ++i)
    {
      const Point<2> xi(unit(rng), unit(rng));
      const Point<2> back = c.reference_point(c.real_point(xi));
      EXPECT_LT(back.distance(xi), 1e-12);
    }
  // The inverse Jacobian against central differences of the map.
  const Point<2>     xi(0.3, 0.6);
  const double       eps = 1e-6;
  const Tensor<2, 2> K   = c.inverse_jacobian_at(xi);
  Tensor<2, 2>       J;
  for (unsigned int b = 0; b < 2; ++b)
    {
      Point<2> plus = xi, minus = xi;
      plus[b] += eps;
      minus[b] -= eps;
      const Tensor<1, 2> column =
        (c.real_point(plus) - c.real_point(minus)) / (2 * eps);
      for (unsigned int a = 0; a < 2; ++a)
        J[a][b] = column[a];
    }
  const Tensor<2, 2> identity = K * J;
  EXPECT_NEAR(identity[0][0], 1., 1e-8);
  EXPECT_NEAR(identity[1][1], 1., 1e-8);
  EXPECT_NEAR(identity[0][1], 0., 1e-8);
  EXPECT_NEAR(identity[1][0], 0., 1e-8);
}
