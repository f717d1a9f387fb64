// Frictional contact between bodies (effect 'frictional contact'): the
// colliding disks meet and part without sticking or interpenetrating, with
// momentum kept to round-off, no work done by frictionless contact and no
// energy gained. (The block on a base, with friction: incline_test.cc.)
#include <deal.II/base/mpi.h>

#include <dealmpm/effects/frictional_contact.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  std::string
  colliding_disks(const std::string &extra)
  {
    std::ifstream     file(DEALMPM_SOURCE_DIR "/prm/colliding_disks.prm");
    std::stringstream text;
    text << file.rdbuf() << "\n" << extra;
    return text.str();
  }

  /** Along the disks' line of approach (1, 1) / sqrt 2: the largest
   * coordinate of body 1's particles and the smallest of body 2's. */
  std::pair<double, double>
  facing_extents(Simulation<2> &simulation)
  {
    double front_1 = -std::numeric_limits<double>::max();
    double front_2 = std::numeric_limits<double>::max();
    for (const auto &p : simulation.particle_set().handler)
      {
        const double s = (p.get_location()[0] + p.get_location()[1]) / M_SQRT2;
        if (simulation.particle_set().body_of(p.get_properties()) == 0)
          front_1 = std::max(front_1, s);
        else
          front_2 = std::min(front_2, s);
      }
    return {Utilities::MPI::max(front_1, MPI_COMM_WORLD),
            Utilities::MPI::min(front_2, MPI_COMM_WORLD)};
  }

  struct Collision
  {
    double smallest_gap = std::numeric_limits<double>::max();
    double final_gap    = 0;
    double max_momentum = 0; ///< |p| / (m v0)
    double growth       = 0; ///< max (E - W - E0) / E0
    double final_loss   = 0; ///< (E0 + W - E) / E0 at the end
    double work         = 0;
    double min_kinetic  = 0; ///< / KE0
  };

  Collision
  collide(const std::string &extra)
  {
    auto simulation = test::make_simulation<2>(colliding_disks(extra), 2, 1);
    const Statistics initial = simulation->statistics();
    Collision        c;
    c.min_kinetic               = 1;
    const double momentum_scale = initial.mass * 0.1 * std::sqrt(2.);
    while (simulation->time() < 3.5 - 1e-9)
      {
        simulation->advance(1e-3);
        if (simulation->step_number() % 25 != 0)
          continue;
        const auto [front_1, front_2] = facing_extents(*simulation);
        c.smallest_gap     = std::min(c.smallest_gap, front_2 - front_1);
        c.final_gap        = front_2 - front_1;
        const Statistics s = simulation->statistics();
        c.max_momentum =
          std::max(c.max_momentum,
                   std::hypot(s.momentum[0], s.momentum[1]) / momentum_scale);
        c.work = simulation->external_work();
        const double balance =
          (s.total_energy() - c.work - initial.total_energy()) /
          initial.total_energy();
        c.growth     = std::max(c.growth, balance);
        c.final_loss = -balance;
        c.min_kinetic =
          std::min(c.min_kinetic, s.kinetic_energy / initial.kinetic_energy);
      }
    return c;
  }
} // namespace

TEST(Contact, CollidingDisksPartWithoutInterpenetrating)
{
  const Collision c = collide("set Effects = frictional contact\n");
  std::cout << "contact, colliding disks: smallest gap between the facing "
               "particles "
            << c.smallest_gap << " m, final gap " << c.final_gap
            << " m, max |p| / (m v0) " << c.max_momentum
            << ", max (E - W - E0) / E0 " << c.growth
            << ", final (E0 + W - E) / E0 " << c.final_loss << ", contact work "
            << c.work << " J, min KE / KE0 " << c.min_kinetic << std::endl;
  // The disks met (kinetic energy went into strain energy) ...
  EXPECT_LT(c.min_kinetic, 0.3);
  // ... no particle of one crossed the other's front ...
  EXPECT_GT(c.smallest_gap, 0.);
  // ... and they parted: their fronts end farther apart than a cell
  // (0.05 m).
  EXPECT_GT(c.final_gap, 0.05);
  EXPECT_LT(c.max_momentum, 1e-12);
  // Frictionless contact between two bodies does no work (the pair's
  // normal forces act on one normal velocity) ...
  EXPECT_LT(std::abs(c.work), 1e-12);
  // ... and adds no energy; the nodes' impulsive corrections take some
  // (4.9 % measured at dt = 1e-3 s, 3.6 % at 4e-3 s).
  EXPECT_LT(c.growth, 0.005);
  EXPECT_LT(c.final_loss, 0.08);
}
