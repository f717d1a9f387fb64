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
