// Absorbing boundary (effect 'absorbing boundary'): a compression pulse
// runs along a confined bar (slip walls above and below, so that it is a
// plane P wave) and leaves through the dashpots at its far end, which
// match the bar's impedance rho c_p. With the far end free instead, the
// pulse comes back and the bar keeps its energy. Under MUSL and USF the
// dashpots' velocity is set again after the re-map: without it the
// balance with the dashpots' work missed by 1.3 % under MUSL (now 0.1 %;
// the check allows 0.5 %).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  // E = 1e7, nu = 0.3, rho = 1000: c_p = sqrt((lambda + 2 mu) / rho) =
  // 116.03 m/s, c_s = sqrt(mu / rho) = 62.02 m/s.
  const double c_p = std::sqrt(1e7 * 0.7 / (1.3 * 0.4) / 1000);
  const double c_s = std::sqrt(1e7 / 2.6 / 1000);

  /** A 2 m bar whose first 0.2 m start at 0.1 m/s: two pulses of 0.05
   * m/s, one running to the far end (id 1), the other reflected at the
   * free near end and following it. */
  std::string
  pulse(const bool absorbing, const std::string &scheme = "MUSL")
  {
    std::ostringstream s;
    s.precision(17);
    s << "set Number of bodies = 2\n"
      << "subsection MPM\n set Stress update = " << scheme << "\nend\n";
    if (absorbing)
      s << "set Effects = absorbing boundary\n"
        << "subsection Absorbing boundary\n set Boundary ids = 1\n"
        << " set Density = 1000\n set P-wave speed = " << c_p
        << "\n set S-wave speed = " << c_s << "\nend\n";
    s << "subsection Grid\n set Upper corner = 2, 0.1\n"
      << " set Cells = 200, 10\n set Boundary conditions = 2: slip, 3: "
         "slip\nend\n"
      << "subsection Material 1\n set Density = 1000\n"
      << " subsection linear elastic\n  set Young's modulus = 1e7\n"
      << "  set Poisson's ratio = 0.3\n end\nend\n"
      << "subsection Body 1\n set Upper corner = 0.2, 0.1\n"
      << " set Velocity = 0.1, 0\nend\n"
      << "subsection Body 2\n set Lower corner = 0.2, 0\n"
      << " set Upper corner = 2, 0.1\nend\n";
    return s.str();
  }

  struct Left
  {
    double energy;  ///< (kinetic + strain) at the end / E0
    double balance; ///< |E - W - E0| / E0
  };

  /** Both pulses have left by (2 + 0.2 + 0.2) / c_p = 0.021 s; run to
   * 0.03 s. */
  Left
  run(const bool absorbing, const std::string &scheme = "MUSL")
  {
    auto simulation = test::make_simulation<2>(pulse(absorbing, scheme), 2);
    const double E0 = simulation->statistics().total_energy();
    while (simulation->time() < 0.03 - 1e-12)
      simulation->advance(
        std::min(simulation->time_step(), 0.03 - simulation->time()));
    const Statistics s = simulation->statistics();
    return {(s.kinetic_energy + s.strain_energy) / E0,
            std::abs(s.total_energy() - simulation->external_work() - E0) / E0};
  }
} // namespace

TEST(AbsorbingBoundary, PulseLeavesThroughMatchedDashpots)
{
  const Left absorbed = run(true);
  const Left kept     = run(false);
  std::cout << "absorbing boundary: energy left " << absorbed.energy
            << " of E0 (free end: " << kept.energy
            << "), energy balance with the dashpots' work " << absorbed.balance
            << std::endl;
  EXPECT_LT(absorbed.energy, 0.02);
  EXPECT_GT(kept.energy, 0.9);
  EXPECT_LT(absorbed.balance, 0.005);
  for (const std::string scheme : {"USL", "USF"})
    {
      const Left other = run(true, scheme);
      std::cout << scheme << ": energy left " << other.energy
                << ", energy balance " << other.balance << std::endl;
      EXPECT_LT(other.energy, 0.02) << scheme;
      // USL has no re-map; its balance carries the drift of its own
      // energy accounting (3.4 % here), as it did before.
      EXPECT_LT(other.balance, scheme == "USL" ? 0.05 : 0.005) << scheme;
    }
}
