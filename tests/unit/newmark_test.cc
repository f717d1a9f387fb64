// Newmark's step coefficients (NewmarkStep) on the harmonic oscillator
// x'' = -w^2 x, applied exactly as the sweeps apply them: the force at the
// particle's (predicted) location, P2G's predicted velocity, the
// displacement velocity that moves it, the reported velocity.
#include <dealmpm/transfer/particle_update.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace dealmpm;

namespace
{
  constexpr double w = 2 * M_PI, x0 = 1, v0 = 0.3;

  /** Largest error over one period of (x, v / w) with steps h, or h and
   * 1.3 h alternating. */
  double
  oscillator_error(const ParticleUpdate &update,
                   const double          h,
                   const bool            alternate)
  {
    double x = x0, v = v0, a_old = 0, g = 0, t = 0, error = 0;
    for (unsigned int k = 0; t < 1 - 1e-12; ++k)
      {
        const double step = std::min(alternate && k % 2 ? 1.3 * h : h, 1 - t);
        const NewmarkStep c(update, step, g);
        const double      a = -w * w * x;
        const double d = v - c.predictor_offset * a_old + c.displacement * a;
        x += step * d;
        v     = d + c.reported * a;
        a_old = a;
        g     = step;
        t += step;
        const double x_exact = x0 * std::cos(w * t) + v0 / w * std::sin(w * t);
        const double v_exact = -x0 * w * std::sin(w * t) + v0 * std::cos(w * t);
        error =
          std::max({error, std::abs(x - x_exact), std::abs(v - v_exact) / w});
      }
    return error;
  }

  double
  rate(const ParticleUpdate &update, const bool alternate)
  {
    return std::log2(oscillator_error(update, 0.004, alternate) /
                     oscillator_error(update, 0.002, alternate));
  }
} // namespace

TEST(Newmark, SecondOrderWithConstantAndChangingSteps)
{
  ParticleUpdate update;
  update.newmark = true;
  for (const double beta : {0., 0.25})
    {
      update.beta = beta;
      EXPECT_NEAR(rate(update, false), 2, 0.05) << "beta = " << beta;
      EXPECT_NEAR(rate(update, true), 2, 0.05) << "beta = " << beta;
    }
  // 100 steps a period: central differences' phase error, 2 pi (w h)^2 /
  // 24 = 1e-3 a period, and the reported velocity's lag (2.6e-3 in all);
  // the explicit update (v += h a, x += h v) is off by w h / 2 = 0.03 from
  // its first step.
  update.beta = 0.25;
  EXPECT_LT(oscillator_error(update, 0.01, false), 3e-3);
}

TEST(Newmark, GammaAboveOneHalfDampsAtFirstOrder)
{
  ParticleUpdate update;
  update.newmark = true;
  update.gamma   = 0.6;
  EXPECT_NEAR(rate(update, false), 1, 0.1);
}

TEST(Newmark, ConstantStepsGiveFlipsVelocityIncrement)
{
  // With g = h the predicted velocity gains h a a step (FLIP's increment),
  // and the displacement velocity is v~ + (gamma + 1/2) h a.
  ParticleUpdate update;
  update.newmark = true;
  update.gamma   = 0.7;
  const NewmarkStep c(update, 0.1, 0.1);
  const double      v_predicted_gain =
    c.displacement + c.reported - update.gamma * 0.1;
  EXPECT_NEAR(v_predicted_gain, 0.1, 1e-15);
  EXPECT_NEAR(c.displacement, (update.gamma + 0.5) * 0.1, 1e-15);
  // The first step starts from v_0: v~ = v_0, d = v_0 + (1/2 - beta) h a.
  const NewmarkStep first(update, 0.1, 0);
  EXPECT_EQ(first.predictor_offset, 0);
  EXPECT_NEAR(first.displacement, (0.5 - update.beta) * 0.1, 1e-15);
}
