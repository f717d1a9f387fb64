// The stress update's lean path (StressUpdate::Of: direct, inlined calls to
// a final model's methods, taken when every material of the scene is that
// model) gives the general path's numbers (a virtual call per particle) to
// the bit, in 2D and 3D: each particle's state after USL's G2P sweep with
// the stress update, and what the particle check learned (the largest
// signal rate, the particle that has it, the smallest J). The lean path is
// only offered when every material is exactly the model.
#include <dealmpm/materials/j2_plasticity.h>
#include <dealmpm/materials/linear_elastic.h>
#include <dealmpm/materials/modified_cam_clay.h>
#include <dealmpm/materials/neo_hookean.h>
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/stress_update.h>

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <utility>
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

namespace
{
  /** update_stresses() of @p material on 8 points (random F near I, L
   * and a starting stress) against update_stress() point by point: the
   * number of entries (stress and internal variables) that differ. */
  template <int dim>
  unsigned int
  batch_differs_from_points(const Material<dim> &material)
  {
    std::mt19937                           rng(11);
    std::uniform_real_distribution<double> entry(-0.2, 0.2);
    const unsigned int                     n          = 8;
    unsigned int                           n_internal = 0;
    for (const FieldDescription &f : material.internal_variables())
      n_internal += f.n_components;
    std::vector<Tensor<2, dim>>          F(n), L(n);
    std::vector<SymmetricTensor<2, dim>> batch(n);
    std::vector<double>                  batch_internal(n * n_internal);
    for (unsigned int q = 0; q < n; ++q)
      {
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              F[q][i][j] = (i == j ? 1. : 0.) + entry(rng);
              L[q][i][j] = entry(rng);
            }
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            batch[q][i][j] = 1e5 * entry(rng);
        material.initialize_internal_variables(
          ArrayView<double>(batch_internal.data() + q * n_internal,
                            n_internal));
      }
    std::vector<SymmetricTensor<2, dim>> points          = batch;
    std::vector<double>                  points_internal = batch_internal;
    material.update_stresses(make_array_view(std::as_const(L)),
                             make_array_view(std::as_const(F)),
                             1e-3,
                             make_array_view(batch),
                             make_array_view(batch_internal));
    for (unsigned int q = 0; q < n; ++q)
      material.update_stress(
        L[q],
        F[q],
        1e-3,
        points[q],
        ArrayView<double>(points_internal.data() + q * n_internal, n_internal));
    unsigned int differ = 0;
    for (unsigned int q = 0; q < n; ++q)
      differ += !(batch[q] == points[q]);
    for (std::size_t i = 0; i < batch_internal.size(); ++i)
      differ += batch_internal[i] != points_internal[i];
    return differ;
  }

  /** Whether max_wave_speed() of @p material over points near I (some
   * stretched, some compressed; with @p inverted one turned inside out,
   * J < 0), each in the model's initial state, is the largest
   * wave_speed_of_state() to the bit. */
  template <int dim>
  bool
  max_wave_speed_is_largest(const Material<dim> &material,
                            const bool           inverted = false)
  {
    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> entry(-0.2, 0.2);
    std::vector<Tensor<2, dim>>            F(8);
    unsigned int                           n = 0;
    for (const auto &field : material.internal_variables())
      n += field.n_components;
    std::vector<double> internal(F.size() * n);
    double              largest = 0;
    for (Tensor<2, dim> &f : F)
      {
        const ArrayView<double> state(internal.data() + (&f - &F[0]) * n, n);
        material.initialize_internal_variables(state);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            f[i][j] = (i == j ? 1. : 0.) + entry(rng);
        if (inverted && &f == &F[3])
          f[0] *= -1.;
        largest = std::max(largest, material.wave_speed_of_state(f, state));
      }
    return material.max_wave_speed(make_array_view(std::as_const(F)),
                                   make_array_view(std::as_const(internal))) ==
             largest &&
           material.max_wave_speed(ArrayView<const Tensor<2, dim>>(),
                                   ArrayView<const double>()) == 0.;
  }

  /** The neo-Hookean stress against its tensor expression
   * mu / J (B - I) + lambda ln(J) / J I: entries that differ. */
  template <int dim>
  unsigned int
  neo_hookean_differs_from_expression()
  {
    NeoHookean<dim>                        material(lame);
    std::mt19937                           rng(3);
    std::uniform_real_distribution<double> entry(-0.3, 0.3);
    unsigned int                           differ = 0;
    for (unsigned int trial = 0; trial < 100; ++trial)
      {
        Tensor<2, dim> F;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            F[i][j] = (i == j ? 1. : 0.) + entry(rng);
        SymmetricTensor<2, dim> stress;
        material.update_stress(F, F, 1., stress, {});
        const double                  J = determinant(F);
        const SymmetricTensor<2, dim> B = symmetrize(F * transpose(F));
        const SymmetricTensor<2, dim> expected =
          (lame.mu / J) * (B - unit_symmetric_tensor<dim>()) +
          (lame.lambda * std::log(J) / J) * unit_symmetric_tensor<dim>();
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            differ += stress[i][j] != expected[i][j];
      }
    return differ;
  }
} // namespace

