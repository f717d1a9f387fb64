// NodesOnGrid couples an FEM region's nodes to the background grid point to
// point: each rank sends its points only to the ranks whose owned cells'
// box holds them, after the ranks published their boxes. ctest runs these
// tests on 1, 2 and 3 ranks. A cluster of points, owned by the ranks in
// turn (a partition unlike the grid's), circles through the box: every
// point must be placed by exactly one rank and its answer (the grid's
// linear interpolation of the node positions, exact for x itself up to
// round-off, hence 1e-12) must reach its owner, with the boxes published
// again only now and then. A point off the grid, or one that jumps past
// its published box, must stop the run, never be lost silently.
#include <deal.II/base/mpi.h>

#include <dealmpm/base/run_messages.h>
#include <dealmpm/fem/nodes_on_grid.h>

#include <gtest/gtest.h>

#include <cmath>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** A box of 1.2 x 0.9 in @p cells. */
  std::unique_ptr<Simulation<2>>
  grid_of_several_ranks(const std::string &cells = "12, 9")
  {
    return test::make_simulation<2>(
      "subsection Grid\n set Cells = " + cells +
      "\n"
      " set Lower corner = 0, 0\n set Upper corner = 1.2, 0.9\nend\n"
      "subsection Body 1\n set Lower corner = 0.1, 0.1\n"
      " set Upper corner = 0.9, 0.8\nend\n");
  }

  /** This rank's points of a cluster of 3 x 3 points 0.05 apart (half a
   * cell), its centre at @p angle on a circle of radius 0.3 about the
   * box's centre: per point x, y and its number. */
  std::vector<double>
  cluster(const double angle, const unsigned int rank, const unsigned int n)
  {
    std::vector<double> mine;
    for (unsigned int k = 0; k < 9; ++k)
      if (k % n == rank)
        {
          mine.push_back(0.6 + 0.3 * std::cos(angle) + 0.05 * (k % 3));
          mine.push_back(0.45 + 0.3 * std::sin(angle) + 0.05 * (k / 3));
          mine.push_back(k);
        }
    return mine;
  }

  /** The placing ranks' answers: per point the grid's interpolation of
   * its nodes' positions and the point's number. */
  std::vector<double>
  answers(const NodesOnGrid<2> &points, const BackgroundGrid<2> &grid)
  {
    std::vector<double> per_point(3 * points.n_points(), 0.);
    for (const auto &p : points.placed())
      {
        for (unsigned int n = 0; n < p.nodes.size(); ++n)
          for (unsigned int d = 0; d < 2; ++d)
            per_point[3 * p.point + d] +=
              p.weights[n] * grid.node_positions[p.nodes[n]][d];
        per_point[3 * p.point + 2] = points.value(p.point, 2);
      }
    return per_point;
  }

  /** The step's reduction as Simulation does it: publish again when any
   * rank asks; the first failure on any rank. */
  std::string
  finish_step(NodesOnGrid<2> &points, const MPI_Comm comm)
  {
    if (Utilities::MPI::logical_or(points.publication_wanted(), comm))
      points.publish_at_next_step();
    return first_message(points.failure(), comm);
  }
} // namespace

TEST(NodesOnGrid, EveryPointPlacedOnceAndAnsweredToItsOwner)
{
  // Cells of h = 0.025: on 2 and 3 ranks the cluster's published box
  // does not meet every rank's owned box.
  const auto               simulation = grid_of_several_ranks("48, 36");
  const BackgroundGrid<2> &grid       = simulation->background_grid();
  const unsigned int       rank = Utilities::MPI::this_mpi_process(grid.comm);
  const unsigned int       n_ranks = Utilities::MPI::n_mpi_processes(grid.comm);
  NodesOnGrid<2>           points;
  points.grid_changed(grid);
  // 240 steps of 1/160 of a turn: the cluster travels 0.47 of a cell a
  // step and 113 cells in all, through every rank's cells.
  unsigned int publications = 0;
  for (unsigned int step = 0; step < 240; ++step)
    {
      const std::vector<double> mine =
        cluster(2 * M_PI * step / 160, rank, n_ranks);
      const unsigned int before = points.n_publications();
      points.gather_and_place(grid, mine, 3);
      publications += points.n_publications() - before;
      const std::vector<double> back =
        points.sum_to_owners(answers(points, grid), 3, grid.comm);
      ASSERT_EQ(back.size(), mine.size());
      for (std::size_t j = 0; j < mine.size(); ++j)
        ASSERT_NEAR(back[j], mine[j], 1e-12)
          << "point " << mine[3 * (j / 3) + 2] << " at step " << step;
      ASSERT_EQ(finish_step(points, grid.comm), "") << "step " << step;
    }
  // Published at the start and again each time a point has come two cells
  // (0.05) from where the boxes were published: at most once per 0.05 of
  // the path (2.83), at least once per 0.05 of the cluster's sweep in x
  // (0.6, three times).
  EXPECT_GE(publications, 1u + static_cast<unsigned int>(3 * 0.6 / 0.05));
  EXPECT_LE(publications, 2u + static_cast<unsigned int>(2.83 / 0.05));
}

