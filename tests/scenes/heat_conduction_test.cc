// Heat conduction (effect 'heat conduction'), issue 37's first part: a
// long bar at rest, one row of cells between slip walls, 2 x 2 particles a
// cell, nothing moving. Against closed forms, on 20, 40 and 80 cells, with
// linear shape functions (USL) and the quadratic B-spline (MUSL):
// - its end x = 0 held at T1 = 100 K from t = 0, T0 = 0: the semi-infinite
//   bar's T = T1 erfc(x / (2 sqrt(alpha t))), alpha = k / (rho c) = 1e-3
//   m^2/s, at t = 10 s (the far end stays at T0);
// - both ends held at 0, the first mode T1 sin(pi x) decays as exp(-alpha
//   pi^2 t), at t = 50 s.
// The error (rms over the particles, / T1) falls at second order (seen
// 1.95-2.5; the bound asks for 1.9): the particles carry their temperature
// gradient g_p and each node takes T_p + g_p . (x_i - x_c), so a field
// linear over a particle's support maps exactly, also beside a held wall.
// Without the gradient the order was 1.5: the nodes beside a wall took the
// particles' mean, an O(h) error in a layer O(h) wide. The heat balance
// closes to round-off: what the particles store grows by what the held
// ends gave (heat_in), 1e-10.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double T1 = 100, k = 1, rho = 1000, c = 1, alpha = k / (rho * c);

  /** The bar on @p cells cells; @p boundary: the heat conduction
   * section's lines for its ends (beyond 'Fixed temperatures = @p
   * fixed'); @p density rho unless given. */
  std::string
  bar(const unsigned int cells,
      const std::string &method,
      const std::string &initial,
      const std::string &fixed,
      const std::string &boundary = "",
      const double       density  = rho)
  {
    std::ostringstream s;
    s << "set Effects = heat conduction\n"
      << "subsection Heat conduction\n set Initial temperature = " << initial
      << "\n set Conductivity = " << k << "\n set Specific heat = " << c
      << "\n set Fixed temperatures = " << fixed << "\n"
      << boundary << "\nend\n"
      << "subsection MPM\n"
      << method << "\nend\n"
      << "subsection Grid\n set Upper corner = 1, " << 1. / cells
      << "\n set Cells = " << cells << ", 1\n"
      << " set Boundary conditions = 0: slip, 1: slip, 2: slip, 3: slip\n"
      << "end\nsubsection Material 1\n set Density = " << density
      << "\n subsection linear elastic\n  set Young's modulus = 1e3\n"
      << " end\nend\nsubsection Body 1\n set Upper corner = 1, " << 1. / cells
      << "\nend\n";
    return s.str();
  }

  struct BarResult
  {
    double error;   ///< rms of T - exact over the particles, / T1
    double balance; ///< |stored - stored_0 - heat_in| / heat_in
  };

  /** The bar from @p initial with @p fixed ends, run to @p t_end,
   * against @p exact(x). */
  BarResult
  heated_bar(const unsigned int                   cells,
             const std::string                   &method,
             const std::string                   &initial,
             const std::string                   &fixed,
             const double                         t_end,
             const std::function<double(double)> &exact)
  {
    auto simulation =
      test::make_simulation<2>(bar(cells, method, initial, fixed));
    const double stored_0 =
      test::effect_column(simulation->statistics(), "heat_stored");
    while (simulation->time() < t_end - 1e-12)
      simulation->advance(
        std::min(simulation->time_step(), t_end - simulation->time()));
    const ParticleSet<2> &particles = simulation->particle_set();
    const unsigned int    T         = particles.layout.offset("temperature");
    double                sum = 0, n = 0;
    for (const auto &p : particles.handler)
      {
        const double x = p.get_location()[0];
        sum += std::pow((p.get_properties()[T] - exact(x)) / T1, 2);
        n += 1;
      }
    const Statistics s       = simulation->statistics();
    const double     stored  = test::effect_column(s, "heat_stored");
    const double     heat_in = test::effect_column(s, "heat_in");
    sum                      = Utilities::MPI::sum(sum, MPI_COMM_WORLD);
    n                        = Utilities::MPI::sum(n, MPI_COMM_WORLD);
    return {std::sqrt(sum / n),
            std::abs(stored - stored_0 - heat_in) /
              std::max(std::abs(heat_in), std::abs(stored_0))};
  }
} // namespace

