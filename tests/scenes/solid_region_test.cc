// A finite element solid region alone (issue 15's first check): the
// axially vibrating bar, fixed at x = 0 and free at x = L, started in its
// first mode v(x, 0) = v0 sin(pi x / 2L), moves as v0 cos(w t) sin(pi x /
// 2L), w = pi c / 2L, c = sqrt(E / rho) (nu = 0: no lateral coupling).
// The free end's velocity over one period converges with h (second order)
// and with the degree k; after a period the energy is back (central
// differences conserve it to O(dt^2)); the lumped mass is the bar's.
#include <deal.II/base/function.h>
#include <deal.II/grid/grid_generator.h>

#include <dealmpm/fem/solid_region.h>
#include <dealmpm/materials/linear_elastic.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace dealmpm;

namespace
{
  constexpr double L = 1, E = 100, rho = 1, v0 = 1e-3;

  class FirstMode : public Function<2>
  {
  public:
    FirstMode()
      : Function<2>(2)
    {}
    double
    value(const Point<2> &x, const unsigned int component) const override
    {
      return component == 0 ? v0 * std::sin(M_PI * x[0] / (2 * L)) : 0.;
    }
  };

  struct BarResult
  {
    double error; ///< largest |v_end - exact| over a period, / v0
    double drift; ///< |E(T) - E(0)| / E(0) after one period
    double mass;  ///< lumped mass over rho L H
  };

  BarResult
  vibrating_bar(const unsigned int cells, const unsigned int degree)
  {
    LinearElastic<2> material(LameParameters{0., E / 2.});
    material.density = rho;
    SolidRegion<2> region(MPI_COMM_WORLD, material, degree);
    const double   H = L / cells;
    GridGenerator::subdivided_hyper_rectangle(region.get_triangulation(),
                                              {cells, 1},
                                              Point<2>(0, 0),
                                              Point<2>(L, H),
                                              true);
    region.setup({0});
    region.set_velocity(FirstMode());
    const double c = std::sqrt(E / rho), w = M_PI * c / (2 * L);
    const double dt     = region.stable_time_step(0.2);
    const double period = 2 * M_PI / w;
    BarResult    result{0, 0, 0};
    double       mass = 0;
    for (unsigned int i = 0; i < region.get_mass().locally_owned_size(); ++i)
      mass += region.get_mass().local_element(i);
    result.mass = Utilities::MPI::sum(mass, MPI_COMM_WORLD) / 2 / (rho * L * H);
    const double e0 = region.kinetic_energy();
    double       t  = 0;
    while (t < period - 1e-12)
      {
        const double step = std::min(dt, period - t);
        region.step(step);
        t += step;
        // v is the half step's: compare at t - dt/2.
        const double exact = v0 * std::cos(w * (t - step / 2));
        result.error =
          std::max(result.error,
                   std::abs(region.node_velocity(Point<2>(L, 0), 0) - exact) /
                     v0);
      }
    // The kinetic energy is of the half step, the strain energy of t: at
    // the end of the period (all kinetic, its rate zero) their sum is the
    // energy to O(dt^2).
    result.drift =
      std::abs(region.kinetic_energy() + region.strain_energy() - e0) / e0;
    return result;
  }
} // namespace

TEST(SolidRegion, VibratingBarConvergesWithHAndK)
{
  const BarResult q1_coarse = vibrating_bar(8, 1);
  const BarResult q1_fine   = vibrating_bar(16, 1);
  const BarResult q2_coarse = vibrating_bar(8, 2);
  std::cout << "bar: Q1 h = 1/8 " << q1_coarse.error << ", h = 1/16 "
            << q1_fine.error << ", Q2 h = 1/8 " << q2_coarse.error
            << "; energy drift " << q1_coarse.drift << ", " << q1_fine.drift
            << ", " << q2_coarse.drift << std::endl;
  for (const BarResult &r : {q1_coarse, q1_fine, q2_coarse})
    EXPECT_NEAR(r.mass, 1., 1e-12);
  // Second order in h: halving h divides the error by about 4 (7.4e-3,
  // 1.87e-3 seen; Q2 on the coarse cells 9.3e-5).
  EXPECT_LT(q1_fine.error, 0.35 * q1_coarse.error);
  // The quadratic element on the same cells beats the linear one on cells
  // half their size.
  EXPECT_LT(q2_coarse.error, q1_fine.error);
  EXPECT_LT(q1_coarse.error, 0.05);
  // Energy after a period: 1.9e-3, 4.3e-4, 3.8e-4 seen; second order.
  for (const BarResult &r : {q1_coarse, q1_fine, q2_coarse})
    EXPECT_LT(r.drift, 3e-3);
  EXPECT_LT(q1_fine.drift, 0.35 * q1_coarse.drift);
}
