// A column that starts geostatic ('Body 1/Initial stress = geostatic') is
// at rest under gravity from the first step: sigma_yy = -rho g (H - y) and
// sigma_xx = K0 sigma_yy at every particle at t = 0, and with no damping its
// kinetic energy stays below 1e-10 of its strain energy over 0.5 s (1.4
// periods of its first axial mode, 4 H / c = 0.37 s). Started stress-free,
// the same column falls into its own weight: its kinetic energy exceeds a
// tenth of the geostatic strain energy. Linear elastic (a rate form) and
// neo-Hookean (stress from F), with a K0 given and with the material's own
// nu / (1 - nu); Modified Cam-Clay (on its yield surface at rest, and
// lightly overconsolidated: p_c 1.5 times that surface's).
#include <dealmpm/materials/modified_cam_clay.h>

#include <gtest/gtest.h>

#include <cmath>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const std::string elastic_entries = R"(
    set Young's modulus = 1e7
    set Poisson's ratio = 0.25
)";

  /** A clay normally consolidated from 100 Pa: loaded to its geostatic
   * stress, every particle yields and rests on its yield surface. */
  const std::string clay_entries = R"(
    set Critical state ratio = 1.2
    set Compression index    = 0.1
    set Swelling index       = 0.02
    set Shear modulus        = 3e6
    set Reference pressure   = 100
)";

  std::string
  column(const std::string &model,
         const std::string &initial_stress,
         const std::string &K0,
         const std::string &entries = elastic_entries)
  {
    return R"(
set Dimension = 2
set Effects   = gravity
subsection Grid
  set Lower corner        = 0, 0
  set Upper corner        = 1, 10
  set Cells               = 2, 20
  set Boundary conditions = 0: slip, 1: slip, 2: slip
end
subsection Material 1
  set Model   = )" +
           model + R"(
  set Density = 1000
  subsection )" +
           model + entries + R"(
  end
end
subsection Body 1
  set Shape          = box
  set Lower corner   = 0, 0
  set Upper corner   = 1, 10
  set Initial stress = )" +
           initial_stress + R"(
  set K0             = )" +
           K0 + R"(
end
subsection Gravity
  set Acceleration = 0, -9.81
end
)";
  }

  /** The largest kinetic energy over 0.5 s. */
  double
  largest_kinetic_energy(Simulation<2> &simulation)
  {
    double largest = 0;
    while (simulation.time() < 0.5)
      {
        simulation.advance(simulation.time_step());
        largest = std::max(largest, simulation.statistics().kinetic_energy);
      }
    return largest;
  }
} // namespace

TEST(Geostatic, ColumnStartsAtRestUnderItsWeight)
{
  double geostatic_strain_energy = 0;
  for (const std::string model : {"linear elastic", "neo-Hookean"})
    for (const std::string K0 : {"0.6", "elastic"})
      {
        auto simulation =
          test::make_simulation<2>(column(model, "geostatic", K0));
        const double      expected_K0 = K0 == "elastic" ? 0.25 / 0.75 : 0.6;
        const auto       &particles   = simulation->particle_set();
        const CoreFields &f           = particles.fields;
        double            worst_yy = 0, worst_xx = 0;
        for (const auto &p : particles.handler)
          {
            const auto stress =
              read_symmetric<2>(&p.get_properties()[f.stress]);
            const double sigma_v = -1000 * 9.81 * (10 - p.get_location()[1]);
            worst_yy = std::max(worst_yy, std::abs(stress[1][1] - sigma_v));
            worst_xx = std::max(worst_xx,
                                std::abs(stress[0][0] - expected_K0 * sigma_v));
          }
        const double rho_g_H = 1000 * 9.81 * 10;
        EXPECT_LT(worst_yy, 1e-9 * rho_g_H) << model << ", K0 = " << K0;
        // The material's own K0 comes from a confined compression of 1e-6:
        // nu / (1 - nu) to about 1e-6 for neo-Hookean.
        EXPECT_LT(worst_xx, (K0 == "elastic" ? 1e-6 : 1e-9) * rho_g_H)
          << model << ", K0 = " << K0;
        const double strain_energy = simulation->statistics().strain_energy;
        const double share =
          largest_kinetic_energy(*simulation) / strain_energy;
        std::cout << model << ", K0 = " << K0
                  << ": largest kinetic energy over 0.5 s / strain energy at "
                     "the start: "
                  << share << std::endl;
        EXPECT_LT(share, 1e-10) << model << ", K0 = " << K0;
        if (model == "linear elastic" && K0 == "elastic")
          geostatic_strain_energy = strain_energy;
      }
  // cpGIMP's domains are those the body was filled with: they still tile
  // it, and the column rests.
  {
    auto simulation = test::make_simulation<2>(
      column("linear elastic", "geostatic", "elastic") +
      "subsection MPM\n set Shape function = cpGIMP\nend\n");
    const double strain_energy = simulation->statistics().strain_energy;
    const double share = largest_kinetic_energy(*simulation) / strain_energy;
    std::cout << "linear elastic, cpGIMP: largest kinetic energy over 0.5 s / "
                 "strain energy at the start: "
              << share << std::endl;
    EXPECT_LT(share, 1e-10);
  }
  // Modified Cam-Clay, whose unstrained state carries its reference
  // pressure: every particle is put on its stress by a plastic loading
  // from there, and the column rests. Its K0 is given (a normally
  // consolidated clay's own K0 at rest is not what a tiny confined
  // compression from the tip of its yield surface gives).
  for (const std::string K0 : {"0.6", "0.8"})
    {
      auto simulation = test::make_simulation<2>(
        column("Modified Cam-Clay", "geostatic", K0, clay_entries));
      const CoreFields &f        = simulation->particle_set().fields;
      double            worst_yy = 0;
      double            worst_K0 = 0;
      for (const auto &p : simulation->particle_set().handler)
        {
          const auto stress = read_symmetric<2>(&p.get_properties()[f.stress]);
          const double sigma_v = -1000 * 9.81 * (10 - p.get_location()[1]);
          worst_yy = std::max(worst_yy, std::abs(stress[1][1] - sigma_v));
          if (K0 == "0.6")
            worst_K0 =
              std::max(worst_K0, std::abs(stress[0][0] - 0.6 * sigma_v));
        }
      EXPECT_LT(worst_yy, 1e-9 * 1000 * 9.81 * 10) << "clay, K0 = " << K0;
      EXPECT_LT(worst_K0, 1e-9 * 1000 * 9.81 * 10) << "clay, K0 = " << K0;
      const double strain_energy = simulation->statistics().strain_energy;
      const double share = largest_kinetic_energy(*simulation) / strain_energy;
      std::cout << "Modified Cam-Clay, K0 = " << K0
                << ": largest kinetic energy over 0.5 s / strain energy at "
                   "the start: "
                << share << std::endl;
      EXPECT_LT(share, 1e-10) << "clay, K0 = " << K0;
    }
  // Lightly overconsolidated: every particle's p_c is 1.5 times the yield
  // surface's through its stress at rest (normally consolidated it was 1),
  // and the column rests as well.
  {
    auto simulation = test::make_simulation<2>(
      column("Modified Cam-Clay",
             "geostatic",
             "0.6",
             clay_entries + "    set Overconsolidation ratio = 1.5\n"));
    const ParticleSet<2> &particles = simulation->particle_set();
    const unsigned int    pc =
      particles.internal_offset[0] + ModifiedCamClay<2>::preconsolidation_index;
    double worst = 0;
    for (const auto &p : particles.handler)
      {
        const auto                  props = p.get_properties();
        const SymmetricTensor<2, 3> tau =
          test::kirchhoff_stress(*simulation, p);
        const double p_  = -trace(tau) / 3.;
        const double q   = std::sqrt(1.5) * deviator(tau).norm();
        const double p_c = p_ + q * q / (1.2 * 1.2 * p_);
        worst            = std::max(worst, std::abs(props[pc] / p_c - 1.5));
      }
    EXPECT_LT(worst, 1e-9) << "overconsolidated clay";
    const double strain_energy = simulation->statistics().strain_energy;
    EXPECT_LT(largest_kinetic_energy(*simulation) / strain_energy, 1e-10)
      << "overconsolidated clay";
  }
  // Stress-free at the start, it falls into its weight.
  auto simulation =
    test::make_simulation<2>(column("linear elastic", "none", "elastic"));
  EXPECT_GT(largest_kinetic_energy(*simulation) / geostatic_strain_energy, 0.1);
}

