// NodalExchange does what deal.II's compress(add) and update_ghost_values()
// do, vector by vector, with one message per neighbour: on a grid of
// several ranks (ctest runs this on 2 and 3 ranks, the scene tests on 1),
// vectors whose ghosts hold integers (exact sums in any order) must come
// out equal entry by entry, owned and ghost, and in the same ghost state.
#include <deal.II/base/mpi.h>

#include <dealmpm/grid/nodal_exchange.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** Three vectors on the grid's nodes, every local entry (owned and
   * ghost) set to a different integer of its global index, rank and
   * vector. */
  std::vector<NodalVector>
  filled(const BackgroundGrid<2> &grid)
  {
    const auto        &partitioner = grid.partitioner;
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(partitioner->get_mpi_communicator());
    const unsigned int n_local =
      partitioner->locally_owned_size() + partitioner->n_ghost_indices();
    std::vector<NodalVector> vectors(3);
    for (unsigned int k = 0; k < vectors.size(); ++k)
      {
        vectors[k].reinit(partitioner);
        for (unsigned int i = 0; i < n_local; ++i)
          vectors[k].local_element(i) = (partitioner->local_to_global(i) % 97) +
                                        1000. * (k + 1) + 7. * rank;
      }
    return vectors;
  }

  void
  expect_equal(const NodalVector &expected, const NodalVector &actual)
  {
    const unsigned int n_local = expected.locally_owned_size() +
                                 expected.get_partitioner()->n_ghost_indices();
    for (unsigned int i = 0; i < n_local; ++i)
      ASSERT_EQ(actual.local_element(i), expected.local_element(i))
        << "local entry " << i << " of " << n_local;
    EXPECT_EQ(actual.has_ghost_elements(), expected.has_ghost_elements());
  }

  std::unique_ptr<Simulation<2>>
  grid_of_several_ranks()
  {
    // Cells on every rank, and ranks meeting along edges and corners.
    return test::make_simulation<2>(
      "subsection Grid\n set Cells = 12, 9\nend\n"
      "subsection Body 1\n set Lower corner = 0.1, 0.1\n"
      " set Upper corner = 0.9, 0.9\nend\n");
  }
} // namespace

namespace
{
  /** What @p ours does to three vectors at once must equal what
   * @p theirs (deal.II) does to each. */
  template <typename Ours, typename Theirs>
  void
  expect_as_deal_ii(const Ours &ours, const Theirs &theirs)
  {
    const auto               simulation = grid_of_several_ranks();
    std::vector<NodalVector> expected   = filled(simulation->background_grid());
    std::vector<NodalVector> actual     = filled(simulation->background_grid());
    NodalExchange            exchange;
    for (NodalVector &v : actual)
      exchange.add(v);
    ours(exchange);
    for (unsigned int k = 0; k < expected.size(); ++k)
      {
        theirs(expected[k]);
        expect_equal(expected[k], actual[k]);
      }
  }
} // namespace

TEST(NodalExchange, SumsGhostsIntoOwnersAsCompressDoes)
{
  expect_as_deal_ii([](NodalExchange &e) { e.sum_ghosts_into_owners(); },
                    [](NodalVector &v) { v.compress(VectorOperation::add); });
}

TEST(NodalExchange, CopiesOwnersToGhostsAsUpdateGhostValuesDoes)
{
  expect_as_deal_ii([](NodalExchange &e) { e.copy_owners_to_ghosts(); },
                    [](NodalVector &v) { v.update_ghost_values(); });
}

TEST(NodalExchange, RefusesVectorsOfAnotherGrid)
{
  const auto    simulation = grid_of_several_ranks();
  NodalVector   on_grid(simulation->background_grid().partitioner);
  NodalVector   other(std::make_shared<Utilities::MPI::Partitioner>(3u));
  NodalExchange exchange;
  exchange.add(on_grid);
  EXPECT_THROW(exchange.add(other), std::logic_error);
}
