// Bodies: particle mass = density x covered volume (exact for shapes made of
// whole cells, close for curved ones), unique ids.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  template <int dim>
  double
  body_mass(const std::string &grid, const std::string &body)
  {
    auto simulation = test::make_simulation<dim>(
      "set Dimension = " + std::to_string(dim) + "\nsubsection Grid\n" + grid +
      "\nend\nsubsection Material 1\n set Density = 2\nend\n"
      "subsection Body 1\n" +
      body + "\nend\n");
    std::set<types::particle_index> ids;
    for (const auto &p : simulation->particle_set().handler)
      ids.insert(p.get_id());
    EXPECT_EQ(ids.size(),
              simulation->particle_set().handler.n_global_particles());
    return simulation->statistics().mass / 2.;
  }
} // namespace

TEST(Body, BoxOfWholeCellsHasExactMass)
{
  EXPECT_NEAR(
    body_mass<2>(" set Cells = 10, 10",
                 " set Lower corner = 0.2, 0.3\n set Upper corner = 0.6, 0.5"),
    0.08,
    1e-14);
}

TEST(Body, DiskAndCylinderApproximateTheirVolume)
{
  const double disk = body_mass<2>(
    " set Cells = 40, 40",
    " set Shape = ball\n set Center = 0.5, 0.5\n set Radius = 0.3");
  EXPECT_NEAR(disk, M_PI * 0.09, 0.01 * M_PI * 0.09);
  const double cylinder = body_mass<3>(
    " set Cells = 20, 20, 20",
    " set Shape = cylinder\n set Center = 0.5, 0.5, 0.5\n set Radius = 0.3\n"
    " set Axis = y\n set Height = 0.5\n set Particles per cell = 2");
  EXPECT_NEAR(cylinder, M_PI * 0.09 * 0.5, 0.03 * M_PI * 0.09 * 0.5);
}

TEST(Body, MeshBodyFillsItsCells)
{
  const std::string mesh =
    DEALMPM_SOURCE_DIR "/tests/data/distorted_square.msh";
  EXPECT_NEAR(body_mass<2>(" set Cells = 16, 16",
                           " set Shape = mesh\n set Mesh file = " + mesh),
              1.,
              1e-12);
}

TEST(Body, IdsStayUniqueAcrossBodiesWithDifferentPatterns)
{
  auto simulation =
    test::make_simulation<2>("subsection Grid\n set Cells = 10, 10\nend\n"
                             "subsection Body 1\n set Particles per cell = 3\n"
                             " set Upper corner = 1, 0.5\nend\n"
                             "subsection Body 2\n set Particles per cell = 1\n"
                             " set Lower corner = 0, 0.5\nend\n",
                             2);
  std::set<types::particle_index> ids;
  for (const auto &p : simulation->particle_set().handler)
    ids.insert(p.get_id());
  EXPECT_EQ(simulation->particle_set().handler.n_global_particles(),
            50u * 9u + 50u);
  EXPECT_EQ(ids.size(), 50u * 9u + 50u);
}

// Two bodies over the same region would fill it twice (twice the density):
// refused with both names, unless the later one replaces the earlier one's
// particles there (an inclusion).
TEST(Body, OverlappingBodiesAreRefusedUnlessTheLaterOneReplaces)
{
  const std::string scene =
    "subsection Grid\n set Cells = 10, 10\nend\n"
    "subsection Body 1\n set Upper corner = 1, 0.6\nend\n"
    "subsection Body 2\n set Lower corner = 0.2, 0.4\n"
    " set Upper corner = 0.6, 1\n set Particles per cell = 3\n";
  try
    {
      test::make_simulation<2>(scene + "end\n", 2);
      ADD_FAILURE() << "overlapping bodies were accepted";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find(
                  "'Body 2/Allow overlap' = 'false': expected a body that "
                  "does not overlap 'Body 1'"),
                std::string::npos)
        << e.what();
    }
  auto simulation =
    test::make_simulation<2>(scene + " set Allow overlap = true\nend\n", 2);
  // Density 1000 over the union 0.6 + 0.4 x 0.4, each place filled once.
  EXPECT_NEAR(simulation->statistics().mass, 1000. * (0.6 + 0.16), 1e-9);
}
