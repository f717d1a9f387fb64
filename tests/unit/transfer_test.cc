// P2G conserves mass and momentum and its internal forces sum to zero; G2P of
// a linear nodal velocity field is exact (value and gradient), also next to
// hanging nodes.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/particle_to_grid.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const char *scene = R"(
set Dimension = 2
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 2, 1
  set Cells = 6, 3
  subsection Local refinement
    set Levels = 2
    set Lower corner = 0.5, 0
    set Upper corner = 1.2, 0.6
  end
end
subsection Body 1
  set Shape = box
  set Lower corner = 0, 0
  set Upper corner = 2, 1
  set Particles per cell = 2
end
)";

  /** Random mass, velocity, stress and a random F near I per particle. */
  void
  randomize_state(ParticleSet<2> &particles, std::mt19937 &rng)
  {
    std::uniform_real_distribution<double> r(-1., 1.);
    const CoreFields                      &f = particles.fields;
    for (auto &p : particles.handler)
      {
        auto props            = p.get_properties();
        props[f.mass]         = 1. + 0.5 * r(rng);
        props[f.velocity]     = r(rng);
        props[f.velocity + 1] = r(rng);
        for (unsigned int i = 0; i < 3; ++i)
          props[f.stress + i] = 100. * r(rng);
        for (unsigned int i = 0; i < 4; ++i)
          props[f.deformation_gradient + i] =
            (i == 0 || i == 3 ? 1. : 0.) + 0.1 * r(rng);
      }
  }
} // namespace

TEST(Transfer, ParticleToGridConservesMassAndMomentum)
{
  auto         simulation = test::make_simulation<2>(scene);
  std::mt19937 rng(3);
  test::scatter_particles_in_cells(*simulation, rng);
  ParticleSet<2> &particles = simulation->particle_set();
  randomize_state(particles, rng);

  const auto &grid = simulation->background_grid();
  Stencil<2>  stencil;
  compute_linear_stencil(grid, particles, stencil);
  NodalFields<2> fields;
  fields.reinit(grid.partitioner);
  particle_to_grid(grid, particles, stencil, fields);

  double mass = 0, px = 0, py = 0, mass_abs = 0;
  for (const auto &p : particles.handler)
    {
      const auto props = p.get_properties();
      mass += props[particles.fields.mass];
      px += props[particles.fields.mass] * props[particles.fields.velocity];
      py += props[particles.fields.mass] * props[particles.fields.velocity + 1];
      mass_abs += props[particles.fields.mass];
    }
  EXPECT_NEAR(fields.mass.l1_norm(), mass, 1e-13 * mass);
  EXPECT_NEAR(fields.momentum[0].mean_value() * fields.momentum[0].size(),
              px,
              1e-12 * mass_abs);
  EXPECT_NEAR(fields.momentum[1].mean_value() * fields.momentum[1].size(),
              py,
              1e-12 * mass_abs);
  // Internal forces are equal and opposite pairs: they sum to zero.
  const double force_scale =
    fields.force[0].l1_norm() + fields.force[1].l1_norm();
  EXPECT_GT(force_scale, 0.);
  EXPECT_LT(std::abs(fields.force[0].mean_value() * fields.force[0].size()),
            1e-13 * force_scale);
  EXPECT_LT(std::abs(fields.force[1].mean_value() * fields.force[1].size()),
            1e-13 * force_scale);
}

namespace
{
  void
  check_linear_field_reproduction(const std::string &scene)
  {
    auto         simulation = test::make_simulation<2>(scene);
    std::mt19937 rng(5);
    test::scatter_particles_in_cells(*simulation, rng);
    ParticleSet<2> &particles = simulation->particle_set();
    const auto     &grid      = simulation->background_grid();

    Tensor<2, 2> A;
    A[0][0] = 0.3, A[0][1] = -1.1, A[1][0] = 0.7, A[1][1] = 2.0;
    const Tensor<1, 2> b({0.25, -0.5});

    NodalFields<2> fields;
    fields.reinit(grid.partitioner);
    std::map<types::global_dof_index, Point<2>> nodes;
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(),
                                         grid.dof_handler,
                                         nodes);
    for (const auto &[dof, x] : nodes)
      if (grid.partitioner->in_local_range(dof) ||
          grid.partitioner->is_ghost_entry(dof))
        for (unsigned int d = 0; d < 2; ++d)
          fields.velocity[d].local_element(
            grid.partitioner->global_to_local(dof)) = (A * x + b)[d];

    Stencil<2> stencil;
    compute_linear_stencil(grid, particles, stencil);
    std::vector<Tensor<2, 2>> L;
    grid_to_particle<G2P::motion_and_deformation>(
      grid,
      stencil,
      fields,
      /*dt=*/0.,
      /*flip_fraction=*/0.,
      particles,
      [&](const auto &,
          const auto &,
          const Tensor<2, 2> &velocity_gradient,
          const Tensor<2, 2> &,
          double) { L.push_back(velocity_gradient); });

    std::size_t k = 0;
    for (const auto &c : grid.cells)
      for (const auto &p : particles.handler.particles_in_cell(c.cell))
        {
          const Tensor<1, 2> v =
            read_vector<2>(&p.get_properties()[particles.fields.velocity]);
          EXPECT_LT((v - (A * p.get_location() + b)).norm(), 1e-13);
          EXPECT_LT((L[k] - A).norm(), 1e-12);
          ++k;
        }
    EXPECT_EQ(k, particles.handler.n_locally_owned_particles());
  }
} // namespace

TEST(Transfer, GridToParticleReproducesLinearField)
{
  check_linear_field_reproduction(scene);
}

TEST(Transfer, GridToParticleReproducesLinearFieldOnDistortedCells)
{
  // Non-affine cells: N and grad N come from the Newton inverse of the Q1
  // map; a wrong inverse breaks the gradient of a non-uniform field.
  check_linear_field_reproduction(
    "subsection Grid\n set Type = mesh file\n set Mesh file = " DEALMPM_SOURCE_DIR
    "/tests/data/distorted_square.msh\n set Global refinements = 2\nend\n"
    "subsection Body 1\n set Particles per cell = 2\nend\n");
}
