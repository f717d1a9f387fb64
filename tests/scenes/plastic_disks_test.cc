// Colliding J2-plastic disks: the colliding-disks scene at 5x the speed
// (0.5 m/s each way) with a yield stress of 5 Pa and linear hardening, so
// that the impact deforms the disks plastically. The energy balance closes
// with the plastic work: kinetic + stored + plastic stays within 2 % of the
// initial kinetic energy up to t = 0.7, before any particle leaves the grid
// (0.66 % seen on this 40 x 40 grid at CFL 0.2, 1.6 % at CFL 0.5: the
// collision's scheme error; without the plastic work it would fall 11 % by
// t = 0.6), while the plastic work grows past 10 % of it; momentum (zero)
// is kept to round-off.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  std::string
  plastic_disks()
  {
    std::ifstream     file(DEALMPM_SOURCE_DIR "/prm/colliding_disks.prm");
    std::stringstream text;
    text << file.rdbuf();
    std::string scene = text.str();
    scene = std::regex_replace(scene, std::regex("0\\.1, 0\\.1"), "0.5, 0.5");
    scene =
      std::regex_replace(scene, std::regex("-0\\.1, -0\\.1"), "-0.5, -0.5");
    return scene + R"(
subsection Grid
  set Cells = 40, 40
end
subsection Time
  set CFL number = 0.2
end
subsection Material 1
  set Model = J2 plasticity
  subsection J2 plasticity
    set Young's modulus   = 1000
    set Poisson's ratio   = 0.3
    set Yield stress      = 5
    set Hardening modulus = 50
  end
end
)";
  }
} // namespace

TEST(PlasticDisks, EnergyBalanceClosesWithPlasticWork)
{
  auto             simulation = test::make_simulation<2>(plastic_disks(), 2, 1);
  const Statistics initial    = simulation->statistics();
  ASSERT_TRUE(initial.has_dissipated_work);
  ASSERT_EQ(initial.dissipated_work, 0);
  double max_drift = 0, max_momentum = 0;
  while (simulation->time() < 0.7)
    {
      simulation->advance(simulation->time_step());
      if (simulation->step_number() % 10 != 0)
        continue;
      const Statistics s = simulation->statistics();
      max_drift          = std::max(max_drift,
                           std::abs(s.total_energy() - initial.total_energy()));
      max_momentum =
        std::max(max_momentum, std::hypot(s.momentum[0], s.momentum[1]));
    }
  const Statistics end = simulation->statistics();
  std::cout << "plastic disks: plastic work / E0 = "
            << end.dissipated_work / initial.total_energy()
            << ", max |E - E0| / E0 = " << max_drift / initial.total_energy()
            << std::endl;
  EXPECT_EQ(end.n_particles, initial.n_particles);
  EXPECT_GT(end.dissipated_work, 0.1 * initial.total_energy());
  EXPECT_LT(max_drift, 0.02 * initial.total_energy());
  EXPECT_LT(max_momentum, 1e-12 * initial.mass * 0.5 * std::sqrt(2.));
}

// A scene whose materials do not dissipate has no dissipated_work column.
TEST(PlasticDisks, ElasticScenesCountNoPlasticWork)
{
  std::ifstream     file(DEALMPM_SOURCE_DIR "/prm/colliding_disks.prm");
  std::stringstream text;
  text << file.rdbuf();
  auto simulation = test::make_simulation<2>(text.str(), 2, 1);
  EXPECT_FALSE(simulation->statistics().has_dissipated_work);
}
