// Thermal expansion (heat conduction's 'Thermal expansion', issue 37): a
// block heated uniformly by a 'Heat source' from T0 = 0 by about 100 K
// (alpha = 1e-5: a thermal strain of 1e-3), slowly and smoothly, s(t) =
// s0 (1 - cos(2 pi t / t_h)) over t_h = 100 wave transits, so that it stays
// in equilibrium; no conduction is needed (uniform T). Against the closed
// forms of small-strain thermoelasticity (E = 1e6 Pa, nu = 0.3), dT the
// particles' mean temperature:
// - held between two walls, free across (slip walls are planes of
//   symmetry): sigma_xx = -E alpha dT in 3D, -E alpha dT / (1 - nu) in
//   plane strain (2D);
// - held on every side: sigma = -E alpha dT / (1 - 2 nu) in each
//   direction, sigma_zz included in 2D (the plane holds it too);
// - free: the block grows by alpha dT, and by (1 + nu) alpha dT in the
//   plane in 2D, unstressed, also while it moves.
// The tolerance, 1 % of E alpha dT, is the small-strain forms' own error
// (the thermal strain, 1e-3, times a few) with the ramp's left-over
// vibration (a smooth ramp over 100 transits leaves < 1e-4).
// The energy balance closes: the walls do no work, so the stored energy,
// the kinetic energy and the stress's work on the thermal stretch
// (dissipated_work) sum to zero, within 1 % of the stored energy.
#include <dealmpm/materials/thermal_expansion.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  constexpr double E = 1e6, nu = 0.3, rho = 1000, alpha = 1e-5;
  // The P-wave speed sqrt(E (1 - nu) / ((1 + nu) (1 - 2 nu)) / rho), 36.7
  // m/s: 100 transits of the unit block.
  const double c_p = std::sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho);
  const double t_heat        = 100 / c_p;
  constexpr double dT_target = 100;

  /** A heated block: its grid, walls, body and method. */
  struct Case
  {
    std::string name;
    std::string cells;  ///< the grid's cells (unit box)
    std::string walls;  ///< "Boundary conditions" of the grid
    std::string body;   ///< the body's upper corner (lower: the origin)
    std::string method; ///< lines of subsection MPM
    std::string model =
      "subsection linear elastic\n set Young's modulus = 1e6\n"
      " set Poisson's ratio = 0.3\nend";
    std::string velocity = ""; ///< the body's velocity, if moving
  };

  std::string
  scene(const Case &c)
  {
    std::ostringstream s;
    s << "set Effects = heat conduction\n"
      << "subsection Heat conduction\n set Initial temperature = 0\n"
      << " set Specific heat = 1\n set Thermal expansion = " << alpha
      << "\n set Heat source = " << dT_target * rho / t_heat
      << " * (1 - cos(2 * pi * t / " << t_heat << "))\nend\n"
      << "subsection MPM\n"
      << c.method << "\nend\n"
      << "subsection Grid\n set Cells = " << c.cells
      << "\n set Boundary conditions = " << c.walls << "\nend\n"
      << "subsection Material 1\n set Density = " << rho << "\n"
      << c.model << "\nend\n"
      << "subsection Body 1\n set Upper corner = " << c.body << "\n"
      << (c.velocity.empty() ? "" : " set Velocity = " + c.velocity + "\n")
      << "end\n";
    return s.str();
  }

  /** What a heated block ends with. */
  struct Heated
  {
    double                dT = 0;  ///< the particles' mean temperature
    SymmetricTensor<2, 3> stress;  ///< the particles' mean Cauchy stress
    std::vector<double>   stretch; ///< the particles' stretch()
    double                stored = 0, kinetic = 0, dissipated = 0;
  };

  /** The particles' stretch in each direction: the slope of their
   * position x against their reference position X = x - u (least
   * squares over all particles and ranks), which a uniform stretch about
   * any moving centre gives exactly. */
  template <int dim>
  std::vector<double>
  stretch(const ParticleSet<dim> &particles)
  {
    std::vector<double> sums(1 + 4 * dim);
    for (const auto &p : particles.handler)
      {
        const auto           props = p.get_properties();
        const Tensor<1, dim> u =
          read_vector<dim>(&props[particles.fields.displacement]);
        sums[0] += 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double x = p.get_location()[d], X = x - u[d];
            sums[1 + 4 * d] += x;
            sums[2 + 4 * d] += X;
            sums[3 + 4 * d] += x * X;
            sums[4 + 4 * d] += X * X;
          }
      }
    Utilities::MPI::sum(sums, MPI_COMM_WORLD, sums);
    std::vector<double> slope(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double n = sums[0], x = sums[1 + 4 * d] / n,
                     X = sums[2 + 4 * d] / n;
        slope[d] =
          (sums[3 + 4 * d] - n * x * X) / (sums[4 + 4 * d] - n * X * X);
      }
    return slope;
  }

  template <int dim>
  Heated
  heat(const Case &c)
  {
    auto                    simulation = test::make_simulation<dim>(scene(c));
    const Statistics        s          = test::run_to(*simulation, t_heat);
    const ParticleSet<dim> &particles  = simulation->particle_set();
    const unsigned int      T          = particles.layout.offset("temperature");
    Heated                  h;
    double                  n = 0;
    for (const auto &p : particles.handler)
      {
        const auto F = read_tensor<dim>(
          &p.get_properties()[particles.fields.deformation_gradient]);
        h.stress += test::kirchhoff_stress(*simulation, p) / determinant(F);
        h.dT += p.get_properties()[T];
        n += 1;
      }
    n                = Utilities::MPI::sum(n, MPI_COMM_WORLD);
    h.dT             = Utilities::MPI::sum(h.dT, MPI_COMM_WORLD) / n;
    h.stress         = Utilities::MPI::sum(h.stress, MPI_COMM_WORLD) / n;
    h.stretch        = stretch(particles);
    h.stored         = s.strain_energy;
    h.kinetic        = s.kinetic_energy;
    h.dissipated     = s.dissipated_work;
    std::string name = c.name;
    std::replace(name.begin(), name.end(), '\n', ' ');
    std::cout << name << ": dT " << h.dT << ", stress " << h.stress
              << ", stretch";
    for (const double r : h.stretch)
      std::cout << ' ' << r;
    std::cout << ", energy stored " << h.stored << " kinetic " << h.kinetic
              << " thermal work " << h.dissipated << std::endl;
    return h;
  }

  /** The energy of the walls' zero work: stored + kinetic + thermal work
   * = 0, within 1 % of the stored energy. */
  void
  expect_balance(const Heated &h, const std::string &name)
  {
    EXPECT_LT(std::abs(h.stored + h.kinetic + h.dissipated), 1e-2 * h.stored)
      << name;
  }

  const std::vector<std::string> methods = {
    "set Stress update = USL\nset Shape function = linear",
    "set Stress update = MUSL\nset Shape function = quadratic B-spline",
    "set Stress update = USF\nset Shape function = uGIMP",
    "set Stress update = USL\nset Shape function = linear\n"
    "set Formulation = total Lagrangian",
    "set Stress update = MUSL\nset Shape function = cpGIMP\n"
    "set Anti-locking = F-bar"};
} // namespace

