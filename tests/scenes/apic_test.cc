// APIC (Jiang et al. 2015) conserves angular momentum: a spinning elastic
// disk with no external forces keeps its grid angular momentum
// sum_i x_i x (m v)_i from step to step to round-off. PIC, for comparison,
// loses a visible part of it. The same with USF and MUSL; and only APIC
// scenes store the affine matrix.
#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** Spin the disk rigidly, run, return the relative change of the grid
   * angular momentum between the first and last P2G. */
  double
  angular_momentum_change(const std::string &velocity_update,
                          const std::string &scheme = "USL",
                          const std::string &grid   = "")
  {
    auto simulation = test::make_simulation<2>(
      "subsection Grid\n set Lower corner = -1, -1\n set Upper corner = 1, 1\n"
      " set Cells = 20, 20\n" +
      grid +
      "end\nsubsection Body 1\n set Shape = ball\n"
      " set Center = 0.03, -0.02\n set Radius = 0.6\nend\n"
      "subsection Material 1\n set Model = neo-Hookean\n set Density = 1000\n"
      " subsection neo-Hookean\n  set Young's modulus = 1\n end\nend\n"
      "subsection MPM\n set Velocity update = " +
      velocity_update + "\n set Stress update = " + scheme + "\nend\n");
    auto &particles = simulation->particle_set();
    for (auto &p : particles.handler)
      {
        const Point<2> x                                  = p.get_location();
        p.get_properties()[particles.fields.velocity]     = -0.5 * x[1];
        p.get_properties()[particles.fields.velocity + 1] = 0.5 * x[0];
      }
    const auto grid_angular_momentum = [&]() {
      const auto &fields = simulation->nodal_fields();
      const auto &grid   = simulation->background_grid();
      double      sum    = 0;
      for (unsigned int i = 0; i < fields.mass.locally_owned_size(); ++i)
        sum += grid.node_positions[i][0] * fields.momentum[1].local_element(i) -
               grid.node_positions[i][1] * fields.momentum[0].local_element(i);
      return Utilities::MPI::sum(sum, MPI_COMM_WORLD);
    };
    simulation->advance(2e-3);
    const double first = grid_angular_momentum();
    for (unsigned int step = 0; step < 300; ++step)
      simulation->advance(2e-3);
    return std::abs(grid_angular_momentum() - first) / std::abs(first);
  }
} // namespace

TEST(APIC, ConservesAngularMomentum)
{
  const double apic = angular_momentum_change("APIC");
  const double pic  = angular_momentum_change("PIC");
  std::cout << "angular momentum change over 300 steps: APIC " << apic
            << ", PIC " << pic << std::endl;
  EXPECT_LT(apic, 1e-12);
  EXPECT_GT(pic, 1e-3);
}

TEST(APIC, ConservesAngularMomentumWithUSFAndMUSL)
{
  // MUSL re-maps after the particles moved: its affine transfer measures
  // from the positions of the stencil, so the round trip still conserves.
  for (const std::string scheme : {"USF", "MUSL"})
    {
      const double change = angular_momentum_change("APIC", scheme);
      std::cout << "APIC with " << scheme << ": " << change << std::endl;
      EXPECT_LT(change, 1e-12) << scheme;
    }
}

TEST(APIC, ConservesAngularMomentumAcrossHangingNodes)
{
  // A refined patch under part of the disk: its particles' cells have
  // hanging nodes, where the affine sums run over the weights about the
  // particle's position (G2P) or the weights' centroid (P2G), and the
  // other cells use the closed forms of a box cell.
  const std::string patch =
    " subsection Local refinement\n  set Levels = 1\n"
    "  set Lower corner = -0.3, -0.7\n  set Upper corner = 0.5, 0.1\n end\n";
  for (const std::string scheme : {"USL", "MUSL"})
    {
      const double change = angular_momentum_change("APIC", scheme, patch);
      std::cout << "APIC with " << scheme << " and hanging nodes: " << change
                << std::endl;
      EXPECT_LT(change, 1e-12) << scheme;
    }
  EXPECT_GT(angular_momentum_change("PIC", "USL", patch), 1e-3);
}

TEST(APIC, AffineMatrixStoredOnlyWhenChosen)
{
  const std::string scene = "subsection MPM\n set Velocity update = ";
  auto              apic  = test::make_simulation<2>(scene + "APIC\nend\n");
  auto              flip  = test::make_simulation<2>(scene + "FLIP\nend\n");
  EXPECT_TRUE(apic->particle_set().layout.has("apic_B"));
  EXPECT_FALSE(flip->particle_set().layout.has("apic_B"));
  EXPECT_EQ(apic->particle_set().layout.size(),
            flip->particle_set().layout.size() + 4);
}
