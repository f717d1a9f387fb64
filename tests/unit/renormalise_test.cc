// A plastic grain sheared without end (the floor of a granular flow) grows
// F's condition number until b_e = F C_p^-1 F^T, which the Hencky models
// compute each step, has lost every digit to cancellation. The models on
// the Hencky frame may replace an ill-conditioned F by a symmetric F' of
// the same J with C_p^-1 to match (renormalise_deformation()), and the
// stress update does so past a condition number of 1e4:
// - the replacement changes nothing the model computes: after it, the same
//   spatial increments give the same stresses and state to round-off (J2,
//   Drucker-Prager, Mohr-Coulomb, Modified Cam-Clay; 2D and 3D);
// - a J2 grain in simple shear to gamma = 1e6 through the stress update
//   keeps the isochoric flow's zero pressure and q = sigma_y to 1e-5;
//   without the replacement (the same shear on the model alone) the
//   pressure was -1.8e-5 sigma_y at gamma = 1e4, 3.3e-3 at 1e5 and -1.05
//   at 1e6.
#include <dealmpm/materials/drucker_prager.h>
#include <dealmpm/materials/j2_plasticity.h>
#include <dealmpm/materials/modified_cam_clay.h>
#include <dealmpm/materials/mohr_coulomb.h>
#include <dealmpm/transfer/stress_update.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

#include "material_point.h"
#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** K = 10, G = 5. */
  const LameParameters soil_lame = {10. - 10. / 3., 5.};

  /** Drive two points along the same plastic path; replace the second's
   * F halfway; continue both with the same spatial increments f = F_k
   * F_(k-1)^-1. The largest difference of stress and of the scalar state
   * variables at the end, relative to their size. */
  template <int dim, class Model, class... Arguments>
  double
  response_change(const Arguments &...arguments)
  {
    test::MaterialPoint<dim, Model> kept(arguments...),
      renormalised(arguments...);
    const auto path = [](const unsigned int k) {
      return test::wandering_deformation<dim>(0.1 * k, 0.02);
    };
    for (unsigned int k = 1; k <= 30; ++k)
      {
        kept.deform(path(k));
        renormalised.deform(path(k));
      }
    Tensor<2, dim> F = path(30);
    renormalised.model.renormalise_deformation(
      F, make_array_view(renormalised.internal));
    EXPECT_NEAR(determinant(F), determinant(path(30)), 1e-12);
    EXPECT_LT((F - transpose(F)).norm(), 1e-12 * F.norm());
    for (unsigned int k = 31; k <= 60; ++k)
      {
        F = path(k) * invert(path(k - 1)) * F;
        kept.deform(path(k));
        renormalised.deform(F);
      }
    const unsigned int first_scalar = Model::plastic_strain_index;
    EXPECT_GT(kept.internal[first_scalar], 0.01); // the path flows
    double change =
      (Tensor<2, dim>(kept.stress) - Tensor<2, dim>(renormalised.stress))
        .norm() /
      kept.stress.norm();
    for (unsigned int c = first_scalar; c < kept.internal.size(); ++c)
      change = std::max(change,
                        std::abs(kept.internal[c] - renormalised.internal[c]) /
                          std::max(std::abs(kept.internal[c]), 1e-300));
    return change;
  }

  MohrCoulombParameters
  rock()
  {
    MohrCoulombParameters mc;
    mc.friction_angle = 30 * M_PI / 180.;
    mc.dilation_angle = 10 * M_PI / 180.;
    mc.cohesion       = 0.05;
    return mc;
  }

  CamClayParameters
  clay()
  {
    CamClayParameters c;
    c.critical_state_ratio    = 1.2;
    c.compression_index       = 0.1;
    c.swelling_index          = 0.02;
    c.shear_modulus           = 3e6;
    c.reference_pressure      = 100e3;
    c.overconsolidation_ratio = 1;
    return c;
  }

  template <int dim>
  void
  check_every_model()
  {
    const IsotropicHardening hardening{1e5, 1e6};
    const DruckerPragerCone  cone =
      DruckerPragerCone::matched("plane strain", 30 * M_PI / 180., 0., 0.05);
    EXPECT_LT((response_change<dim, J2Plasticity<dim>>(
                LameParameters{5.8e6, 3.8e6}, hardening)),
              1e-9);
    EXPECT_LT((response_change<dim, DruckerPrager<dim>>(soil_lame, cone)),
              1e-9);
    EXPECT_LT((response_change<dim, MohrCoulomb<dim>>(soil_lame, rock())),
              1e-9);
    EXPECT_LT((response_change<dim, ModifiedCamClay<dim>>(clay())), 1e-9);
  }
} // namespace

