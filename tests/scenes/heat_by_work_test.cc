// Heating by dissipated work (heat conduction's 'Taylor-Quinney
// coefficient', issue 37): a plane-strain copper bar (Johnson-Cook, OFHC
// constants, 7.62 x 23.47 mm) hits a rigid slip wall at 210 m/s, as the
// Taylor bar does, for 10 microseconds on 0.4 mm cells.
// - Without conduction (k = 0) each particle heats by beta w / (rho0 c),
//   w the plastic work per unit reference volume it dissipated: the
//   generated heat is beta times the dissipated work and all of it is
//   stored, to round-off (1e-10: sums of a few thousand terms).
// - Johnson-Cook then takes its temperature from the particle's: with the
//   model's own specific heat and Taylor-Quinney coefficient the run is
//   the adiabatic one to round-off (1e-9): the model heats by its flow
//   stress times d gamma, the effect by the step's plastic work tau : d
//   eps_p, the same number in a radial return (seen equal to 12 digits).
// - With copper's conductivity (400 W/m/K) the hottest point is cooler,
//   but by little (seen 0.036 K of an 80.7 K rise): in 10 microseconds
//   heat spreads sqrt(alpha t) = 0.034 mm, a tenth of a cell.
#include <dealmpm/materials/johnson_cook.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double rho = 8960, c = 383, beta = 0.9;

  std::string
  taylor_bar(const std::string &heat)
  {
    std::ostringstream s;
    s << heat << "subsection Grid\n set Lower corner = -0.008, 0\n"
      << " set Upper corner = 0.008, 0.026\n set Cells = 40, 65\n"
      << " set Boundary conditions = 2: slip\nend\n"
      << "subsection Material 1\n set Model = Johnson-Cook\n"
      << " set Density = " << rho << "\nend\n"
      << "subsection Body 1\n set Lower corner = -0.00381, 0\n"
      << " set Upper corner = 0.00381, 0.02347\n"
      << " set Velocity = 0, -210\nend\n";
    return s.str();
  }

  std::string
  heat_section(const double conductivity)
  {
    std::ostringstream s;
    s << "set Effects = heat conduction\nsubsection Heat conduction\n"
      << " set Initial temperature = 298\n set Conductivity = " << conductivity
      << "\n set Specific heat = " << c
      << "\n set Taylor-Quinney coefficient = " << beta << "\nend\n";
    return s.str();
  }

  /** The hottest Johnson-Cook temperature of the bar's particles. */
  double
  hottest(Simulation<2> &simulation)
  {
    const ParticleSet<2> &particles = simulation.particle_set();
    const auto           &model =
      dynamic_cast<const JohnsonCook<2> &>(simulation.material(0));
    double T = 0;
    for (const auto &p : particles.handler)
      {
        const auto props = p.get_properties();
        T                = std::max(T,
                     model.temperature(ArrayView<const double>(
                       &props[particles.internal_offset[0]],
                       particles.n_internal[0])));
      }
    return Utilities::MPI::max(T, MPI_COMM_WORLD);
  }
} // namespace

TEST(HeatByWork, PlasticWorkHeatsTheTaylorBarAsJohnsonCookDoes)
{
  auto adiabatic = test::make_simulation<2>(taylor_bar(""));
  test::run_to(*adiabatic, 1e-5);
  const double T_adiabatic = hottest(*adiabatic);

  auto         heated = test::make_simulation<2>(taylor_bar(heat_section(0)));
  const double stored_0 =
    test::effect_column(heated->statistics(), "heat_stored");
  const Statistics s         = test::run_to(*heated, 1e-5);
  const double     T_heated  = hottest(*heated);
  const double     generated = test::effect_column(s, "heat_generated");
  const double     stored    = test::effect_column(s, "heat_stored");

  // The particle's temperature is the model's.
  const ParticleSet<2> &particles = heated->particle_set();
  const unsigned int    T         = particles.layout.offset("temperature");
  double                T_max     = 0;
  for (const auto &p : particles.handler)
    T_max = std::max(T_max, p.get_properties()[T]);
  T_max = Utilities::MPI::max(T_max, MPI_COMM_WORLD);

  std::cout.precision(12);
  std::cout << "hottest: adiabatic model " << T_adiabatic << " K, heated "
            << T_heated << " K (particle " << T_max << " K); generated "
            << generated << " J/m, dissipated " << s.dissipated_work
            << " J/m, stored - stored_0 " << stored - stored_0 << std::endl;
  ASSERT_GT(s.dissipated_work, 0);
  EXPECT_NEAR(generated, beta * s.dissipated_work, 1e-10 * generated);
  EXPECT_NEAR(stored - stored_0, generated, 1e-10 * generated);
  EXPECT_EQ(T_heated, T_max);
  EXPECT_GT(T_adiabatic, 298 + 50); // it heats
  EXPECT_NEAR(T_heated, T_adiabatic, 1e-9 * T_adiabatic);

  auto conducting = test::make_simulation<2>(taylor_bar(heat_section(400)));
  test::run_to(*conducting, 1e-5);
  const double T_conducting = hottest(*conducting);
  std::cout << "hottest with conduction: " << T_conducting << " K" << std::endl;
  EXPECT_LT(T_conducting, T_heated);
  EXPECT_GT(T_conducting - 298, 0.9 * (T_heated - 298));
}
