// What a scene does not list costs nothing: no timer section, no particle
// property, no change of the state.
#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  std::string
  scene(const std::string &effects)
  {
    return "set Effects = " + effects +
           "\nsubsection Grid\n set Cells = 8, 8\nend\n"
           "subsection Body 1\n set Lower corner = 0.25, 0.25\n set Upper corner = 0.75, 0.75\nend\n";
  }
} // namespace

TEST(Effects, UnlistedEffectHasNoTimerSectionOrProperties)
{
  auto plain   = test::make_simulation<2>(scene(""));
  auto falling = test::make_simulation<2>(scene("gravity"));
  for (unsigned int i = 0; i < 5; ++i)
    {
      plain->advance(1e-3);
      falling->advance(1e-3);
    }
  const auto plain_sections =
    plain->timer().get_summary_data(TimerOutput::total_wall_time);
  const auto falling_sections =
    falling->timer().get_summary_data(TimerOutput::total_wall_time);
  EXPECT_EQ(plain_sections.count("effect: gravity"), 0u);
  EXPECT_EQ(falling_sections.count("effect: gravity"), 1u);
  EXPECT_EQ(plain->particle_set().layout.size(),
            falling->particle_set().layout.size());

  // Without gravity a body at rest stays at rest; with it, it falls at g.
  EXPECT_EQ(plain->statistics().kinetic_energy, 0.);
  const Statistics s = falling->statistics();
  EXPECT_NEAR(s.momentum[1] / s.mass, -9.81 * 5e-3, 1e-9);
}

// Gravity with a ramp time T: v(t) = g t^2 / (2 T) while it grows, g (t -
// T / 2) after; the potential's change in time is counted as work, so that
// the energy balance of the free fall closes.
TEST(Effects, GravityRampsUpLinearly)
{
  auto simulation = test::make_simulation<2>(
    scene("gravity") + "subsection Gravity\n set Ramp time = 0.1\nend\n");
  const double g  = 9.81;
  const double E0 = simulation->statistics().total_energy();
  EXPECT_EQ(simulation->statistics().gravitational_energy, 0.);
  const auto velocity = [&] {
    const Statistics s = simulation->statistics();
    return s.momentum[1] / s.mass;
  };
  for (unsigned int i = 0; i < 50; ++i)
    simulation->advance(1e-3);
  EXPECT_NEAR(velocity(), -g * 0.05 * 0.05 / 0.2, 1e-12);
  for (unsigned int i = 0; i < 150; ++i)
    simulation->advance(1e-3);
  EXPECT_NEAR(velocity(), -g * (0.2 - 0.05), 1e-10);
  const Statistics s   = simulation->statistics();
  const double balance = s.total_energy() - simulation->external_work() - E0;
  std::cout << "gravity ramp: energy balance " << balance << " of kinetic "
            << s.kinetic_energy << ", the ramp's work "
            << simulation->external_work() << std::endl;
  // The step's own error: x moves with the new velocity (symplectic Euler),
  // which loses M g^2 dt^2 / 2 a step, dt / t = 0.5 % of the kinetic
  // energy by t = 0.2 s with or without a ramp; the ramp's work (its
  // potential's change in time, about M g y) is 100 times larger.
  EXPECT_LT(std::abs(balance), 0.01 * s.kinetic_energy);
  EXPECT_LT(std::abs(balance), 0.01 * std::abs(simulation->external_work()));
}

