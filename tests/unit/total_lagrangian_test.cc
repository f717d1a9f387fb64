// Total Lagrangian's transfers against closed forms:
// - the internal force of a homogeneous state is its reference traction:
//   f_I = -P oint N_I N dA (P = J sigma F^-T) on the body's nodes, zero
//   inside; with the Cauchy stress in place of P it would be -sigma N;
// - G2P of a nodal velocity linear in the reference position, v = A X, gives
//   dF/dt = A exactly: F_n+1 = F_n + dt A, L = A F_n^-1;
// - the reference stencil is made at X = x - u with F = I (cpGIMP, whose
//   domains follow F), and the current state is given back;
// - the smallest stretch of R diag(a, b, c) Q is min(a, b, c);
// - bodies that touch share a node, bodies apart do not.
#include <dealmpm/base/smallest_stretch.h>
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/particle_to_grid.h>
#include <dealmpm/transfer/reference_stencil.h>

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  // The body fills its cells: 2 x 2 particles per cell integrate the
  // bilinear functions' gradients exactly.
  const char *block = R"(
set Dimension = 2
subsection Grid
  set Lower corner = -1, -1
  set Upper corner = 3, 2
  set Cells = 8, 6
end
subsection Body 1
  set Shape = box
  set Lower corner = 0, 0
  set Upper corner = 2, 1
  set Particles per cell = 2
end
)";

  Tensor<2, 2>
  some_deformation()
  {
    Tensor<2, 2> F;
    F[0][0] = 1.3;
    F[0][1] = 0.4;
    F[1][0] = -0.2;
    F[1][1] = 0.8;
    return F;
  }

  /** Every particle gets deformation F, stress sigma and velocity 0. */
  void
  set_homogeneous_state(ParticleSet<2>              &particles,
                        const Tensor<2, 2>          &F,
                        const SymmetricTensor<2, 2> &sigma)
  {
    const CoreFields &f = particles.fields;
    for (auto &p : particles.handler)
      {
        const auto props = p.get_properties();
        write_tensor<2>(&props[f.deformation_gradient], F);
        write_symmetric<2>(&props[f.stress], sigma);
      }
  }
} // namespace

TEST(TotalLagrangian, ForceOfAHomogeneousStateIsItsReferenceTraction)
{
  auto                  simulation = test::make_simulation<2>(block);
  ParticleSet<2>       &particles  = simulation->particle_set();
  const auto           &grid       = simulation->background_grid();
  const Tensor<2, 2>    F          = some_deformation();
  SymmetricTensor<2, 2> sigma;
  sigma[0][0] = 3.;
  sigma[1][1] = -1.;
  sigma[0][1] = 2.;
  set_homogeneous_state(particles, F, sigma);
  const Tensor<2, 2> P = determinant(F) * sigma * transpose(invert(F));

  Stencil<2> stencil;
  compute_reference_stencil(
    grid, simulation->get_kernel(), particles, false, stencil);
  NodalFields<2> fields;
  fields.reinit(grid.partitioner);
  particle_to_grid(grid,
                   particles,
                   stencil,
                   fields,
                   false,
                   true,
                   Formulation::total_lagrangian);

  // oint N_I N dA over the block [0, 2] x [0, 1] (cells of 0.5): each face
  // node carries its hat's integral along the face, 0.5 inside a face and
  // 0.25 at a corner, on each face it lies on.
  const auto weight = [](const double s, const double low, const double high) {
    return std::abs(s - low) < 1e-12 || std::abs(s - high) < 1e-12 ? 0.25 : 0.5;
  };
  double largest_error = 0, largest_force = 0;
  for (unsigned int n = 0; n < grid.node_positions.size(); ++n)
    {
      const Point<2> &x = grid.node_positions[n];
      Tensor<1, 2>    oint;
      const bool      inside_x = x[0] > -1e-12 && x[0] < 2 + 1e-12;
      const bool      inside_y = x[1] > -1e-12 && x[1] < 1 + 1e-12;
      if (inside_x && inside_y)
        {
          if (std::abs(x[0]) < 1e-12)
            oint[0] -= weight(x[1], 0, 1);
          if (std::abs(x[0] - 2) < 1e-12)
            oint[0] += weight(x[1], 0, 1);
          if (std::abs(x[1]) < 1e-12)
            oint[1] -= weight(x[0], 0, 2);
          if (std::abs(x[1] - 1) < 1e-12)
            oint[1] += weight(x[0], 0, 2);
        }
      const Tensor<1, 2> expected = -P * oint;
      Tensor<1, 2>       force;
      for (unsigned int d = 0; d < 2; ++d)
        force[d] = fields.force[d].local_element(n);
      largest_error = std::max(largest_error, (force - expected).norm());
      largest_force = std::max(largest_force, force.norm());
    }
  EXPECT_LT(largest_error, 1e-12 * P.norm());
  // The traction differs from the Cauchy stress's: the check can tell.
  EXPECT_GT(largest_force, 0.1 * P.norm());
  EXPECT_GT((P - Tensor<2, 2>(sigma)).norm(), 0.3 * P.norm());
}

