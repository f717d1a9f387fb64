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

// A grid's memory is about a quarter GridCells: they keep the two vertices
// the kernels read, not all 2^dim (320 B in 3D and 152 B in 2D before
// 2026-11-30).
TEST(GridCell, KeepsTwoVerticesNotAll)
{
  EXPECT_LE(sizeof(GridCell<2>), 120u);
  EXPECT_LE(sizeof(GridCell<3>), 176u);
}

TEST(GridCell, DistortedCellMapRoundTrip)
{
  GridCell<2>                 c;
  const GridCell<2>::Vertices vertices = {{Point<2>(0, 0),
                                           Point<2>(1.2, 0.1),
                                           Point<2>(-0.1, 0.9),
                                           Point<2>(1.4, 1.3)}};
  c.stored_vertices                    = &vertices;
  c.origin                             = vertices[0];
  c.far_corner                         = vertices[3];
  c.affine                             = false;
  c.h                                  = 0.9;
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

namespace
{
  /** Bardenhagen and Kober (2004), uGIMP in 1D: node at distance x, cell
   * size h, particle half-length l. */
  double
  gimp_closed_form(const double x, const double h, const double l)
  {
    const double r = std::abs(x);
    if (r < l)
      return 1. - (r * r + l * l) / (2. * h * l);
    if (r < h - l)
      return 1. - r / h;
    if (r < h + l)
      return (h + l - r) * (h + l - r) / (4. * h * l);
    return 0.;
  }
} // namespace

TEST(Stencil, GIMPMatchesClosedFormOnUniformGrid)
{
  auto simulation = test::make_simulation<2>(
    "subsection Grid\n set Cells = 8, 8\nend\n"
    "subsection Body 1\n set Lower corner = 0.25, 0.25\n"
    " set Upper corner = 0.75, 0.75\nend\n"
    "subsection MPM\n set Shape function = uGIMP\nend\n");
  std::mt19937 rng(11);
  test::scatter_particles_in_cells(*simulation, rng);
  Stencil<2> stencil;
  compute_gimp_stencil(simulation->background_grid(),
                       simulation->particle_set(),
                       false,
                       stencil);
  const auto  &grid = simulation->background_grid();
  const double h = 1. / 8, l = h / 4; // 2 particles per cell and direction
  std::size_t  k = 0;
  for (const auto &c : grid.cells)
    for (const auto &p :
         simulation->particle_set().handler.particles_in_cell(c.cell))
      {
        double sum = 0;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          {
            const Tensor<1, 2> r =
              grid.node_positions[stencil.node[e]] - p.get_location();
            EXPECT_NEAR(stencil.N[e],
                        gimp_closed_form(r[0], h, l) *
                          gimp_closed_form(r[1], h, l),
                        1e-14);
            sum += stencil.N[e];
          }
        EXPECT_NEAR(sum, 1., 1e-14);
        ++k;
      }
}

TEST(Stencil, GIMPPartitionOfUnityWithHangingNodes)
{
  for (const std::string kernel : {"uGIMP", "cpGIMP"})
    {
      auto simulation = test::make_simulation<2>(
        refined_scene<2>() + "subsection MPM\n set Shape function = " + kernel +
        "\nend\n");
      std::mt19937 rng(3);
      test::scatter_particles_in_cells(*simulation, rng);
      Stencil<2> stencil;
      compute_gimp_stencil(simulation->background_grid(),
                           simulation->particle_set(),
                           kernel == "cpGIMP",
                           stencil);
      for (std::size_t k = 0; k < stencil.n_particles(); ++k)
        {
          double       sum = 0, scale = 0;
          Tensor<1, 2> gradient_sum;
          for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
            {
              sum += stencil.N[e];
              gradient_sum += stencil.grad_N[e];
              scale = std::max(scale, stencil.grad_N[e].norm());
            }
          EXPECT_NEAR(sum, 1., 1e-13);
          EXPECT_LT(gradient_sum.norm(), 1e-12 * scale);
        }
    }
}