namespace
{
  /** The bar on 20, 40 and 80 cells with linear shape functions (USL) and
   * the B-spline (MUSL): the error falls at order 1.9 or more, and the heat
   * balance closes to round-off. */
  void
  expect_convergence(const std::string                   &initial,
                     const std::string                   &fixed,
                     const double                         t_end,
                     const std::function<double(double)> &exact)
  {
    for (const std::string method :
         {"set Stress update = USL\nset Shape function = linear",
          "set Stress update = MUSL\nset Shape function = quadratic B-spline"})
      {
        std::vector<double> errors;
        for (const unsigned int cells : {20u, 40u, 80u})
          {
            const BarResult r =
              heated_bar(cells, method, initial, fixed, t_end, exact);
            std::cout << initial << ", " << method << ", " << cells
                      << " cells: error " << r.error << ", heat balance "
                      << r.balance << std::endl;
            errors.push_back(r.error);
            EXPECT_LT(r.balance, 1e-10) << method << ", " << cells;
          }
        for (unsigned int i = 1; i < errors.size(); ++i)
          EXPECT_GT(std::log2(errors[i - 1] / errors[i]), 1.9) << method;
      }
  }
} // namespace

TEST(HeatConduction, BarHeatedAtItsEndFollowsErfc)
{
  expect_convergence("0", "0: 100", 10, [](const double x) {
    return T1 * std::erfc(x / (2 * std::sqrt(alpha * 10)));
  });
}

// The end x = 0 held at 100 K times a 'Temperature curve' rising from 0
// at t = 0 to 1 at t = 10 s, T = r t with r = 10 K/s: the semi-infinite
// bar's T = 4 r t i^2erfc(x / (2 sqrt(alpha t))) = r t ((1 + x^2 / (2
// alpha t)) erfc(eta) - x / sqrt(pi alpha t) exp(-eta^2)) (Carslaw and
// Jaeger 2.5), at t = 10 s; linear shape functions on 20, 40 and 80
// cells: order >= 1.8 (seen 1.91, 1.85: the held end's rate jumps from 0
// to r at t = 0, a kink the step's time error resolves more slowly than
// the held end's smooth erfc) and the balance to round-off.
TEST(HeatConduction, HeldEndFollowsItsTemperatureCurve)
{
  std::vector<double> errors;
  for (const unsigned int cells : {20u, 40u, 80u})
    {
      auto simulation = test::make_simulation<2>(
        bar(cells,
            "set Stress update = USL\nset Shape function = linear",
            "0",
            "0: 100",
            " set Temperature curve = 0: 0, 10: 1"));
      const Statistics      s         = test::run_to(*simulation, 10.);
      const ParticleSet<2> &particles = simulation->particle_set();
      const unsigned int    T         = particles.layout.offset("temperature");
      double                sum = 0, n = 0;
      for (const auto &p : particles.handler)
        {
          const double x = p.get_location()[0], t = 10, r = 10;
          const double eta = x / (2 * std::sqrt(alpha * t));
          const double exact =
            r * t *
            ((1 + 2 * eta * eta) * std::erfc(eta) -
             2 / std::sqrt(M_PI) * eta * std::exp(-eta * eta));
          sum += std::pow((p.get_properties()[T] - exact) / T1, 2);
          n += 1;
        }
      errors.push_back(std::sqrt(Utilities::MPI::sum(sum, MPI_COMM_WORLD) /
                                 Utilities::MPI::sum(n, MPI_COMM_WORLD)));
      const double heat_in = test::effect_column(s, "heat_in");
      std::cout << "ramped end, " << cells << " cells: error " << errors.back()
                << std::endl;
      EXPECT_NEAR(test::effect_column(s, "heat_stored"),
                  heat_in,
                  1e-10 * heat_in);
    }
  for (unsigned int i = 1; i < errors.size(); ++i)
    EXPECT_GT(std::log2(errors[i - 1] / errors[i]), 1.8);
}