TEST(TotalLagrangian, DeformationRateIsTheReferenceVelocityGradient)
{
  auto               simulation = test::make_simulation<2>(block);
  ParticleSet<2>    &particles  = simulation->particle_set();
  const auto        &grid       = simulation->background_grid();
  const Tensor<2, 2> F_n        = some_deformation();
  set_homogeneous_state(particles, F_n, SymmetricTensor<2, 2>());
  Stencil<2> stencil;
  compute_reference_stencil(
    grid, simulation->get_kernel(), particles, false, stencil);

  Tensor<2, 2> A;
  A[0][0] = 0.7;
  A[0][1] = -1.1;
  A[1][0] = 0.3;
  A[1][1] = 0.2;
  NodalFields<2> fields;
  fields.reinit(grid.partitioner);
  for (unsigned int n = 0; n < grid.node_positions.size(); ++n)
    for (unsigned int d = 0; d < 2; ++d)
      fields.velocity[d].local_element(n) =
        (A * grid.node_positions[n])[d] + 5. * d;

  const double       dt      = 0.01;
  double             worst_F = 0, worst_L = 0;
  const Tensor<2, 2> L_expected = A * invert(F_n);
  grid_to_particle<G2P::deformation, Formulation::total_lagrangian>(
    grid,
    stencil,
    fields,
    dt,
    1.,
    particles,
    [&](const auto &,
        const ArrayView<double> &,
        const Tensor<2, 2> &L,
        const Tensor<2, 2> &F,
        const double        h) {
      worst_F = std::max(worst_F, (F - (F_n + dt * A)).norm());
      worst_L = std::max(worst_L, (L - L_expected).norm());
      // The cell size for the stable step is the current one.
      EXPECT_NEAR(h, 0.5 * smallest_stretch(F), 1e-12);
    });
  EXPECT_LT(worst_F, 1e-13);
  EXPECT_LT(worst_L, 1e-12);
}

