// Starting a material point at rest under a given stress (geostatic
// initialisation), without a grid:
// - the material's own K0 from a confined compression is nu / (1 - nu) for
//   the elastic models (linear elastic, neo-Hookean, J2 and Drucker-Prager
//   in their elastic range) and 1 for the Tait fluid;
// - start_at_stress gives each model the geostatic stress it is asked for,
//   in 2D and 3D, with gravity along an axis and oblique, through one step
//   of the model's own update (a stretch for hyperelastic models, the rate
//   form's increment for linear elasticity);
// - a stress beyond the yield surface (a cohesionless Drucker-Prager soil
//   with K0 = 0.05) and a fluid under a stress that is not a pressure are
//   refused.
#include <dealmpm/materials/drucker_prager.h>
#include <dealmpm/materials/initial_stress.h>
#include <dealmpm/materials/j2_plasticity.h>
#include <dealmpm/materials/linear_elastic.h>
#include <dealmpm/materials/neo_hookean.h>
#include <dealmpm/materials/tait_fluid.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

using namespace dealmpm;

namespace
{
  constexpr double nu = 0.3;

  template <int dim>
  std::vector<std::unique_ptr<Material<dim>>>
  elastic_models()
  {
    const double         E    = 1e7;
    const LameParameters lame = {E * nu / ((1 + nu) * (1 - 2 * nu)),
                                 E / (2 * (1 + nu))};
    IsotropicHardening   hardening;
    hardening.yield_stress = 1e6;
    std::vector<std::unique_ptr<Material<dim>>> models;
    models.push_back(std::make_unique<LinearElastic<dim>>(lame));
    models.push_back(std::make_unique<NeoHookean<dim>>(lame));
    models.push_back(std::make_unique<J2Plasticity<dim>>(lame, hardening));
    models.push_back(std::make_unique<DruckerPrager<dim>>(
      lame, DruckerPragerCone::matched("plane strain", 30 * M_PI / 180, 0, 0)));
    for (auto &m : models)
      m->density = 2000;
    return models;
  }

  template <int dim>
  unsigned int
  n_internal(const Material<dim> &material)
  {
    unsigned int n = 0;
    for (const auto &field : material.internal_variables())
      n += field.n_components;
    return n;
  }

  template <int dim>
  Tensor<1, dim>
  downwards(const bool oblique)
  {
    Tensor<1, dim> n;
    n[dim - 1] = -1;
    if (oblique)
      n[0] = 0.5;
    return n / n.norm();
  }

  template <int dim>
  void
  check_models_start_at_the_geostatic_stress()
  {
    for (const auto &material : elastic_models<dim>())
      for (const bool oblique : {false, true})
        {
          const Tensor<1, dim> n = downwards<dim>(oblique);
          // The cohesionless cone is smaller than the elastic K0's stress:
          // its confined compression yields.
          if (dynamic_cast<const DruckerPrager<dim> *>(material.get()) ==
              nullptr)
            {
              EXPECT_NEAR(confined_stress_ratio(*material,
                                                n_internal(*material),
                                                n),
                          nu / (1 - nu),
                          1e-5);
            }
          // 10 m of soil at rho = 2000: sigma_v = -1.96e5 Pa.
          const SymmetricTensor<2, dim> target =
            geostatic_stress(-2000 * 9.81 * 10, n, 0.55);
          Tensor<2, dim>          F;
          SymmetricTensor<2, dim> stress;
          std::vector<double>     internal(n_internal(*material));
          ASSERT_TRUE(start_at_stress(
            *material, target, F, stress, make_array_view(internal)));
          EXPECT_LT((stress - target).norm(), 1e-9 * target.norm());
          // F is a stretch: symmetric, compressed along n.
          EXPECT_LT((F - transpose(F)).norm(), 1e-14);
          EXPECT_LT(n * (F * n), 1.);
          // The model's own update of that F from its start gives the
          // stress again.
          std::vector<double> again(n_internal(*material));
          material->initialize_internal_variables(make_array_view(again));
          SymmetricTensor<2, dim> restarted;
          Tensor<2, dim>          log_F;
          for (const auto &[lambda, q] : eigenvectors(symmetrize(F)))
            log_F += std::log(lambda) * outer_product(q, q);
          material->update_stress(
            log_F, F, 1., restarted, make_array_view(again));
          EXPECT_LT((restarted - target).norm(), 1e-9 * target.norm());
        }
  }
} // namespace

TEST(InitialStress, ModelsStartAtTheGeostaticStress2D)
{
  check_models_start_at_the_geostatic_stress<2>();
}

TEST(InitialStress, ModelsStartAtTheGeostaticStress3D)
{
  check_models_start_at_the_geostatic_stress<3>();
}

TEST(InitialStress, GeostaticStressIsTheWeightAboveAndK0Across)
{
  const Tensor<1, 2>          down({0., -1.});
  const SymmetricTensor<2, 2> s = geostatic_stress(-100., down, 0.4);
  EXPECT_DOUBLE_EQ(s[1][1], -100.);
  EXPECT_DOUBLE_EQ(s[0][0], -40.);
  EXPECT_DOUBLE_EQ(s[0][1], 0.);
}

TEST(InitialStress, RefusesWhatAModelCannotCarryAtRest)
{
  // A cohesionless soil cannot carry a lateral stress this small: the
  // deviator lies beyond the cone.
  const auto            models = elastic_models<3>();
  const Material<3>    &soil   = *models[3];
  const Tensor<1, 3>    n      = downwards<3>(false);
  Tensor<2, 3>          F;
  SymmetricTensor<2, 3> stress;
  std::vector<double>   internal(n_internal(soil));
  EXPECT_FALSE(start_at_stress(soil,
                               geostatic_stress(-1e5, n, 0.05),
                               F,
                               stress,
                               make_array_view(internal)));
  EXPECT_TRUE(start_at_stress(soil,
                              geostatic_stress(-1e5, n, 0.5),
                              F,
                              stress,
                              make_array_view(internal)));

  // A fluid rests under a pressure only.
  TaitParameters water;
  water.sound_speed = 20;
  water.exponent    = 7;
  water.viscosity   = 1e-3;
  TaitFluid<3> fluid(water);
  fluid.density = 1000;
  std::vector<double> fluid_state(n_internal<3>(fluid));
  EXPECT_NEAR(confined_stress_ratio<3>(fluid, fluid_state.size(), n), 1., 1e-6);
  EXPECT_TRUE(start_at_stress<3>(fluid,
                                 geostatic_stress(-1e4, n, 1.),
                                 F,
                                 stress,
                                 make_array_view(fluid_state)));
  EXPECT_LT((stress + 1e4 * unit_symmetric_tensor<3>()).norm(), 1e-4);
  EXPECT_FALSE(start_at_stress<3>(fluid,
                                  geostatic_stress(-1e4, n, 0.5),
                                  F,
                                  stress,
                                  make_array_view(fluid_state)));
}
