// A large rectangle's coarse mesh is its Cells divided by a power of two
// they share (here to at most 1e4 coarse cells), refined back to the
// scene's cells: the same cells (size, place, boundary ids, levels as the
// scene counts them), while each rank holds only its share of them. Runs
// on 1 rank and, through ctest, on 2.
#include <deal.II/base/mpi.h>

#include <dealmpm/transfer/particle_weights.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** The grid of a scene with @p grid_entries (the body stays small). */
  template <int dim>
  std::unique_ptr<Simulation<dim>>
  scene_with_grid(const std::string &grid_entries)
  {
    const std::string corner    = dim == 2 ? "0.1, 0.1" : "0.1, 0.1, 0.1";
    const std::string dimension = dim == 2 ? "" : "set Dimension = 3\n";
    return test::make_simulation<dim>(
      dimension + "subsection Grid\n set Most coarse cells = 1e4\n" +
      grid_entries + "end\nsubsection Body 1\n set Lower corner = " + corner +
      "\n set Upper corner = " + (dim == 2 ? "0.2, 0.2" : "0.2, 0.2, 0.2") +
      "\nend\n");
  }

  /** Every active cell is a box of @p h at grid level @p level, and every
   * boundary face carries the colorized id of its side. The sweeps see
   * each as a box too (LinearWeights::is_box(): K exactly diagonal), also
   * where refinement put its vertices off an axis by round-off: else they
   * take the general path there, half again as many instructions. */
  template <int dim>
  void
  expect_uniform_cells(const BackgroundGrid<dim> &grid,
                       const Tensor<1, dim>      &h,
                       const int                  level)
  {
    const BoundingBox<dim> &box = grid.bounding_box;
    for (const auto &cell : grid.triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          EXPECT_EQ(grid.level(cell), level) << cell->center();
          for (unsigned int d = 0; d < dim; ++d)
            EXPECT_NEAR(cell->extent_in_direction(d), h[d], 1e-12 * h[d]);
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                const unsigned int d = f / 2;
                const double       side =
                  f % 2 ? box.upper_bound(d) : box.lower_bound(d);
                EXPECT_NEAR(cell->face(f)->center()[d], side, 1e-12);
                EXPECT_EQ(cell->face(f)->boundary_id(), f) << cell->center();
              }
        }
    unsigned int not_boxes = 0;
    for (const GridCell<dim> &c : grid.cells)
      not_boxes += !LinearWeights<dim>::is_box(c);
    EXPECT_EQ(not_boxes, 0u) << "of " << grid.cells.size() << " cells";
  }
} // namespace

