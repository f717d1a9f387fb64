// Linear weights computed where P2G and G2P use them (Stencil::where_used)
// give what the stored linear stencil gives: G2P's velocity, position,
// reference location and F to the bit in USL's sweep (with the light-node
// weights); P2G's nodal mass, momentum and force to round-off (it sums a
// cell's particles first, so the sums change order) and so MUSL's G2P,
// re-map and stress update (which keep the reference location until the
// stress update); on a grid with hanging nodes and on distorted
// (non-affine) cells. The weights themselves are deal.II's Q1 functions.
#include <deal.II/fe/fe_q.h>

#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/particle_to_grid.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const char *refined_scene = R"(
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
  set Particles per cell = 2
end
)";

  const std::string distorted_scene =
    "subsection Grid\n set Type = mesh file\n set Mesh file = " DEALMPM_SOURCE_DIR
    "/tests/data/distorted_square.msh\n set Global refinements = 2\nend\n"
    "subsection Body 1\n set Particles per cell = 2\nend\n";

  /** Every local value of @p a equals @p b's up to the order of a sum:
   * a nodal value sums at most a few dozen particles' shares, so
   * reordering changes it by a few dozen ulps of the largest value; 1e-12
   * of it is far above that and far below a wrong weight's O(1) error. */
  void
  expect_same_sums(const NodalVector &a, const NodalVector &b)
  {
    ASSERT_EQ(a.locally_owned_size(), b.locally_owned_size());
    ASSERT_GT(a.linfty_norm(), 0.);
    unsigned int differ = 0;
    for (unsigned int i = 0; i < a.locally_owned_size(); ++i)
      differ += std::abs(a.local_element(i) - b.local_element(i)) >
                1e-12 * a.linfty_norm();
    EXPECT_EQ(differ, 0u);
  }

  /** Each particle's location, reference location and properties. */
  std::vector<double>
  particle_state(const ParticleSet<2> &particles)
  {
    std::vector<double> state;
    for (const auto &p : particles.handler)
      {
        for (unsigned int d = 0; d < 2; ++d)
          {
            state.push_back(p.get_location()[d]);
            state.push_back(p.get_reference_location()[d]);
          }
        for (const double value : p.get_properties())
          state.push_back(value);
      }
    return state;
  }

  void
  set_particle_state(ParticleSet<2> &particles, const std::vector<double> &s)
  {
    std::size_t i = 0;
    for (auto &p : particles.handler)
      {
        Point<2> x, xi;
        for (unsigned int d = 0; d < 2; ++d)
          {
            x[d]  = s[i++];
            xi[d] = s[i++];
          }
        p.set_location(x);
        p.set_reference_location(xi);
        for (double &value : p.get_properties())
          value = s[i++];
      }
  }

  /** Random state on the particles and a random nodal velocity,
   * increment and light-node weight on the grid. */
  void
  randomize(ParticleSet<2>          &particles,
            const BackgroundGrid<2> &grid,
            NodalFields<2>          &fields,
            std::mt19937            &rng)
  {
    std::uniform_real_distribution<double> r(-1., 1.);
    const CoreFields                      &f = particles.fields;
    for (auto &p : particles.handler)
      {
        auto props = p.get_properties();
        props[f.mass] += 0.5 * r(rng) * props[f.mass];
        for (unsigned int d = 0; d < 2; ++d)
          props[f.velocity + d] = r(rng);
        for (unsigned int i = 0; i < 3; ++i)
          props[f.stress + i] = 100. * r(rng);
        for (unsigned int i = 0; i < 4; ++i)
          props[f.deformation_gradient + i] =
            (i == 0 || i == 3 ? 1. : 0.) + 0.1 * r(rng);
      }
    fields.increment_weight.reinit(grid.partitioner);
    for (unsigned int i = 0; i < fields.mass.locally_owned_size() +
                                   grid.partitioner->n_ghost_indices();
         ++i)
      {
        fields.increment_weight.local_element(i) = 0.5 + 0.5 * r(rng);
        for (unsigned int d = 0; d < 2; ++d)
          {
            fields.velocity[d].local_element(i)           = r(rng);
            fields.velocity_increment[d].local_element(i) = 0.1 * r(rng);
          }
      }
    fields.has_light_nodes = true;
  }

  void
  check_weights_where_used(const std::string &scene)
  {
    auto         simulation = test::make_simulation<2>(scene);
    std::mt19937 rng(7);
    test::scatter_particles_in_cells(*simulation, rng);
    ParticleSet<2>          &particles = simulation->particle_set();
    const BackgroundGrid<2> &grid      = simulation->background_grid();
    NodalFields<2>           fields, fields_where_used, fields_stored_remap;
    fields.reinit(grid.partitioner);
    fields_where_used.reinit(grid.partitioner);
    fields_stored_remap.reinit(grid.partitioner);
    randomize(particles, grid, fields, rng);

    Stencil<2> stored, where_used;
    compute_linear_stencil(grid, particles, stored);
    where_used.where_used = true;
    particle_to_grid(grid, particles, stored, fields);
    particle_to_grid(grid, particles, where_used, fields_where_used);
    expect_same_sums(fields.mass, fields_where_used.mass);
    for (unsigned int d = 0; d < 2; ++d)
      {
        expect_same_sums(fields.momentum[d], fields_where_used.momentum[d]);
        expect_same_sums(fields.force[d], fields_where_used.force[d]);
      }

    // USL's sweep: gather with the light-node pass, then move (which
    // changes the reference location the weights are computed from).
    const std::vector<double> before = particle_state(particles);
    const auto                g2p    = [&](const Stencil<2> &stencil) {
      set_particle_state(particles, before);
      grid_to_particle<G2P::motion_and_deformation>(grid,
                                                    stencil,
                                                    WithLightNodes<2>{fields},
                                                    /*dt=*/0.01,
                                                    /*flip_fraction=*/0.9,
                                                    particles);
      return particle_state(particles);
    };
    const std::vector<double> after_stored     = g2p(stored);
    const std::vector<double> after_where_used = g2p(where_used);
    ASSERT_EQ(after_stored.size(), after_where_used.size());
    unsigned int differ = 0;
    for (std::size_t i = 0; i < after_stored.size(); ++i)
      differ += after_stored[i] != after_where_used[i];
    EXPECT_EQ(differ, 0u);
    EXPECT_NE(after_stored, before); // the sweep did something

    // MUSL's G2P, re-map and stress update: the stored weights are the
    // step's start's; computed where used, from the reference location
    // its G2P leaves and its stress update sets.
    const auto musl = [&](const Stencil<2> &stencil, NodalFields<2> &remap) {
      set_particle_state(particles, before);
      const bool keep = stencil.where_used;
      if (keep)
        grid_to_particle<G2P::motion_keeping_reference>(
          grid, stencil, fields, 0.01, 0.9, particles);
      else
        grid_to_particle<G2P::motion>(
          grid, stencil, fields, 0.01, 0.9, particles);
      particle_to_grid(grid, particles, stencil, remap, true, false);
      if (keep)
        grid_to_particle<G2P::deformation_then_reference>(
          grid, stencil, remap, 0.01, 0.9, particles);
      else
        grid_to_particle<G2P::deformation>(
          grid, stencil, remap, 0.01, 0.9, particles);
      return particle_state(particles);
    };
    const std::vector<double> musl_stored = musl(stored, fields_stored_remap);
    const std::vector<double> musl_where_used =
      musl(where_used, fields_where_used);
    expect_same_sums(fields_stored_remap.mass, fields_where_used.mass);
    for (unsigned int d = 0; d < 2; ++d)
      expect_same_sums(fields_stored_remap.momentum[d],
                       fields_where_used.momentum[d]);
    // The re-mapped velocity carries P2G's round-off into L and F.
    differ = 0;
    for (std::size_t i = 0; i < musl_stored.size(); ++i)
      differ += std::abs(musl_stored[i] - musl_where_used[i]) >
                1e-12 * std::max(1., std::abs(musl_stored[i]));
    EXPECT_EQ(differ, 0u);
    EXPECT_NE(musl_stored, before);
  }
} // namespace

