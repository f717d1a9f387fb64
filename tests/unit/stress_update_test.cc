// The stress update's lean path (StressUpdate::Of: direct, inlined calls to
// a final model's methods, taken when every material of the scene is that
// model) gives the general path's numbers (a virtual call per particle) to
// the bit, in 2D and 3D: each particle's state after USL's G2P sweep with
// the stress update, and what the particle check learned (the largest
// signal rate, the particle that has it, the smallest J). The lean path is
// only offered when every material is exactly the model.
#include <dealmpm/materials/linear_elastic.h>
#include <dealmpm/materials/neo_hookean.h>
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/stress_update.h>

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const LameParameters lame = {5.8e6, 3.8e6};

  template <int dim>
  std::unique_ptr<Material<dim>>
  linear_elastic()
  {
    auto m     = std::make_unique<LinearElastic<dim>>(lame);
    m->density = 1000;
    return m;
  }

  template <int dim>
  void
  check_lean_equals_general(const std::string &scene)
  {
    auto         simulation = test::make_simulation<dim>(scene);
    std::mt19937 rng(5);
    test::scatter_particles_in_cells(*simulation, rng);
    ParticleSet<dim>          &particles = simulation->particle_set();
    const BackgroundGrid<dim> &grid      = simulation->background_grid();
    NodalFields<dim>           fields;
    fields.reinit(grid.partitioner);
    test::randomize_state(particles, grid, fields, rng, 1e4);
    std::vector<std::unique_ptr<Material<dim>>> materials;
    materials.push_back(linear_elastic<dim>());

    Stencil<dim> stencil;
    stencil.where_used               = true;
    const double              dt     = 1e-3;
    const std::vector<double> before = test::particle_state(particles);
    const auto                sweep  = [&](auto &&after_deformation) {
      test::set_particle_state(particles, before);
      grid_to_particle<G2P::motion_and_deformation>(
        grid, stencil, fields, dt, 0.9, particles, after_deformation);
      return test::particle_state(particles);
    };
    StressUpdate<dim>         general(materials, particles, dt);
    StressUpdate<dim>         lean(materials, particles, dt);
    const std::vector<double> by_general = sweep(general);
    const std::vector<double> by_lean =
      sweep(typename StressUpdate<dim>::template Of<LinearElastic<dim>>{lean});

    ASSERT_EQ(by_general.size(), by_lean.size());
    unsigned int differ = 0;
    for (std::size_t i = 0; i < by_general.size(); ++i)
      differ += by_general[i] != by_lean[i];
    EXPECT_EQ(differ, 0u);
    EXPECT_NE(by_general, before); // the sweep did something
    EXPECT_FALSE(general.check.failed);
    EXPECT_FALSE(lean.check.failed);
    EXPECT_GT(general.check.max_signal_rate, 0.);
    EXPECT_EQ(general.check.max_signal_rate, lean.check.max_signal_rate);
    EXPECT_EQ(general.check.fastest, lean.check.fastest);
    EXPECT_EQ(general.check.min_J, lean.check.min_J);
  }
} // namespace

TEST(StressUpdate, LeanLinearElasticEqualsGeneral)
{
  const std::string material =
    "subsection Material 1\n set Model = linear elastic\nend\n";
  check_lean_equals_general<2>(
    material + "subsection Grid\n set Cells = 6, 5\nend\n"
               "subsection Body 1\n set Particles per cell = 2\nend\n");
  check_lean_equals_general<3>(
    "set Dimension = 3\n" + material +
    "subsection Grid\n set Lower corner = 0, 0, 0\n set Upper corner = 1, "
    "1, 1\n set Cells = 3, 3, 4\nend\nsubsection Body 1\n set Lower corner "
    "= 0, 0, 0\n set Upper corner = 1, 1, 1\n set Particles per cell = "
    "2\nend\n");
}

TEST(StressUpdate, LeanPathOnlyWhenEveryMaterialIsTheModel)
{
  auto simulation = test::make_simulation<2>("");
  using Elastic   = LinearElastic<2>;
  std::vector<std::unique_ptr<Material<2>>> materials;
  const auto                                all_elastic = [&] {
    return StressUpdate<2>(materials, simulation->particle_set(), 1e-3)
      .all_materials_are<Elastic>();
  };
  materials.push_back(linear_elastic<2>());
  EXPECT_TRUE(all_elastic());
  materials.push_back(linear_elastic<2>());
  EXPECT_TRUE(all_elastic());
  materials.push_back(std::make_unique<NeoHookean<2>>(lame));
  EXPECT_FALSE(all_elastic());
  materials.erase(materials.begin(), materials.begin() + 2);
  EXPECT_FALSE(all_elastic());
}
