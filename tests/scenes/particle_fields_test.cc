// What each particle stores of its body and material. A body has one
// material, so no particle stores its material index
// (ParticleSet::material_of looks it up from the body), and in a scene of
// one body no particle stores its body index either (ParticleSet::body_of
// is 0): 8-16 B of the particles' own memory (benchmarks/README.md). The
// physics must still see each particle's own material: the strain energy
// of bodies of swapped materials against its closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  template <int dim>
  void
  expect_core_fields_only(const ParticleSet<dim> &particles)
  {
    EXPECT_FALSE(particles.layout.has("body"));
    EXPECT_FALSE(particles.layout.has("material"));
    // mass, initial volume, velocity, displacement, F, stress.
    const unsigned int n_stress =
      SymmetricTensor<2, dim>::n_independent_components;
    EXPECT_EQ(particles.fields.n_core, 2 + 2 * dim + dim * dim + n_stress);
    unsigned int n = 0;
    for (const auto &p : particles.handler)
      {
        EXPECT_EQ(particles.body_of(p.get_properties()), 0u);
        EXPECT_EQ(particles.material_of(p.get_properties()), 0u);
        ++n;
      }
    EXPECT_GT(n, 0u);
  }

  /** Neo-Hookean strain energy density (plane strain in 2D), with the
   * Lame constants of Young's modulus @p E and Poisson's ratio 0.3. */
  double
  neo_hookean_energy(const double E, const Tensor<2, 2> &F)
  {
    const double nu = 0.3, mu = E / (2 * (1 + nu)),
                 lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double log_J  = std::log(determinant(F));
    return 0.5 * mu * (trace(transpose(F) * F) - 2) - mu * log_J +
           0.5 * lambda * log_J * log_J;
  }

  std::string
  material(const unsigned int m, const double E)
  {
    return "subsection Material " + std::to_string(m) +
           "\n set Model = neo-Hookean\n set Density = 1000\n"
           " subsection neo-Hookean\n  set Young's modulus = " +
           std::to_string(E) + "\n  set Poisson's ratio = 0.3\n end\nend\n";
  }

  std::string
  body(const unsigned int b,
       const std::string &lower,
       const std::string &upper,
       const unsigned int m)
  {
    return "subsection Body " + std::to_string(b) +
           "\n set Lower corner = " + lower + "\n set Upper corner = " + upper +
           "\n set Material = " + std::to_string(m) + "\nend\n";
  }
} // namespace

TEST(ParticleFields, OneBodyStoresNeitherBodyNorMaterial)
{
  expect_core_fields_only(
    test::make_simulation<2>(
      "subsection Grid\n set Cells = 8, 8\nend\nsubsection Body 1\n"
      " set Lower corner = 0.25, 0.25\n set Upper corner = 0.75, 0.75\nend\n")
      ->particle_set());
  expect_core_fields_only(
    test::make_simulation<3>(
      "set Dimension = 3\nsubsection Grid\n set Lower corner = 0, 0, 0\n"
      " set Upper corner = 1, 1, 1\n set Cells = 4, 4, 4\nend\n"
      "subsection Body 1\n set Lower corner = 0, 0, 0\n"
      " set Upper corner = 0.5, 0.5, 0.5\nend\n")
      ->particle_set());
}

TEST(ParticleFields, EachBodyIsOfItsMaterial)
{
  // Bodies 1 and 3 of material 2 (E = 4000), body 2 of material 1 (1000):
  // the order of the bodies is not that of the materials. Each box covers
  // whole cells, so its particles' volumes sum to its area.
  auto simulation = test::make_simulation<2>(
    "set Number of bodies = 3\nset Number of materials = 2\n"
    "subsection Grid\n set Upper corner = 3, 1\n set Cells = 12, 4\nend\n" +
      material(1, 1000) + material(2, 4000) + body(1, "0, 0", "0.5, 0.5", 2) +
      body(2, "1, 0", "2, 0.5", 1) + body(3, "2.5, 0", "3, 1", 2),
    3,
    2);
  ParticleSet<2> &particles = simulation->particle_set();
  EXPECT_TRUE(particles.layout.has("body"));
  EXPECT_FALSE(particles.layout.has("material"));
  EXPECT_EQ(particles.fields.n_core, 14u);

  const unsigned int material_of_body[] = {1, 0, 1};
  const double       area[]             = {0.25, 0.5, 0.5};
  const double       E[]                = {1000, 4000};
  Tensor<2, 2>       F;
  F[0][0] = 1.2, F[0][1] = 0.1, F[1][1] = 0.9;
  // Deform one body at a time: the strain energy is that body's area
  // times its own material's energy density.
  for (unsigned int deformed = 0; deformed < 3; ++deformed)
    {
      for (auto &p : particles.handler)
        {
          const auto         props = p.get_properties();
          const unsigned int b     = particles.body_of(props);
          ASSERT_LT(b, 3u);
          EXPECT_EQ(particles.material_of(props), material_of_body[b]);
          write_tensor<2>(&props[particles.fields.deformation_gradient],
                          b == deformed ?
                            F :
                            Tensor<2, 2>(unit_symmetric_tensor<2>()));
        }
      const double expected =
        area[deformed] * neo_hookean_energy(E[material_of_body[deformed]], F);
      EXPECT_NEAR(simulation->statistics().strain_energy,
                  expected,
                  1e-12 * expected)
        << "body " << deformed + 1;
    }
}