// A smooth start: the bar's first mode T1 sin(pi x) with both ends held
// at 0 decays as exp(-alpha pi^2 t); at t = 50 s (to 0.61).
TEST(HeatConduction, FirstModeDecays)
{
  expect_convergence("100 * sin(pi * x)", "0: 0, 1: 0", 50, [](double x) {
    return T1 * std::sin(M_PI * x) * std::exp(-alpha * M_PI * M_PI * 50);
  });
}

// A scene that does not list heat conduction has no temperature, no
// timer row and no heat columns.
TEST(HeatConduction, UnlistedCostsNothing)
{
  auto plain = test::make_simulation<2>(
    "subsection Body 1\n set Upper corner = 0.5, 0.5\nend\n");
  plain->advance(1e-3);
  EXPECT_FALSE(plain->particle_set().layout.has("temperature"));
  EXPECT_EQ(plain->timer()
              .get_summary_data(TimerOutput::total_wall_time)
              .count("effect: heat conduction"),
            0u);
  for (const std::string &column : plain->statistics().effect_columns)
    EXPECT_EQ(column.find("heat"), std::string::npos);
}

namespace
{
  /** The bar (rho = 1: alpha = 1 m^2/s) from 0 K to t = 8 s with the
   * ends @p fixed and @p boundary: the rms error against the steady
   * @p exact(x), / @p scale, and the heat balance. */
  BarResult
  steady_bar(const unsigned int                   cells,
             const std::string                   &method,
             const std::string                   &fixed,
             const std::string                   &boundary,
             const std::function<double(double)> &exact,
             const double                         scale)
  {
    auto simulation =
      test::make_simulation<2>(bar(cells, method, "0", fixed, boundary, 1.));
    const Statistics      s         = test::run_to(*simulation, 8.);
    const ParticleSet<2> &particles = simulation->particle_set();
    const unsigned int    T         = particles.layout.offset("temperature");
    double                sum = 0, n = 0;
    for (const auto &p : particles.handler)
      {
        sum +=
          std::pow((p.get_properties()[T] - exact(p.get_location()[0])) / scale,
                   2);
        n += 1;
      }
    const double stored  = test::effect_column(s, "heat_stored");
    const double heat_in = test::effect_column(s, "heat_in");
    sum                  = Utilities::MPI::sum(sum, MPI_COMM_WORLD);
    n                    = Utilities::MPI::sum(n, MPI_COMM_WORLD);
    return {std::sqrt(sum / n), std::abs(stored - heat_in) / std::abs(stored)};
  }

  /** steady_bar() on 10 and 20 cells, linear (USL) and B-spline (MUSL):
   * the particles carry their temperature gradient to the nodes, so a
   * linear field maps and conducts exactly and the steady line is the
   * discrete solution too; the error is the transient left at t = 8 s
   * (below 1e-6), bounded by 1e-5. The balance closes to round-off. */
  void
  expect_steady(const std::string                   &fixed,
                const std::string                   &boundary,
                const std::function<double(double)> &exact,
                const double                         scale)
  {
    for (const std::string method :
         {"set Stress update = USL\nset Shape function = linear",
          "set Stress update = MUSL\nset Shape function = quadratic B-spline"})
      for (const unsigned int cells : {10u, 20u})
        {
          const BarResult r =
            steady_bar(cells, method, fixed, boundary, exact, scale);
          std::cout << boundary << ", " << method << ", " << cells
                    << " cells: error " << r.error << ", heat balance "
                    << r.balance << std::endl;
          EXPECT_LT(r.error, 1e-5) << method << ", " << cells;
          EXPECT_LT(r.balance, 1e-10) << method << ", " << cells;
        }
  }
} // namespace

