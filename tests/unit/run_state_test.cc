// The run's state is written and read back whole, to the last bit.
#include <dealmpm/core/run_state.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

using namespace dealmpm;

TEST(RunState, WrittenAndReadBackWhole)
{
  RunState state;
  state.time             = 0.1 + 1e-17 * 3;
  state.step             = 1234;
  state.next_output      = 1. / 3.;
  state.particle_steps   = 9.87654321e12;
  state.stepping_time    = 12.5;
  state.lost_particles   = 7;
  state.last_dt          = 1e-3 / 3;
  state.output.counter   = 5;
  state.output.last_time = 2. / 7.;
  state.output.last_step = 1200;
  state.effect_states    = {{}, {M_PI, -1e-300}};
  const std::string pvd =
    (std::filesystem::temp_directory_path() / "run_state_test.pvd").string();
  state.output.particle_series.add_and_write(0.25, "particles_00001.pvtu", pvd);
  std::filesystem::remove(pvd);
  Statistics initial;
  initial.mass           = 3.5;
  initial.momentum       = {{1. / 3, -2. / 3, 0}};
  initial.kinetic_energy = 0.1;
  state.accuracy.start(initial);
  Statistics later     = initial;
  later.kinetic_energy = 0.125;
  state.accuracy.observe(later, 0.01);
  state.accuracy.observe_step(0.97, 0.43);

  std::stringstream file;
  state.save(file);
  RunState read;
  read.load(file);

  EXPECT_EQ(read.time, state.time);
  EXPECT_EQ(read.step, state.step);
  EXPECT_EQ(read.next_output, state.next_output);
  EXPECT_EQ(read.particle_steps, state.particle_steps);
  EXPECT_EQ(read.stepping_time, state.stepping_time);
  EXPECT_EQ(read.lost_particles, state.lost_particles);
  EXPECT_EQ(read.last_dt, state.last_dt);
  EXPECT_EQ(read.output.counter, state.output.counter);
  EXPECT_EQ(read.output.last_time, state.output.last_time);
  EXPECT_EQ(read.output.last_step, state.output.last_step);
  EXPECT_EQ(read.output.particle_series, state.output.particle_series);
  EXPECT_FALSE(read.output.particle_series == OutputSeries());
  EXPECT_EQ(read.effect_states, state.effect_states);
  const AccuracyReport &a = read.accuracy.report(),
                       &b = state.accuracy.report();
  EXPECT_EQ(a.energy_drift, b.energy_drift);
  EXPECT_EQ(a.min_J, b.min_J);
  EXPECT_EQ(a.max_cfl, b.max_cfl);
  // The monitor goes on from where it was: the same observation gives the
  // same report.
  Statistics again     = initial;
  again.kinetic_energy = 0.2;
  read.accuracy.observe(again, 0.02);
  state.accuracy.observe(again, 0.02);
  EXPECT_EQ(read.accuracy.report().energy_drift,
            state.accuracy.report().energy_drift);
  EXPECT_EQ(read.accuracy.report().momentum_drift,
            state.accuracy.report().momentum_drift);
}