// An FEM region updates a cell's points in one call (update_stresses());
// the models that override it (neo-Hookean, linear elastic) and the
// default (point by point, here J2 plasticity with its internal
// variables) give update_stress()'s numbers to the bit. The neo-Hookean
// stress, written in scalars, is its tensor expression to the bit.
TEST(StressUpdate, CellBatchEqualsPointByPoint)
{
  // Yield at 1e5 Pa: the random strains of up to 0.2 flow plastically.
  const IsotropicHardening hardening{1e5, 1e6};
  EXPECT_EQ(batch_differs_from_points<2>(NeoHookean<2>(lame)), 0u);
  EXPECT_EQ(batch_differs_from_points<3>(NeoHookean<3>(lame)), 0u);
  EXPECT_EQ(batch_differs_from_points<2>(LinearElastic<2>(lame)), 0u);
  EXPECT_EQ(batch_differs_from_points<3>(LinearElastic<3>(lame)), 0u);
  EXPECT_EQ(batch_differs_from_points<2>(J2Plasticity<2>(lame, hardening)), 0u);
  EXPECT_EQ(batch_differs_from_points<3>(J2Plasticity<3>(lame, hardening)), 0u);
  EXPECT_EQ(neo_hookean_differs_from_expression<2>(), 0u);
  EXPECT_EQ(neo_hookean_differs_from_expression<3>(), 0u);
}

// A region's cell takes the largest wave speed of its points in one call:
// the models that take the square root once (neo-Hookean, linear elastic;
// the neo-Hookean also takes one log, at the smallest J, or the largest
// where lambda < 0) and the default (J2 plasticity) give the largest point
// value to the bit, also with an inverted point among them.
TEST(StressUpdate, CellMaxWaveSpeedEqualsLargestPoint)
{
  // Poisson's ratio -0.2: lambda < 0, the modulus rises with J.
  NeoHookean<2> auxetic_2({-1.6e6, 3.8e6});
  NeoHookean<3> auxetic_3({-1.6e6, 3.8e6});
  for (const bool inverted : {false, true})
    {
      auxetic_2.density = auxetic_3.density = 1000;
      EXPECT_TRUE(max_wave_speed_is_largest<2>(auxetic_2, inverted));
      EXPECT_TRUE(max_wave_speed_is_largest<3>(auxetic_3, inverted));
      NeoHookean<2> neo_2(lame);
      NeoHookean<3> neo_3(lame);
      neo_2.density = neo_3.density = 1000;
      EXPECT_TRUE(max_wave_speed_is_largest<2>(neo_2, inverted));
      EXPECT_TRUE(max_wave_speed_is_largest<3>(neo_3, inverted));
    }
  NeoHookean<2>    neo_2(lame);
  NeoHookean<3>    neo_3(lame);
  LinearElastic<2> linear_2(lame);
  LinearElastic<3> linear_3(lame);
  J2Plasticity<2>  j2_2(lame, IsotropicHardening{1e5, 1e6});
  J2Plasticity<3>  j2_3(lame, IsotropicHardening{1e5, 1e6});
  // Its wave speed follows the pressure of each point's state.
  ModifiedCamClay<2> clay_2(CamClayParameters{});
  ModifiedCamClay<3> clay_3(CamClayParameters{});
  for (Material<2> *m :
       std::initializer_list<Material<2> *>{&neo_2, &linear_2, &j2_2, &clay_2})
    {
      m->density = 1000;
      EXPECT_TRUE(max_wave_speed_is_largest<2>(*m));
    }
  for (Material<3> *m :
       std::initializer_list<Material<3> *>{&neo_3, &linear_3, &j2_3, &clay_3})
    {
      m->density = 1000;
      EXPECT_TRUE(max_wave_speed_is_largest<3>(*m));
    }
}