// Contact and boundary friction on a scene they have nothing to do in (one
// body, no wall): the statistics are those of the scene without them, to
// round-off; without them the run has no body fields and no timer section
// of theirs.
TEST(Effects, ContactAndFrictionCostNothingWhereUnused)
{
  const std::string body =
    "subsection Grid\n set Cells = 8, 8\n set Boundary conditions = 2: "
    "slip\nend\nsubsection Body 1\n set Lower corner = 0.25, 0.25\n set "
    "Upper corner = 0.75, 0.75\n set Velocity = 0.3, 0.1\nend\n"
    "subsection Boundary friction\n set Coefficients = 2: 0.3\nend\n";
  // Contact with one body, friction on a wall the block does not reach
  // (contact does not combine with wall friction: two scenes).
  auto plain   = test::make_simulation<2>("set Effects = gravity\n" + body);
  auto contact = test::make_simulation<2>(
    "set Effects = gravity, frictional contact\n" + body);
  auto friction = test::make_simulation<2>(
    "set Effects = gravity, boundary friction\n" + body);
  for (unsigned int i = 0; i < 20; ++i)
    {
      plain->advance(2e-3);
      contact->advance(2e-3);
      friction->advance(2e-3);
    }
  const Statistics a = plain->statistics();
  for (auto *with : {contact.get(), friction.get()})
    {
      const Statistics b = with->statistics();
      EXPECT_NEAR(a.kinetic_energy, b.kinetic_energy, 1e-12 * a.kinetic_energy);
      EXPECT_NEAR(a.strain_energy, b.strain_energy, 1e-12 * a.kinetic_energy);
      for (unsigned int d = 0; d < 2; ++d)
        EXPECT_NEAR(a.momentum[d], b.momentum[d], 1e-12 * a.mass);
      EXPECT_EQ(with->external_work(), 0.);
    }
  const auto with = contact.get();

  const auto sections =
    plain->timer().get_summary_data(TimerOutput::total_wall_time);
  EXPECT_EQ(sections.count("effect: frictional contact"), 0u);
  EXPECT_EQ(sections.count("effect: boundary friction"), 0u);
  EXPECT_FALSE(plain->nodal_field_set().has_body_fields());
  EXPECT_EQ(plain->nodal_field_set().n_vectors(), 1u + 4 * 2);
  EXPECT_TRUE(with->nodal_field_set().has_body_fields());
  EXPECT_EQ(with->timer()
              .get_summary_data(TimerOutput::total_wall_time)
              .count("effect: frictional contact"),
            1u);
}

// Loads, rigid bodies and damage listed but idle (a zero pressure, a body
// far away, a failure strain never reached) change nothing; unlisted, they
// add no particle field and no timer section.
TEST(Effects, IdleLoadsRigidBodiesAndDamageChangeNothing)
{
  const std::string body =
    "subsection Grid\n set Cells = 8, 8\n set Boundary conditions = 2: "
    "slip\nend\nsubsection Body 1\n set Lower corner = 0.25, 0.25\n set "
    "Upper corner = 0.75, 0.75\n set Velocity = 0.3, 0.1\nend\n"
    "subsection Traction\n set Bodies = 1\n set Pressure = 0\nend\n"
    "subsection Rigid body\n set Lower corner = 0.9, 0.9\n"
    " set Upper corner = 2, 2\nend\n"
    "subsection Damage\n set Onset = 10\n set Failure = 10\nend\n";
  auto plain = test::make_simulation<2>("set Effects = gravity\n" + body);
  std::vector<std::unique_ptr<Simulation<2>>> idle;
  for (const std::string effect : {"traction", "rigid body", "damage"})
    idle.push_back(test::make_simulation<2>("set Effects = gravity, " + effect +
                                            "\n" + body));
  for (unsigned int i = 0; i < 20; ++i)
    {
      plain->advance(2e-3);
      for (auto &with : idle)
        with->advance(2e-3);
    }
  const Statistics a = plain->statistics();
  for (auto &with : idle)
    {
      const Statistics b = with->statistics();
      EXPECT_NEAR(a.kinetic_energy, b.kinetic_energy, 1e-12 * a.kinetic_energy);
      EXPECT_NEAR(a.strain_energy, b.strain_energy, 1e-12 * a.kinetic_energy);
      for (unsigned int d = 0; d < 2; ++d)
        EXPECT_NEAR(a.momentum[d], b.momentum[d], 1e-12 * a.mass);
      EXPECT_EQ(with->external_work(), 0.);
    }
  for (const std::string field : {"surface_area", "surface_offset", "damage"})
    EXPECT_FALSE(plain->particle_set().layout.has(field)) << field;
  EXPECT_TRUE(idle[0]->particle_set().layout.has("surface_area"));
  EXPECT_TRUE(idle[2]->particle_set().layout.has("damage"));
  const auto sections =
    plain->timer().get_summary_data(TimerOutput::total_wall_time);
  for (const std::string effect : {"traction", "rigid body", "damage"})
    EXPECT_EQ(sections.count("effect: " + effect), 0u) << effect;
}
