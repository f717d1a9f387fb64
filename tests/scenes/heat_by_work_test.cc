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
#include <cmath>
#include <fstream>
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

// Friction heats the material where it slides ('Friction heat fraction',
// all of it by default). The incline's block (0.2 x 0.1 m, 20 kg/m, mu =
// 0.2 on a 30 degree slope, PIC, as incline_test.cc) slides 0.40 m in 0.5
// s: the heat generated is the work the wall's friction took, to
// round-off (the same numbers, node by node), all of it stored though
// the block conducts, and mu m g cos(30) s of the distance it slid,
// within 1 % (seen 1e-5: the elastic block's slip is its centre's travel
// within its strain, 1e-4).
TEST(HeatByWork, FrictionHeatsTheSlidingBlockByMuNs)
{
  const double       g = 9.81, mu = 0.2, t = M_PI / 6;
  std::ostringstream s;
  s.precision(17);
  s << "set Effects = gravity, boundary friction, heat conduction\n"
    << "subsection Gravity\n set Acceleration = " << g * std::sin(t) << ", "
    << -g * std::cos(t) << "\nend\n"
    << "subsection Boundary friction\n set Coefficients = 2: " << mu
    << "\nend\n"
    << "subsection Heat conduction\n set Conductivity = 50\n"
    << " set Specific heat = 500\nend\n"
    << "subsection Grid\n set Upper corner = 1.2, 0.3\n set Cells = 48, 12"
    << "\n set Boundary conditions = 2: slip\nend\n"
    << "subsection Material 1\n set Density = 1000\n"
    << " subsection linear elastic\n  set Young's modulus = 1e7\n end\n"
    << "end\nsubsection MPM\n set Velocity update = PIC\nend\n"
    << "subsection Body 1\n set Lower corner = 0.1, 0\n"
    << " set Upper corner = 0.3, 0.1\nend\n";
  auto         simulation = test::make_simulation<2>(s.str());
  const double stored_0 =
    test::effect_column(simulation->statistics(), "heat_stored");
  const Statistics end       = test::run_to(*simulation, 0.5);
  const double     generated = test::effect_column(end, "heat_generated");
  const double friction = test::effect_column(end, "boundary_friction_work");
  double       slid = 0, n = 0;
  for (const auto &p : simulation->particle_set().handler)
    {
      slid +=
        p.get_properties()[simulation->particle_set().fields.displacement];
      n += 1;
    }
  slid = Utilities::MPI::sum(slid, MPI_COMM_WORLD) /
         Utilities::MPI::sum(n, MPI_COMM_WORLD);
  const double mu_N_s = mu * 20 * g * std::cos(t) * slid;
  std::cout.precision(10);
  std::cout << "friction heat " << generated << " J/m, friction work "
            << friction << " J/m, mu N s " << mu_N_s << " J/m (s = " << slid
            << " m), stored "
            << test::effect_column(end, "heat_stored") - stored_0 << std::endl;
  ASSERT_GT(generated, 1);
  EXPECT_NEAR(generated, -friction, 1e-12 * generated);
  // The stored heat, m c T at 293 K, is 2.9e6 J/m: its round-off.
  EXPECT_NEAR(test::effect_column(end, "heat_stored") - stored_0,
              generated,
              1e-14 * stored_0);
  EXPECT_NEAR(generated, mu_N_s, 1e-2 * mu_N_s);
}

// Contact between bodies: two elastic disks meet off their line of
// centres with friction (mu = 0.5, 'frictional contact'): the heat
// generated is the work the contact took, node by node, to round-off, and
// all of it is stored in the disks.
TEST(HeatByWork, ContactFrictionHeatsTheBodies)
{
  std::ifstream     file(DEALMPM_SOURCE_DIR "/prm/colliding_disks.prm");
  std::stringstream text;
  text << file.rdbuf() << "\n"
       << "set Effects = frictional contact, heat conduction\n"
       << "subsection MPM\n set Velocity update = PIC\nend\n"
       << "subsection Frictional contact\n set Friction coefficient = 0.5\n"
       << "end\nsubsection Heat conduction\n set Conductivity = 1\n"
       << " set Specific heat = 1\nend\n"
       << "subsection Body 1\n set Center = -0.3, -0.1\n"
       << " set Velocity = 0.1, 0\nend\n"
       << "subsection Body 2\n set Center = 0.3, 0.1\n"
       << " set Velocity = -0.1, 0\nend\n";
  auto         simulation = test::make_simulation<2>(text.str(), 2, 1);
  const double stored_0 =
    test::effect_column(simulation->statistics(), "heat_stored");
  const Statistics end       = test::run_to(*simulation, 3.5);
  const double     generated = test::effect_column(end, "heat_generated");
  const double     taken     = test::effect_column(end, "contact_work");
  std::cout.precision(10);
  std::cout << "contact heat " << generated << " J/m, contact work " << taken
            << " J/m (friction's " << test::effect_column(end, "friction_work")
            << ")" << std::endl;
  ASSERT_GT(generated, 0);
  EXPECT_NEAR(generated, -taken, 1e-12 * generated);
  EXPECT_NEAR(test::effect_column(end, "heat_stored") - stored_0,
              generated,
              1e-14 * stored_0);
}
