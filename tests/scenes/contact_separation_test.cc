// Contact's separation check (Frictional contact/Separation check): two
// blocks share the nodes between them across a gap of a cell (their
// particles end 0.025 m apart) while they approach at 1 m/s each. Without
// the check the shared nodes push them apart at once, 0.0125 s before
// they touch; with it they fly free until the gap closes. Either way the
// total momentum is kept.
#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** Body 1's momentum and the total, in x. */
  std::array<double, 2>
  momenta(Simulation<2> &simulation)
  {
    const CoreFields &f       = simulation.particle_set().fields;
    double            sums[2] = {};
    for (const auto &p : simulation.particle_set().handler)
      {
        const double P =
          p.get_properties()[f.mass] * p.get_properties()[f.velocity];
        sums[1] += P;
        if (simulation.particle_set().body_of(p.get_properties()) == 0)
          sums[0] += P;
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                        MPI_COMM_WORLD,
                        ArrayView<double>(sums, 2));
    return {{sums[0], sums[1]}};
  }

  /** Body 1's rightmost particle less body 2's leftmost. */
  double
  overlap(Simulation<2> &simulation)
  {
    double right = -1e9, left = 1e9;
    for (const auto &p : simulation.particle_set().handler)
      if (simulation.particle_set().body_of(p.get_properties()) == 0)
        right = std::max(right, p.get_location()[0]);
      else
        left = std::min(left, p.get_location()[0]);
    return Utilities::MPI::max(right, MPI_COMM_WORLD) +
           Utilities::MPI::max(-left, MPI_COMM_WORLD);
  }

  /** Body 1's momentum at t = 0.01 s and at 0.05 s over its initial one,
   * and the largest overlap of the two bodies' particles. */
  std::array<double, 3>
  approach(const double separation_check)
  {
    auto simulation = test::make_simulation<2>(
      "set Effects = frictional contact\n"
      "subsection Frictional contact\n set Separation check = " +
        std::to_string(separation_check) +
        "\nend\n"
        "subsection Grid\n set Upper corner = 1, 0.25\n set Cells = 40, 10\n"
        "end\nsubsection Material 1\n set Density = 1000\n"
        " subsection linear elastic\n  set Young's modulus = 1e6\n end\nend\n"
        "subsection Body 1\n set Lower corner = 0.2, 0.05\n"
        " set Upper corner = 0.49, 0.2\n set Velocity = 1, 0\nend\n"
        "subsection Body 2\n set Lower corner = 0.51, 0.05\n"
        " set Upper corner = 0.8, 0.2\n set Velocity = -1, 0\nend\n",
      2);
    const auto            before = momenta(*simulation);
    std::array<double, 3> result{{0, 0, -1e9}};
    for (const double t : {0.01, 0.05})
      {
        while (simulation->time() < t - 1e-12)
          {
            simulation->advance(
              std::min(simulation->time_step(), t - simulation->time()));
            result[2] = std::max(result[2], overlap(*simulation));
          }
        const auto after = momenta(*simulation);
        EXPECT_NEAR(after[1], before[1], 1e-12 * before[0]);
        result[t < 0.02 ? 0 : 1] = after[0] / before[0];
      }
    return result;
  }
} // namespace

TEST(ContactSeparation, BodiesAcrossAGapDoNotTouchBeforeItCloses)
{
  const auto without = approach(0), with = approach(0.9);
  std::cout << "contact across a gap: at t = 0.01 s body 1 keeps " << without[0]
            << " of its momentum without the separation "
            << "check, " << with[0] << " with it (exact: 1 until t = 0.0125 "
            << "s); at 0.05 s " << without[1] << ", " << with[1]
            << "; largest overlap of the particles " << without[2] << ", "
            << with[2] << " m" << std::endl;
  EXPECT_LT(without[0], 0.95);
  EXPECT_NEAR(with[0], 1., 1e-12);
  // Once they touch they bounce, and do not pass through each other.
  EXPECT_LT(with[1], 0.);
  EXPECT_LT(with[2], 0.);
}