TEST(TotalLagrangian, ReferenceStencilIsMadeAtTheReferencePositions)
{
  // cpGIMP stretches its domains by F: the reference stencil must see F = I.
  auto simulation = test::make_simulation<2>(
    std::string(block) + "subsection MPM\n set Shape function = cpGIMP\nend\n");
  ParticleSet<2> &particles = simulation->particle_set();
  const auto     &grid      = simulation->background_grid();
  Stencil<2>      at_start;
  simulation->get_kernel().compute_stencil(grid, particles, at_start);

  // Move and deform every particle; the stencil must not see it.
  const CoreFields     &f = particles.fields;
  const Tensor<1, 2>    u({0.3, -0.2});
  std::vector<Point<2>> moved;
  for (auto &p : particles.handler)
    {
      const auto props = p.get_properties();
      write_vector<2>(&props[f.displacement], u);
      write_tensor<2>(&props[f.deformation_gradient], some_deformation());
      p.set_location(p.get_location() + u);
      moved.push_back(p.get_location());
    }
  Stencil<2> reference;
  compute_reference_stencil(
    grid, simulation->get_kernel(), particles, true, reference);
  EXPECT_TRUE(reference.reference);
  ASSERT_EQ(reference.node, at_start.node);
  for (unsigned int e = 0; e < reference.N.size(); ++e)
    {
      EXPECT_NEAR(reference.N[e], at_start.N[e], 1e-14);
      EXPECT_LT((reference.grad_N[e] - at_start.grad_N[e]).norm(), 1e-12);
    }
  // APIC's positions are the reference ones; the particles' state is back.
  unsigned int k = 0;
  for (auto &p : particles.handler)
    {
      EXPECT_LT((p.get_location() - moved[k]).norm(), 1e-15);
      EXPECT_LT((reference.position[k] - (moved[k] - u)).norm(), 1e-14);
      EXPECT_LT((read_tensor<2>(&p.get_properties()[f.deformation_gradient]) -
                 some_deformation())
                  .norm(),
                1e-15);
      ++k;
    }
}

TEST(TotalLagrangian, SmallestStretch)
{
  const auto rotation_2d = [](const double angle) {
    Tensor<2, 2> R;
    R[0][0] = R[1][1] = std::cos(angle);
    R[1][0]           = std::sin(angle);
    R[0][1]           = -R[1][0];
    return R;
  };
  Tensor<2, 2> D;
  D[0][0] = 1.7;
  D[1][1] = 0.05;
  EXPECT_NEAR(smallest_stretch<2>(rotation_2d(0.4) * D * rotation_2d(-1.3)),
              0.05,
              1e-14);
  EXPECT_NEAR(smallest_stretch<2>(unit_symmetric_tensor<2>()), 1., 1e-15);
  // A stretch far below the others keeps its relative accuracy (J^2 over
  // the larger eigenvalue): J, a difference of products of size 1, is
  // good to about eps / 1e-6 = 2e-10 relative here, while the smaller
  // root of the characteristic equation (half trace less the radius, a
  // difference of numbers near 1.45) is off by 4e-5. And an inverted F
  // has the same stretches.
  D[1][1] = 1e-6;
  EXPECT_NEAR(smallest_stretch<2>(rotation_2d(0.4) * D * rotation_2d(-1.3)) /
                1e-6,
              1.,
              1e-9);
  D[1][1] = -0.05;
  EXPECT_NEAR(smallest_stretch<2>(rotation_2d(0.4) * D * rotation_2d(-1.3)),
              0.05,
              1e-14);
  EXPECT_NEAR(smallest_stretch_squared<2>(D), 0.05 * 0.05, 1e-15);

  // 3D: about z, then about x.
  Tensor<2, 3> Rz, Rx, D3;
  Rz[2][2] = Rx[0][0] = 1.;
  Rz[0][0] = Rz[1][1] = Rx[1][1] = Rx[2][2] = std::cos(0.7);
  Rz[1][0] = Rx[2][1] = std::sin(0.7);
  Rz[0][1] = Rx[1][2] = -std::sin(0.7);
  D3[0][0]            = 0.9;
  D3[1][1]            = 2.5;
  D3[2][2]            = 0.3;
  EXPECT_NEAR(smallest_stretch<3>(Rz * D3 * Rx), 0.3, 1e-13);
  EXPECT_NEAR(smallest_stretch<3>(unit_symmetric_tensor<3>()), 1., 1e-14);
  // As in 2D, a stretch of 1e-6 to 1e-9 (the smallest root of C itself,
  // 1e-12 beside roots near 1, is off by 1e-3 here).
  D3[2][2] = 1e-6;
  EXPECT_NEAR(smallest_stretch<3>(Rz * D3 * Rx) / 1e-6, 1., 1e-9);
  D3[2][2] = -0.3;
  EXPECT_NEAR(smallest_stretch<3>(Rz * D3 * Rx), 0.3, 1e-13);
}