// A slope drawn as a polygon starts geostatic under the material above
// each particle, not under the top of its bounding box: sigma_yy = -rho g
// (s(x) - y) with s the surface above x (the crest at 3 m, the face
// falling 1 in 2 to the toe at 1 m), sigma_xx = K0 sigma_yy. Every
// particle lies inside the polygon, and the polygon is filled: the
// particles' volume is its area to the staircase of the face (at most one
// sub-cell along the face).
TEST(Geostatic, PolygonSlopeStartsUnderTheMaterialAboveEachParticle)
{
  const std::string slope = R"(
set Dimension = 2
set Effects   = gravity
subsection Grid
  set Lower corner        = 0, 0
  set Upper corner        = 8, 3.5
  set Cells               = 32, 14
  set Boundary conditions = 0: slip, 1: slip, 2: no-slip
end
subsection Material 1
  set Model   = linear elastic
  set Density = 2000
  subsection linear elastic)" +
                            elastic_entries +
                            R"(
  end
end
subsection Body 1
  set Shape          = polygon
  set Vertices       = 0, 0; 8, 0; 8, 1; 6, 1; 2, 3; 0, 3
  set Initial stress = geostatic
  set K0             = 0.5
end
subsection Gravity
  set Acceleration = 0, -9.81
end
)";
  auto              simulation = test::make_simulation<2>(slope);
  const CoreFields &f          = simulation->particle_set().fields;
  const auto        surface    = [](const double x) {
    return x <= 2 ? 3. : (x >= 6 ? 1. : 3. - (x - 2) / 2.);
  };
  double       worst_yy = 0, worst_xx = 0, volume = 0;
  unsigned int outside = 0;
  for (const auto &p : simulation->particle_set().handler)
    {
      const auto   props   = p.get_properties();
      const auto   stress  = read_symmetric<2>(&props[f.stress]);
      const auto  &x       = p.get_location();
      const double sigma_v = -2000 * 9.81 * (surface(x[0]) - x[1]);
      outside += x[1] > surface(x[0]);
      worst_yy = std::max(worst_yy, std::abs(stress[1][1] - sigma_v));
      worst_xx = std::max(worst_xx, std::abs(stress[0][0] - 0.5 * sigma_v));
      volume += props[f.initial_volume] *
                determinant(read_tensor<2>(&props[f.deformation_gradient]));
    }
  EXPECT_EQ(outside, 0u);
  EXPECT_LT(worst_yy, 1e-9 * 2000 * 9.81 * 3);
  EXPECT_LT(worst_xx, 1e-9 * 2000 * 9.81 * 3);
  // 8 below y = 1, 4 in the crest's block, 4 in the face's triangle; the
  // staircase of sub-cells (0.125 m) misses at most half a sub-cell in
  // each of the 32 columns across the face.
  const double area = 8 + 4 + 4;
  EXPECT_NEAR(volume, area, 32 * 0.5 * 0.125 * 0.125);
}
