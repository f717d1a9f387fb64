// cpGIMP's weights are computed where used while its stretched domains fit
// the three-node windows, and stored while one does not: a run gives the
// stored weights' answers either way.
#include <deal.II/base/timer.h>

#include <dealmpm/effects/effect.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** Does nothing, but says it reads the stored weights (the default of
   * Effect::reads_stencil()): a scene that lists it stores them every
   * step. */
  class StoredWeights : public Effect<2>
  {};

  void
  register_stored_weights()
  {
    static bool registered = false;
    if (registered)
      return;
    registered = true;
    effect_registry<2>().add(
      "stored weights",
      "test: nothing, but the weights are stored.",
      [](ParameterHandler &) {},
      [](SceneReader &) { return std::make_unique<StoredWeights>(); });
  }

  /** Two bars of one particle a cell (domains of half a cell, the most
   * the windows take) and Poisson's ratio 0 meet at 0.5 m/s each: the
   * impact squeezes them along x, the rebound stretches them past half a
   * cell, and y never stretches (no lateral stress, no lateral motion). */
  std::string
  bars(const std::string &scheme, const std::string &effects)
  {
    return "set Effects = " + effects +
           "\nsubsection Grid\n set Lower corner = -0.25, 0\n"
           " set Upper corner = 1.25, 0.25\n set Cells = 24, 4\nend\n"
           "subsection Body 1\n set Lower corner = 0, 0\n"
           " set Upper corner = 0.5, 0.25\n set Particles per cell = 1\n"
           " set Velocity = 0.5, 0\nend\n"
           "subsection Body 2\n set Lower corner = 0.5, 0\n"
           " set Upper corner = 1, 0.25\n set Particles per cell = 1\n"
           " set Velocity = -0.5, 0\nend\n"
           "subsection Material 1\n subsection linear elastic\n"
           "  set Young's modulus = 1e5\n  set Poisson's ratio = 0\n"
           " end\nend\n"
           "subsection MPM\n set Shape function = cpGIMP\n"
           " set Stress update = " +
           scheme + "\nend\n";
  }

  unsigned int
  stencil_steps(Simulation<2> &simulation)
  {
    const auto calls =
      simulation.timer().get_summary_data(TimerOutput::n_calls);
    const auto found = calls.find("stencil");
    return found == calls.end() ? 0 : static_cast<unsigned int>(found->second);
  }
} // namespace

TEST(GimpWindows, CpGimpStoresWeightsWhileADomainStretchesPastTheWindows)
{
  register_stored_weights();
  for (const std::string scheme : {"USL", "MUSL"})
    {
      auto windows = test::make_simulation<2>(bars(scheme, ""), 2);
      auto stored = test::make_simulation<2>(bars(scheme, "stored weights"), 2);
      const double       dt      = 1e-3; // CFL 0.16 at c = 10 m/s
      const unsigned int n_steps = 300;  // three passes of the wave
      for (unsigned int i = 0; i < n_steps; ++i)
        {
          windows->advance(dt);
          stored->advance(dt);
        }
      // Under USL the windows ran in some steps and the stored weights in
      // others; MUSL stores them every step (its three sweeps would each
      // compute the windows).
      const unsigned int stored_steps = stencil_steps(*windows);
      if (scheme == "USL")
        {
          EXPECT_GT(stored_steps, 0u);
          EXPECT_LT(stored_steps, n_steps);
        }
      else
        {
          EXPECT_EQ(stored_steps, n_steps);
        }
      EXPECT_EQ(stencil_steps(*stored), n_steps) << scheme;

      // The same particles in the same states: the weights agree to
      // round-off, which 300 steps of an elastic (linear, not chaotic)
      // response carry on without growing past a few hundred ulps of each
      // value's largest size over the particles; a window that misses the
      // fourth node a stretched domain reaches is wrong by O(1 %) of a
      // weight, which moves positions and stresses by far more than 1e-10
      // of theirs.
      const std::vector<double> a =
                                  test::particle_state(windows->particle_set()),
                                b =
                                  test::particle_state(stored->particle_set());
      ASSERT_EQ(a.size(), b.size());
      const std::size_t width =
        a.size() / windows->particle_set().handler.n_locally_owned_particles();
      // A value's scale is the largest size over the particles of the
      // field it belongs to, whose components share it: a component that
      // is zero but for round-off (v_y, F_xy, the shear stress) is
      // compared at its field's round-off, not at its own.
      std::vector<std::size_t> field(width);
      for (std::size_t c = 0; c < width; ++c)
        field[c] = c;
      const auto join = [&](const std::size_t first, const std::size_t n) {
        for (std::size_t c = first; c < first + n; ++c)
          field[c] = first;
      };
      using Core           = FixedCore<2>;
      const std::size_t at = 4; // after the location and reference location
      join(0, at);
      join(at + Core::velocity, 2);
      join(at + Core::displacement, 2);
      join(at + Core::deformation_gradient, 4);
      join(at + Core::stress, 3);
      std::vector<double> scale(width, 0.);
      for (std::size_t i = 0; i < b.size(); ++i)
        scale[field[i % width]] =
          std::max(scale[field[i % width]], std::abs(b[i]));
      unsigned int differ = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        differ += std::abs(a[i] - b[i]) > 1e-10 * scale[field[i % width]];
      EXPECT_EQ(differ, 0u) << scheme;
      const Statistics s = windows->statistics(), t = stored->statistics();
      EXPECT_NEAR(s.strain_energy, t.strain_energy, 1e-10 * t.strain_energy)
        << scheme;
      EXPECT_GT(t.strain_energy, 0.) << scheme;
    }
}