// No end held: a flux q = 50 W/m^2 into the end x = 0, convection h = 10
// W/m^2/K at x = 1 to T_a = 100 K. Steady, all of q leaves at x = 1: T(1)
// = T_a + q / h = 105 K and T = 105 + q (1 - x) / k (the slowest mode,
// mu tan mu = h / k, mu = 1.43, has decayed by exp(-mu^2 8) = 8e-8 at t =
// 8 s).
TEST(HeatConduction, FluxInConvectionOutGivesTheSteadyLine)
{
  expect_steady(
    "",
    " set Heat fluxes = 0: 50\n set Convection = 1: 10\n"
    " set Ambient temperature = 100",
    [](const double x) { return 105 + 50 * (1 - x) / k; },
    50);
}

// The same with the ambient temperature 50 K times an 'Ambient curve' of
// 2: the same line (linear, USL, 10 cells).
TEST(HeatConduction, AmbientFollowsItsCurve)
{
  const BarResult r = steady_bar(
    10,
    "set Stress update = USL\nset Shape function = linear",
    "",
    " set Heat fluxes = 0: 50\n set Convection = 1: 10\n"
    " set Ambient temperature = 50\n set Ambient curve = 0: 2, 1: 2",
    [](const double x) { return 105 + 50 * (1 - x) / k; },
    50);
  EXPECT_LT(r.error, 1e-5);
  EXPECT_LT(r.balance, 1e-10);
}

// A flux into x = 0 and the end x = 1 held at 0: T = q (1 - x) / k.
TEST(HeatConduction, FluxIntoAnEndHeldAtTheOtherGivesTheSteadyLine)
{
  expect_steady(
    "1: 0",
    " set Heat fluxes = 0: 50",
    [](const double x) { return 50 * (1 - x) / k; },
    50);
}

// The flux's heat follows its curve: q = 50 W/m^2 times a factor rising
// from 0 to 2 over 1 s into an otherwise insulated bar stores q A t_end
// (A the end's area, 1/20 m^2 per metre) exactly: the factor taken at
// mid-step is exact for a linear curve.
TEST(HeatConduction, FluxFollowsItsCurve)
{
  auto simulation = test::make_simulation<2>(
    bar(20,
        "set Shape function = linear",
        "0",
        "",
        " set Heat fluxes = 0: 50\n set Flux curve = 0: 0, 1: 2",
        1.));
  const Statistics s = test::run_to(*simulation, 0.5);
  // The integral of 50 * 2 t over 0.5 s, on 1/20 m^2.
  const double expected = 50 * 0.25 / 20;
  EXPECT_NEAR(test::effect_column(s, "heat_in"), expected, 1e-12 * expected);
  EXPECT_NEAR(test::effect_column(s, "heat_stored"),
              expected,
              1e-10 * expected);
}

namespace
{
  /** The steady plate's temperature with the side y = 1 at 1 and the
   * others at 0 (the series, to 1e-12 away from the top corners). */
  double
  plate_series(const double x, const double y)
  {
    double sum = 0;
    for (double n = 1; n < 400; n += 2)
      sum += std::sin(n * M_PI * x) * std::exp(n * M_PI * (y - 1)) *
             (1 - std::exp(-2 * n * M_PI * y)) /
             (n * (1 - std::exp(-2 * n * M_PI)));
    return 4 / M_PI * sum;
  }
} // namespace

