// A material whose local solve fails stops the run with the particle, its
// material section, F and the state the update left, each internal
// variable by name (issue 11's stability guard).
#include <gtest/gtest.h>

#include <limits>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** A stress-free stand-in for a model whose Newton solve gives up on its
   * third call: it counts its calls, then returns a NaN stress and the
   * iteration count a real solve would report. */
  class GivingUpModel : public Material<2>
  {
  public:
    std::vector<FieldDescription>
    internal_variables() const override
    {
      return {{"calls", 1}, {"iterations", 1}};
    }

    void
    update_stress(const Tensor<2, 2> &,
                  const Tensor<2, 2> &,
                  const double,
                  SymmetricTensor<2, 2> &stress,
                  ArrayView<double>      internal) const override
    {
      internal[0] += 1;
      stress = SymmetricTensor<2, 2>();
      if (internal[0] >= 3)
        {
          internal[1]  = 200;
          stress[0][0] = std::numeric_limits<double>::quiet_NaN();
        }
    }

    double
    wave_speed(const Tensor<2, 2> &) const override
    {
      return 1;
    }

    double
    out_of_plane_stress(const Tensor<2, 2> &,
                        const SymmetricTensor<2, 2> &,
                        ArrayView<const double>) const override
    {
      return 0;
    }

    double
    strain_energy_density(const Tensor<2, 2> &,
                          const SymmetricTensor<2, 2> &,
                          ArrayView<const double>) const override
    {
      return 0;
    }
  };

  const char *scene = R"(
set Number of materials = 2
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Cells = 4, 4
end
subsection Material 1
  set Model = linear elastic
end
subsection Material 2
  set Model = giving up
end
subsection Body 1
  set Lower corner = 0.25, 0.25
  set Upper corner = 0.75, 0.75
  set Material = 2
end
)";
} // namespace

TEST(LocalSolveFailure, StopsWithTheMaterialAndItsState)
{
  material_registry<2>().add(
    "giving up",
    "a model whose local solve fails on its third call (test only)",
    [](ParameterHandler &) {},
    [](SceneReader &) -> std::unique_ptr<Material<2>> {
      return std::make_unique<GivingUpModel>();
    });
  auto simulation = test::make_simulation<2>(scene, 1, 2);
  try
    {
      for (unsigned int s = 0; s < 5; ++s)
        simulation->advance(simulation->time_step());
      FAIL() << "the run went on past a NaN stress";
    }
  catch (const RunError &e)
    {
      const std::string what = e.what();
      std::cout << what << std::endl;
      EXPECT_NE(what.find("non-finite"), std::string::npos) << what;
      EXPECT_NE(what.find("in 'Material 2'"), std::string::npos) << what;
      EXPECT_NE(what.find("calls = 3"), std::string::npos) << what;
      EXPECT_NE(what.find("iterations = 200"), std::string::npos) << what;
      EXPECT_NE(what.find("F = "), std::string::npos) << what;
    }
}

// Every particle leaves the grid (a block thrown at 100 m/s towards an
// open side): the next call for a time step says so in one RunError,
// with the step and time, not deal.II's internal-error message (the
// program's run() says the same before it asks).
TEST(LocalSolveFailure, NoParticlesLeftIsARunError)
{
  auto simulation =
    test::make_simulation<2>("subsection Body 1\n set Upper corner = 0.2, 0.2\n"
                             " set Velocity = -100, 0\nend\n");
  try
    {
      for (unsigned int s = 0; s < 50; ++s)
        simulation->advance(simulation->time_step());
      FAIL() << "the run went on with no particles";
    }
  catch (const RunError &e)
    {
      const std::string what = e.what();
      std::cout << what << std::endl;
      EXPECT_NE(what.find("no particles are left"), std::string::npos) << what;
      EXPECT_NE(what.find("step "), std::string::npos) << what;
    }
}