TEST(GridChange, RectangleIsFewCoarseCellsRefinedToTheScenesCells)
{
  {
    // 192 x 320 = 61,440 cells: halved twice, 48 x 80 = 3,840 <= 1e4
    // coarse cells.
    auto simulation =
      scene_with_grid<2>(" set Upper corner = 1.2, 2\n set Cells = 192, 320\n");
    const BackgroundGrid<2> &grid = simulation->background_grid();
    EXPECT_EQ(grid.base_level, 2u);
    EXPECT_EQ(grid.triangulation.n_cells(0), 3840u);
    EXPECT_EQ(grid.triangulation.n_global_active_cells(), 61440u);
    expect_uniform_cells(grid, Tensor<1, 2>({0.00625, 0.00625}), 0);
  }
  {
    // At most 1e5 coarse cells (the default before 2026-12-04): 61,440
    // cells stay their own coarse mesh.
    auto simulation = scene_with_grid<2>(
      " set Most coarse cells = 1e5\n set Cells = 192, 320\n");
    EXPECT_EQ(simulation->background_grid().base_level, 0u);
  }
  {
    // 'auto' is 1e4 without adaptivity: the same 3,840 coarse cells as
    // above.
    auto simulation = test::make_simulation<2>(
      "subsection Grid\n set Upper corner = 1.2, 2\n set Cells = 192, 320\n"
      "end\nsubsection Body 1\n set Lower corner = 0.1, 0.1\n"
      " set Upper corner = 0.2, 0.2\nend\n");
    const BackgroundGrid<2> &grid = simulation->background_grid();
    EXPECT_EQ(grid.base_level, 2u);
    EXPECT_EQ(grid.triangulation.n_cells(0), 3840u);
  }
  {
    // At most 1e4 cells: the grid is its own coarse mesh, as before.
    auto simulation               = scene_with_grid<2>(" set Cells = 24, 40\n");
    const BackgroundGrid<2> &grid = simulation->background_grid();
    EXPECT_EQ(grid.base_level, 0u);
    EXPECT_EQ(grid.triangulation.n_cells(0), 960u);
  }
  {
    // Odd counts share no power of two: a coarse cell per cell.
    auto simulation = scene_with_grid<2>(" set Cells = 101, 103\n");
    const BackgroundGrid<2> &grid = simulation->background_grid();
    EXPECT_EQ(grid.base_level, 0u);
    EXPECT_EQ(grid.triangulation.n_cells(0), 10403u);
    expect_uniform_cells(grid, Tensor<1, 2>({1. / 101, 1. / 103}), 0);
  }
  {
    // Global refinements count from the scene's cells: level 1.
    auto simulation = scene_with_grid<2>(
      " set Cells = 128, 128\n set Global refinements = 1\n");
    const BackgroundGrid<2> &grid = simulation->background_grid();
    EXPECT_EQ(grid.base_level, 1u);
    EXPECT_EQ(grid.triangulation.n_cells(0), 4096u);
    EXPECT_EQ(grid.triangulation.n_global_active_cells(), 65536u);
    expect_uniform_cells(grid, Tensor<1, 2>({1. / 256, 1. / 256}), 1);
  }
  {
    // 3D: 16 x 16 x 72 = 18,432 cells from 8 x 8 x 36.
    auto simulation = scene_with_grid<3>(
      " set Upper corner = 1, 1, 4.5\n set Cells = 16, 16, 72\n");
    const BackgroundGrid<3> &grid = simulation->background_grid();
    EXPECT_EQ(grid.base_level, 1u);
    EXPECT_EQ(grid.triangulation.n_cells(0), 2304u);
    EXPECT_EQ(grid.triangulation.n_global_active_cells(), 18432u);
    expect_uniform_cells(grid, Tensor<1, 3>({0.0625, 0.0625, 0.0625}), 0);
  }
  {
    // 3D, cells of 1/24 (not a power of two): 24 x 24 x 108 from 12 x 12 x
    // 54, the benchmark's 442k-particle column.
    auto simulation = scene_with_grid<3>(
      " set Upper corner = 1, 1, 4.5\n set Cells = 24, 24, 108\n");
    const BackgroundGrid<3> &grid = simulation->background_grid();
    EXPECT_EQ(grid.base_level, 1u);
    EXPECT_EQ(grid.triangulation.n_cells(0), 7776u);
    const double h = 1. / 24;
    expect_uniform_cells(grid, Tensor<1, 3>({h, h, h}), 0);
  }
}

TEST(GridChange, EachRankHoldsItsOwnCellsAndFewMore)
{
  // A coarse cell per cell put all 262,144 cells on every rank (those of
  // other ranks as artificial cells); from 4,096 coarse cells a rank holds
  // its own, its ghost layer and at most the coarse cells and a few finer
  // ones around its own for the rest. Load balance by particles decides
  // how many a rank owns.
  auto        simulation = scene_with_grid<2>(" set Cells = 512, 512\n");
  const auto &mesh       = simulation->background_grid().triangulation;
  EXPECT_EQ(mesh.n_global_active_cells(), 262144u);
  EXPECT_LT(mesh.n_active_cells() - mesh.n_locally_owned_active_cells(),
            0.05 * 262144);
}

TEST(GridChange, AdaptiveRectangleIsTheFewestCoarseCells)
{
  // 'Most coarse cells = auto': with a criterion the rectangle is made of
  // as few coarse cells as its counts allow (p4est's balance across
  // coarse cells is most of a grid change); without, of at most 1e4.
  const std::string grid = "subsection Grid\n set Upper corner = 1.2, 2\n"
                           " set Cells = 24, 40\n";
  const std::string body = "subsection Body 1\n set Lower corner = 0.1, 0.1\n"
                           " set Upper corner = 0.2, 0.2\nend\n";
  const std::string adaptive =
    "subsection Adaptivity\n set Criteria = particles\n"
    " set Maximum level = 1\nend\n";
  {
    auto simulation = test::make_simulation<2>(grid + "end\n" + body);
    EXPECT_EQ(simulation->background_grid().base_level, 0u);
  }
  {
    // 24 x 40 = 3 x 5 refined three times; the levels still count from
    // the scene's cells.
    auto simulation =
      test::make_simulation<2>(grid + "end\n" + body + adaptive);
    const BackgroundGrid<2> &mesh = simulation->background_grid();
    EXPECT_EQ(mesh.base_level, 3u);
    EXPECT_EQ(mesh.triangulation.n_cells(0), 15u);
    for (const GridCell<2> &c : mesh.cells)
      EXPECT_LE(mesh.level(c.cell), 1);
    EXPECT_GT(mesh.triangulation.n_global_active_cells(), 960u);
  }
  {
    auto simulation = test::make_simulation<2>(
      grid + " set Most coarse cells = 1e5\nend\n" + body + adaptive);
    EXPECT_EQ(simulation->background_grid().base_level, 0u);
  }
}