// Steady conduction in a unit square plate (rho = c = k = 1), the side y
// = 1 held at 1 K and the others at 0, against the series T = 4/pi sum
// over odd n of sin(n pi x) sinh(n pi y) / (n sinh(n pi)), at t = 0.8 s
// (the slowest mode has decayed by exp(-2 pi^2 0.8) = 1.4e-7). The top
// corners, where 1 meets 0, are singular: the rms error is taken below y
// = 0.75 (4.8e-3, 8.3e-4 on 10 and 20 cells); at the centre T = 1/4 by
// symmetry (the four rotations of the plate sum to 1; seen 0.2543,
// 0.2510). Both errors fall at order 1.8 or more from 10 to 20 cells (2.5
// and 2.1 seen), and the centre is within 0.5 % on 20 cells.
TEST(HeatConduction, SteadyPlateFollowsTheSeries)
{
  std::vector<double> errors, centre_errors;
  for (const unsigned int cells : {10u, 20u})
    {
      std::ostringstream s;
      s << "set Effects = heat conduction\n"
        << "subsection Heat conduction\n set Initial temperature = 0\n"
        << " set Conductivity = 1\n set Specific heat = 1\n"
        << " set Fixed temperatures = 0: 0, 1: 0, 2: 0, 3: 1\nend\n"
        << "subsection Grid\n set Cells = " << cells << ", " << cells
        << "\n set Boundary conditions = 0: slip, 1: slip, 2: slip, 3: slip"
        << "\nend\nsubsection Material 1\n set Density = 1\n"
        << " subsection linear elastic\n  set Young's modulus = 1e3\n end\n"
        << "end\nsubsection Body 1\n set Upper corner = 1, 1\nend\n";
      auto simulation = test::make_simulation<2>(s.str());
      test::run_to(*simulation, 0.8);
      const ParticleSet<2> &particles = simulation->particle_set();
      const unsigned int    T         = particles.layout.offset("temperature");
      double                sum = 0, n = 0, centre = 0, n_centre = 0;
      for (const auto &p : particles.handler)
        {
          const Point<2> x   = p.get_location();
          const double   T_p = p.get_properties()[T];
          if (x[1] < 0.75)
            {
              sum += std::pow(T_p - plate_series(x[0], x[1]), 2);
              n += 1;
            }
          if (std::abs(x[0] - 0.5) < 0.5 / cells &&
              std::abs(x[1] - 0.5) < 0.5 / cells)
            {
              centre += T_p - plate_series(x[0], x[1]) + 0.25;
              n_centre += 1;
            }
        }
      errors.push_back(std::sqrt(Utilities::MPI::sum(sum, MPI_COMM_WORLD) /
                                 Utilities::MPI::sum(n, MPI_COMM_WORLD)));
      centre = Utilities::MPI::sum(centre, MPI_COMM_WORLD) /
               Utilities::MPI::sum(n_centre, MPI_COMM_WORLD);
      std::cout << "plate, " << cells << " cells: rms error below y = 0.75 "
                << errors.back() << ", centre " << centre << std::endl;
      centre_errors.push_back(std::abs(centre - 0.25));
    }
  EXPECT_GT(std::log2(errors[0] / errors[1]), 1.8);
  EXPECT_GT(std::log2(centre_errors[0] / centre_errors[1]), 1.8);
  EXPECT_LT(centre_errors[1], 0.005 * 0.25);
}

