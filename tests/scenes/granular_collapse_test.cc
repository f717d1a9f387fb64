// A Drucker-Prager sand column (phi = 19.8 deg, c = 0, the set-up of Bui et
// al. 2008 in 2D) collapsing under gravity onto a frictionless floor: the
// energy balance (kinetic + stored + plastic work + gravitational) closes
// within 2 % of the initial energy up to t = 0.4 s (0.68 % seen on 80 x 20
// cells; without the plastic work it would fall by 45 %), the column
// spreads, and no particle leaves the grid. The same column with
// Mohr-Coulomb (the same angles) closes its balance as well and runs out
// as far as Drucker-Prager (within 10 %): the Drucker-Prager cone is
// matched to Mohr-Coulomb in plane strain (its default), so the two
// models' failure in this plane-strain flow is the same. (They land 0.7 %
// apart; Mohr-Coulomb with phi = 30 lands 16 % short of phi = 19.8: the
// check sees the strength.)
#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const std::string collapse = R"(
set Effects = gravity
subsection Grid
  set Type                = rectangle
  set Lower corner        = 0, 0
  set Upper corner        = 0.5, 0.125
  set Cells               = 80, 20
  set Boundary conditions = 0: slip, 2: slip
end
subsection Material 1
  set Density = 2650
  subsection Drucker-Prager
    set Young's modulus = 0.84e6
    set Poisson's ratio = 0.3
    set Friction angle  = 19.8
  end
  subsection Mohr-Coulomb
    set Young's modulus = 0.84e6
    set Poisson's ratio = 0.3
    set Friction angle  = 19.8
  end
end
subsection Body 1
  set Shape              = box
  set Lower corner       = 0, 0
  set Upper corner       = 0.05, 0.1
  set Particles per cell = 2
  set Material           = 1
end
subsection Gravity
  set Acceleration = 0, -9.81
end
)";

  /** The largest x of the particles (the runout front). */
  double
  front(Simulation<2> &simulation)
  {
    double x = 0;
    for (const auto &p : simulation.particle_set().handler)
      x = std::max(x, p.get_location()[0]);
    return x;
  }
  /** Collapse the column with @p model to t = 0.4 s; check the balance
   * and return the runout front. */
  double
  collapse_with(const std::string &model)
  {
    auto simulation = test::make_simulation<2>(
      collapse + "subsection Material 1\n set Model = " + model + "\nend\n");
    const Statistics initial   = simulation->statistics();
    double           max_drift = 0;
    while (simulation->time() < 0.4)
      {
        simulation->advance(simulation->time_step());
        if (simulation->step_number() % 50 != 0)
          continue;
        const Statistics s = simulation->statistics();
        max_drift =
          std::max(max_drift,
                   std::abs(s.total_energy() - initial.total_energy()));
      }
    const Statistics end = simulation->statistics();
    std::cout << "granular collapse, " << model << ": plastic work / E0 = "
              << end.dissipated_work / initial.total_energy()
              << ", max |E - E0| / E0 = " << max_drift / initial.total_energy()
              << ", front at x = " << front(*simulation) << std::endl;
    EXPECT_EQ(end.n_particles, initial.n_particles) << model;
    EXPECT_GT(end.dissipated_work, 0.3 * initial.total_energy()) << model;
    EXPECT_LT(max_drift, 0.02 * initial.total_energy()) << model;
    EXPECT_GT(front(*simulation), 0.1) << model; // twice the initial width
    return front(*simulation);
  }
} // namespace

TEST(GranularCollapse, EnergyBalanceClosesWithPlasticWork)
{
  collapse_with("Drucker-Prager");
}

TEST(GranularCollapse, MohrCoulombRunsOutAsFarAsDruckerPrager)
{
  const double mohr_coulomb   = collapse_with("Mohr-Coulomb");
  const double drucker_prager = collapse_with("Drucker-Prager");
  EXPECT_NEAR(mohr_coulomb, drucker_prager, 0.1 * drucker_prager);
}