// Held between the walls x = 0 and 1, free across: the 1D form in 3D,
// sigma_xx = -E alpha dT, and the plane-strain form in 2D, -E alpha dT /
// (1 - nu); the free sides' stresses vanish.
TEST(ThermalExpansion, BarHeldBetweenWallsTakesMinusEAlphaDeltaT)
{
  for (const std::string &method : methods)
    {
      const Heated h3 = heat<3>({"3D " + method,
                                 "6, 3, 3",
                                 "0: slip, 1: slip, 2: slip, 4: slip",
                                 "1, 0.5, 0.5",
                                 method});
      const double s3 = -E * alpha * h3.dT;
      // The source heats the current volume, which grows by at most
      // 3 alpha dT = 0.3 %.
      EXPECT_NEAR(h3.dT, dT_target, 5e-3 * dT_target) << method;
      EXPECT_NEAR(h3.stress[0][0], s3, 1e-2 * std::abs(s3)) << method;
      EXPECT_NEAR(h3.stress[1][1], 0, 1e-2 * std::abs(s3)) << method;
      EXPECT_NEAR(h3.stress[2][2], 0, 1e-2 * std::abs(s3)) << method;
      expect_balance(h3, "3D " + method);

      const Heated h2 = heat<2>({"2D " + method,
                                 "8, 8",
                                 "0: slip, 1: slip, 2: slip",
                                 "1, 0.5",
                                 method});
      const double s2 = -E * alpha * h2.dT / (1 - nu);
      EXPECT_NEAR(h2.stress[0][0], s2, 1e-2 * std::abs(s2)) << method;
      EXPECT_NEAR(h2.stress[1][1], 0, 1e-2 * std::abs(s2)) << method;
      EXPECT_NEAR(h2.stress[2][2], s2, 1e-2 * std::abs(s2)) << method;
      expect_balance(h2, "2D " + method);
    }
}

// Held on every side: -E alpha dT / (1 - 2 nu) in every direction, the
// plane's sigma_zz included; with linear elasticity, neo-Hookean and J2
// below its yield (Hencky elasticity), on two resolutions.
TEST(ThermalExpansion, BoxHeldOnEverySideTakesTheBulkForm)
{
  const std::string elastic = "set Young's modulus = 1e6\n"
                              "set Poisson's ratio = 0.3\n";
  for (const std::string &model :
       {"subsection linear elastic\n" + elastic + "end",
        "set Model = neo-Hookean\nsubsection neo-Hookean\n" + elastic + "end",
        "set Model = J2 plasticity\nsubsection J2 plasticity\n" + elastic +
          "set Yield stress = 1e6\nend"})
    for (const unsigned int cells : {4u, 8u})
      {
        const std::string n = std::to_string(cells);
        Case              c3{"3D " + model,
                n + ", " + n + ", " + n,
                "0: slip, 1: slip, 2: slip, 3: slip, 4: slip, 5: slip",
                "1, 1, 1",
                methods[cells == 4 ? 0 : 1],
                model};
        const Heated      h3 = heat<3>(c3);
        const double      s  = -E * alpha * h3.dT / (1 - 2 * nu);
        for (unsigned int d = 0; d < 3; ++d)
          EXPECT_NEAR(h3.stress[d][d], s, 1e-2 * std::abs(s)) << model;
        expect_balance(h3, c3.name);

        Case         c2{"2D " + model,
                n + ", " + n,
                "0: slip, 1: slip, 2: slip, 3: slip",
                "1, 1",
                methods[cells == 4 ? 2 : 0],
                model};
        const Heated h2 = heat<2>(c2);
        const double s2 = -E * alpha * h2.dT / (1 - 2 * nu);
        for (unsigned int d = 0; d < 3; ++d)
          EXPECT_NEAR(h2.stress[d][d], s2, 1e-2 * std::abs(s2)) << model;
        expect_balance(h2, c2.name);
      }
}