TEST(TotalLagrangian, BodiesApartShareNoNode)
{
  const auto two_boxes = [](const double gap) {
    return std::string(R"(
set Dimension = 2
set Number of bodies = 2
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 4, 1
  set Cells = 8, 2
end
subsection Body 1
  set Shape = box
  set Lower corner = 0, 0
  set Upper corner = 1, 1
end
subsection Body 2
  set Shape = box
  set Lower corner = )") +
           std::to_string(1 + gap) + R"(, 0
  set Upper corner = 3, 1
end
)";
  };
  for (const double gap : {0., 1.})
    {
      auto       simulation = test::make_simulation<2>(two_boxes(gap), 2);
      Stencil<2> stencil;
      compute_reference_stencil(simulation->background_grid(),
                                simulation->get_kernel(),
                                simulation->particle_set(),
                                false,
                                stencil);
      const auto apart = bodies_apart(simulation->background_grid(),
                                      simulation->particle_set(),
                                      stencil,
                                      2);
      if (gap == 0.)
        EXPECT_EQ(apart.first, apart.second);
      else
        {
          EXPECT_EQ(apart.first, 0u);
          EXPECT_EQ(apart.second, 1u);
        }
    }
}

// The 3D smallest stretch takes lambda_0 lambda_1 from the smallest root
// of deal.II's trigonometric solution alone: deal.II's product to a few
// eps |T|^2 for symmetric tensors of every kind (C = F^T F near and far
// from I, diagonal ones, repeated eigenvalues, indefinite ones).
TEST(TotalLagrangian, TwoLargestEigenvaluesAsDealII)
{
  std::mt19937                           rng(17);
  std::uniform_real_distribution<double> entry(-1., 1.);
  std::vector<SymmetricTensor<2, 3>>     tensors;
  for (const double spread : {1e-8, 1e-3, 0.3, 2.})
    for (unsigned int trial = 0; trial < 200; ++trial)
      {
        Tensor<2, 3> F;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            F[i][j] = (i == j ? 1. : 0.) + spread * entry(rng);
        tensors.push_back(symmetrize(transpose(F) * F));
        SymmetricTensor<2, 3> T; // indefinite
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            T[i][j] = spread * entry(rng);
        tensors.push_back(T);
      }
  SymmetricTensor<2, 3> diagonal;
  diagonal[0][0] = 0.5, diagonal[1][1] = 3., diagonal[2][2] = 0.5;
  tensors.push_back(diagonal);
  tensors.push_back(unit_symmetric_tensor<3>());
  // diag(2, 2, 1) rotated: two equal eigenvalues, off-diagonal entries.
  Tensor<2, 3> R;
  R[0][0] = R[1][1] = std::cos(0.3);
  R[1][0]           = std::sin(0.3);
  R[0][1]           = -R[1][0];
  R[2][2]           = 1.;
  Tensor<2, 3> D;
  D[0][0] = D[1][1] = 2., D[2][2] = 1.;
  tensors.push_back(symmetrize(R * D * transpose(R)));
  // deal.II's roots and ours (the smallest root, then I2 - l2 (I1 - l2))
  // each carry an error of a few eps |T| per root, so a few eps |T|^2 in
  // the product, for definite and indefinite T alike.
  const double eps    = std::numeric_limits<double>::epsilon();
  unsigned int differ = 0;
  for (const SymmetricTensor<2, 3> &T : tensors)
    {
      const auto lambda = eigenvalues(T); // descending
      differ +=
        std::abs(product_of_two_largest_eigenvalues(T) -
                 lambda[0] * lambda[1]) > 16 * eps * T.norm() * T.norm();
    }
  EXPECT_EQ(differ, 0u);
}