// The first mode in 3D: the bar one cell square across, both ends held
// at 0, 2 x 2 x 2 particles a cell, linear (USL) and B-spline (MUSL) on 20
// and 40 cells: the error falls at second order, the same errors as the
// 2D bar's to six digits (4.16e-4, 9.83e-5 linear; 1.37e-3, 3.41e-4
// B-spline), and the heat balance closes to round-off.
TEST(HeatConduction, FirstModeDecaysIn3d)
{
  for (const std::string method :
       {"set Stress update = USL\nset Shape function = linear",
        "set Stress update = MUSL\nset Shape function = quadratic B-spline"})
    {
      std::vector<double> errors;
      for (const unsigned int cells : {20u, 40u})
        {
          const double       h = 1. / cells;
          std::ostringstream s;
          s << "set Effects = heat conduction\n"
            << "subsection Heat conduction\n"
            << " set Initial temperature = 100 * sin(pi * x)\n"
            << " set Conductivity = " << k << "\n set Specific heat = " << c
            << "\n set Fixed temperatures = 0: 0, 1: 0\nend\n"
            << "subsection MPM\n"
            << method << "\nend\n"
            << "subsection Grid\n set Upper corner = 1, " << h << ", " << h
            << "\n set Cells = " << cells << ", 1, 1\n"
            << " set Boundary conditions = 0: slip, 1: slip, 2: slip, "
               "3: slip, 4: slip, 5: slip\n"
            << "end\nsubsection Material 1\n set Density = " << rho
            << "\n subsection linear elastic\n  set Young's modulus = 1e3\n"
            << " end\nend\nsubsection Body 1\n set Upper corner = 1, " << h
            << ", " << h << "\nend\n";
          auto         simulation = test::make_simulation<3>(s.str());
          const double stored_0 =
            test::effect_column(simulation->statistics(), "heat_stored");
          const Statistics      end       = test::run_to(*simulation, 50.);
          const ParticleSet<3> &particles = simulation->particle_set();
          const unsigned int    T   = particles.layout.offset("temperature");
          double                sum = 0, n = 0;
          for (const auto &p : particles.handler)
            {
              const double exact = T1 * std::sin(M_PI * p.get_location()[0]) *
                                   std::exp(-alpha * M_PI * M_PI * 50);
              sum += std::pow((p.get_properties()[T] - exact) / T1, 2);
              n += 1;
            }
          errors.push_back(std::sqrt(Utilities::MPI::sum(sum, MPI_COMM_WORLD) /
                                     Utilities::MPI::sum(n, MPI_COMM_WORLD)));
          const double stored  = test::effect_column(end, "heat_stored");
          const double heat_in = test::effect_column(end, "heat_in");
          std::cout << "3D, " << method << ", " << cells << " cells: error "
                    << errors.back() << ", heat balance "
                    << (stored - stored_0 - heat_in) / stored_0 << std::endl;
          EXPECT_LT(std::abs(stored - stored_0 - heat_in), 1e-10 * stored_0);
        }
      EXPECT_GT(std::log2(errors[0] / errors[1]), 1.9) << method;
    }
}

// Through grid changes: the adaptive disk drop (prm/disk_drop_adaptive.prm,
// six grids) with a temperature of 100 x K/m across the disk and no
// boundary: the heat the particles store stays at its start to round-off
// (1e-12; seen 3e-15) at every step, as the grid refines and coarsens
// under them and the nodal vectors are rebuilt. (The fine cells' buffer
// layer keeps the hanging nodes away from the particles here.)
TEST(HeatConduction, HeatIsKeptThroughGridAdaptations)
{
  std::ifstream     file(DEALMPM_SOURCE_DIR "/prm/disk_drop_adaptive.prm");
  std::stringstream text;
  text << file.rdbuf() << "\nset Effects = gravity, heat conduction\n"
       << "subsection Heat conduction\n set Initial temperature = 100 * x\n"
       << " set Conductivity = 1\n set Specific heat = 1\nend\n"
       << "subsection Adaptivity\n set Split particles = false\nend\n";
  auto         simulation = test::make_simulation<2>(text.str());
  const double stored_0 =
    test::effect_column(simulation->statistics(), "heat_stored");
  std::set<types::global_cell_index> cell_counts;
  double                             largest_change = 0;
  while (simulation->time() < 0.5 - 1e-12)
    {
      simulation->advance(simulation->time_step());
      if (simulation->step_number() % 10 == 0) // as the program's run does
        simulation->adapt_grid();
      cell_counts.insert(
        simulation->background_grid().triangulation.n_global_active_cells());
      largest_change =
        std::max(largest_change,
                 std::abs(test::effect_column(simulation->statistics(),
                                              "heat_stored") -
                          stored_0));
    }
  std::cout << cell_counts.size() << " grids, largest change of the heat "
            << largest_change << " of " << stored_0 << std::endl;
  EXPECT_GT(cell_counts.size(), 2u);
  EXPECT_LT(largest_change, 1e-12 * stored_0);
}