TEST(Renormalise, KeepsEveryHenckyModelsResponse)
{
  check_every_model<2>();
  check_every_model<3>();
}

// Through the stress update (the general path the step takes for plastic
// materials): one particle of a J2 scene, perfectly plastic, sheared by
// F <- (I + d_gamma e_x (x) e_y) F in steps of d_gamma = 100 to gamma =
// 1e6 (F's condition number about gamma^2 without the replacement).
TEST(Renormalise, KeepsAGrainShearedWithoutEndOnItsYieldSurface)
{
  auto simulation = test::make_simulation<2>(
    "subsection Material 1\n set Model = J2 plasticity\n"
    " subsection J2 plasticity\n  set Young's modulus = 1e7\n"
    "  set Yield stress = 1e4\n  set Hardening modulus = 0\n end\nend\n");
  ParticleSet<2> &particles = simulation->particle_set();
  std::vector<std::unique_ptr<Material<2>>> materials;
  const double                              E = 1e7, nu = 0.3;
  materials.push_back(std::make_unique<J2Plasticity<2>>(
    LameParameters{E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))},
    IsotropicHardening{1e4, 0}));
  materials.back()->density = 1000;
  StressUpdate<2> stress_update(materials, particles, 1e-3);

  auto                    p     = particles.handler.begin();
  const ArrayView<double> props = p->get_properties();
  const unsigned int      at    = particles.fields.deformation_gradient;
  Tensor<2, 2>            step  = unit_symmetric_tensor<2>();
  step[0][1]                    = 100;
  double largest_miss           = 0;
  for (unsigned int k = 0; k < 10000; ++k)
    {
      const Tensor<2, 2> F = step * read_tensor<2>(&props[at]);
      write_tensor<2>(&props[at], F);
      stress_update(*p, props, Tensor<2, 2>(), F, 0.01);
      const SymmetricTensor<2, 2> s =
        read_symmetric<2>(&props[FixedCore<2>::stress]);
      const ArrayView<const double> internal(&props[0] +
                                               particles.internal_offset[0],
                                             particles.n_internal[0]);
      SymmetricTensor<2, 3>         full;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          full[i][j] = s[i][j];
      full[2][2] = materials[0]->out_of_plane_stress(F, s, internal);
      // J = 1: the Kirchhoff stress J2 yields on is sigma. Isochoric
      // flow keeps det b_e = 1, so the pressure stays 0; on its surface,
      // the radial return puts q at sigma_y whatever b_e's errors are.
      const double q    = std::sqrt(1.5) * deviator(full).norm();
      const double p    = trace(full) / 3.;
      const double miss = std::max(std::abs(q - 1e4), std::abs(p)) / 1e4;
      largest_miss =
        std::isfinite(miss) ? std::max(largest_miss, miss) : HUGE_VAL;
    }
  std::cout << "renormalise: sheared J2 grain, largest miss " << largest_miss
            << std::endl;
  EXPECT_FALSE(stress_update.check.failed) << stress_update.check.reason;
  // Each step's b_e comes from an F of condition number up to about 1e4
  // (the step's times the renormalised one's), which costs it up to eps
  // cond^2 = 1e-8 of itself: a pressure of up to K 1e-8 = 8e-6 sigma_y
  // here (measured: 9.2e-7 over the 10,000 steps).
  EXPECT_LT(largest_miss, 1e-5);
}