TEST(ParticleWeights, WhereUsedEqualStoredWithHangingNodes)
{
  check_weights_where_used(refined_scene);
}

TEST(ParticleWeights, WhereUsedEqualStoredOnDistortedCells)
{
  check_weights_where_used(distorted_scene);
}

namespace
{
  /** LinearWeights at random points of every cell are deal.II's FE_Q(1)
   * values and gradients (times d xi / d x), and sum to one (also where
   * hanging nodes are resolved into their masters). */
  template <int dim>
  void
  check_q1_values(const std::string &scene)
  {
    auto                       simulation = test::make_simulation<dim>(scene);
    const BackgroundGrid<dim> &grid       = simulation->background_grid();
    const FE_Q<dim>            fe(1);
    const LinearWeights<dim>   weights{grid};
    std::mt19937               rng(11);
    std::uniform_real_distribution<double> unit(0., 1.);
    unsigned int                           n_unconstrained = 0;
    for (const GridCell<dim> &c : grid.cells)
      {
        Point<dim> xi;
        for (unsigned int d = 0; d < dim; ++d)
          xi[d] = unit(rng);
        const Tensor<2, dim> K =
          c.affine ? c.inverse_jacobian : c.inverse_jacobian_at(xi);
        double       sum = 0;
        unsigned int v   = 0;
        weights.at(xi,
                   c,
                   [&](const unsigned int    node,
                       const double          N,
                       const Tensor<1, dim> &grad_N) {
                     sum += N;
                     if (c.first_weight != numbers::invalid_unsigned_int)
                       return;
                     EXPECT_EQ(node, grid.cell_nodes[c.first_node + v]);
                     EXPECT_NEAR(N, fe.shape_value(v, xi), 1e-15);
                     EXPECT_LT((grad_N - fe.shape_grad(v, xi) * K).norm(),
                               1e-14 * K.norm());
                     ++v;
                   });
        EXPECT_NEAR(sum, 1., 1e-14);
        n_unconstrained += c.first_weight == numbers::invalid_unsigned_int;
      }
    EXPECT_GT(n_unconstrained, 0u);
  }
} // namespace

TEST(ParticleWeights, LinearWeightsAreQ1Functions)
{
  check_q1_values<2>(refined_scene);
  check_q1_values<2>(distorted_scene);
  check_q1_values<3>("set Dimension = 3\nsubsection Grid\n set Lower corner = "
                     "0, 0, 0\n set Upper corner = 1, 2, 1\n set Cells = 2, "
                     "3, 2\n subsection Local refinement\n  set Levels = "
                     "1\n  set Lower corner = 0, 0, 0\n  set Upper corner "
                     "= 0.5, 0.7, 0.5\n end\nend\n");
}