TEST(NodesOnGrid, APointOffTheGridIsAFailureOrZeros)
{
  const auto               simulation = grid_of_several_ranks();
  const BackgroundGrid<2> &grid       = simulation->background_grid();
  const unsigned int       rank = Utilities::MPI::this_mpi_process(grid.comm);
  NodesOnGrid<2>           points;
  points.grid_changed(grid);
  // Rank 0's one point leaves the box over a few steps.
  for (const double x : {1.0, 1.1, 1.15, 1.19, 1.25})
    {
      const std::vector<double> mine =
        rank == 0 ? std::vector<double>{x, 0.5, 7.} : std::vector<double>{};
      points.gather_and_place(grid, mine, 3);
      const std::vector<double> back =
        points.sum_to_owners(answers(points, grid), 3, grid.comm, false);
      if (rank == 0)
        {
          EXPECT_EQ(back[2], x < 1.2 ? 7. : 0.) << "a contact's point at " << x;
        }
      ASSERT_EQ(finish_step(points, grid.comm), "");
      points.gather_and_place(grid, mine, 3);
      points.sum_to_owners(answers(points, grid), 3, grid.comm);
      const std::string failure = finish_step(points, grid.comm);
      if (x < 1.2)
        {
          EXPECT_EQ(failure, "");
        }
      else
        {
          EXPECT_NE(failure.find("(1.25, 0.5) left the background grid"),
                    std::string::npos)
            << failure;
        }
    }
}

TEST(NodesOnGrid, APointThatJumpsIsNeverLostSilently)
{
  const auto               simulation = grid_of_several_ranks("48, 36");
  const BackgroundGrid<2> &grid       = simulation->background_grid();
  const unsigned int       rank = Utilities::MPI::this_mpi_process(grid.comm);
  const unsigned int       n_ranks = Utilities::MPI::n_mpi_processes(grid.comm);
  // The last rank's points sit in the far corner, then one jumps to the
  // origin. On several ranks, rank 0 owns the cells at the origin and
  // none near the far corner, so it does not expect the last rank's
  // points.
  if (rank == 0 && n_ranks > 1)
    {
      for (const GridCell<2> &c : grid.cells)
        ASSERT_LT(c.far_corner[0], 0.85)
          << "the partition changed: pick new points";
    }
  NodesOnGrid<2> points;
  points.grid_changed(grid);
  const std::vector<double> corner{1.15, 0.85, 1., 1.1, 0.85, 2.};
  const std::vector<double> jumped{1.15, 0.85, 1., 0.05, 0.05, 2.};
  for (const auto *at : {&corner, &jumped})
    {
      const std::vector<double> mine =
        rank == n_ranks - 1 ? *at : std::vector<double>{};
      points.gather_and_place(grid, mine, 3);
      const std::vector<double> back =
        points.sum_to_owners(answers(points, grid), 3, grid.comm);
      const std::string failure = finish_step(points, grid.comm);
      bool              right   = true;
      for (std::size_t j = 0; j < mine.size(); ++j)
        right = right && std::abs(back[j] - mine[j]) < 1e-12;
      // On one rank nothing can be missed; on more, a stop that says why.
      if (at == &corner || n_ranks == 1)
        {
          EXPECT_EQ(failure, "");
        }
      else
        {
          EXPECT_NE(failure.find("(0.05, 0.05) moved more than a cell"),
                    std::string::npos)
            << failure;
        }
      if (failure.empty())
        {
          EXPECT_TRUE(right);
        }
    }
}