// Free, at rest and moving: the block grows by 1 + alpha dT (3D) and 1 +
// (1 + nu) alpha dT (2D, in the plane) in every direction, within 1 % of
// the growth, and carries no stress (1 % of E alpha dT).
TEST(ThermalExpansion, FreeBlockGrowsByAlphaDeltaT)
{
  for (const char *velocity : {"", "0.05, 0.02"})
    for (const std::string &method : methods)
      {
        Case c2{"free 2D " + method + " " + velocity,
                "10, 10",
                "",
                "0.5, 0.5",
                method};
        c2.velocity     = velocity;
        const Heated h2 = heat<2>(c2);
        for (unsigned int d = 0; d < 2; ++d)
          EXPECT_NEAR(h2.stretch[d] - 1,
                      (1 + nu) * alpha * h2.dT,
                      1e-2 * (1 + nu) * alpha * h2.dT)
            << c2.name;
        for (unsigned int d = 0; d < 2; ++d)
          EXPECT_NEAR(h2.stress[d][d], 0, 1e-2 * E * alpha * h2.dT) << c2.name;
      }
  const Heated h3 = heat<3>({"free 3D",
                             "6, 6, 6",
                             "",
                             "0.5, 0.5, 0.5",
                             methods[1],
                             "",
                             "0.04, 0.02, 0"});
  for (unsigned int d = 0; d < 3; ++d)
    EXPECT_NEAR(h3.stretch[d] - 1, alpha * h3.dT, 1e-2 * alpha * h3.dT);
}

// Plastic flow under a thermal load: a J2 bar held between walls (3D,
// free across) whose thermal stress -E alpha dT = -1e3 Pa would pass its
// yield stress of 500 Pa stops there (perfect plasticity), and the stress's
// work on the thermal stretch is what the stored energy and the plastic
// work took.
TEST(ThermalExpansion, HeldJ2BarYieldsAtItsYieldStress)
{
  Case         c{"J2 bar",
         "6, 3, 3",
         "0: slip, 1: slip, 2: slip, 4: slip",
         "1, 0.5, 0.5",
         methods[0],
         "set Model = J2 plasticity\nsubsection J2 plasticity\n"
                 "set Young's modulus = 1e6\nset Poisson's ratio = 0.3\n"
                 "set Yield stress = 500\nend"};
  const Heated h = heat<3>(c);
  EXPECT_NEAR(h.stress[0][0], -500, 5);
  EXPECT_NEAR(h.stress[1][1], 0, 5);
  EXPECT_GT(h.dissipated, -h.stored);
}

// The plane-strain expansion's nu and mu come from the model's response to
// a small strain: exact for linear elasticity (nu 0.3 of E 1e6: mu =
// 384,615 Pa), to 1e-6 for neo-Hookean (its tangent at F = I), and mu = 0
// for the Tait fluid (nu = 1/2: the in-plane stretch is 3/2 alpha, the
// volume's 3 alpha).
TEST(ThermalExpansion, InitialElasticConstantsOfAModel)
{
  const std::string elastic = "set Young's modulus = 1e6\n"
                              "set Poisson's ratio = 0.3\n";
  for (const std::string &model :
       {"subsection linear elastic\n" + elastic + "end",
        "set Model = neo-Hookean\nsubsection neo-Hookean\n" + elastic + "end"})
    {
      auto simulation = test::make_simulation<2>(
        "subsection Material 1\n" + model +
        "\nend\nsubsection Body 1\n set Upper corner = 0.5, 0.5\nend\n");
      const auto lame = initial_elastic_constants(simulation->material(0));
      ASSERT_TRUE(lame.has_value());
      EXPECT_NEAR(lame->mu, E / (2 * (1 + nu)), 1e-6 * E) << model;
      EXPECT_NEAR(lame->lambda / (2 * (lame->lambda + lame->mu)), nu, 1e-6)
        << model;
    }
  auto fluid = test::make_simulation<2>(
    "subsection Material 1\n set Model = Tait fluid\nend\n"
    "subsection Body 1\n set Upper corner = 0.5, 0.5\nend\n");
  const auto lame = initial_elastic_constants(fluid->material(0));
  ASSERT_TRUE(lame.has_value());
  EXPECT_NEAR(lame->mu, 0, 1e-6 * lame->lambda);
}
