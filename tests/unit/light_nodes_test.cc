// USL's light nodes (update_nodal_velocity()) lend a particle's velocity
// gradient only the weight w of their own increment, and the particle's
// interpolated dv for the rest: L = sum_i (v_i - (1 - w_i) (dv_i - dv))
// (x) grad N_i over the particle's whole stencil. A GIMP stencil reaches
// the nodes of the next cells, so a light node there counts even where
// the particle's own cell has none. Checked against that sum, computed
// here from the stored stencil, through F's first-order update
// F <- (I + dt L) F.
#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stencil_order.h>

#include <gtest/gtest.h>

#include <map>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  template <int dim>
  Tensor<2, dim>
  deformation_gradient(const ArrayView<const double> &props,
                       const CoreFields              &f)
  {
    Tensor<2, dim> F;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[i][j] = props[f.deformation_gradient + i * dim + j];
    return F;
  }

  /** A uniform grid of 4 x 4 cells filled with particles scattered in
   * their cells, one light node (w = 0.25) in its middle and every other
   * node of weight 1: after USL's G2P sweep with @p shape's stencil, each
   * particle's F is (I + dt L) F with L the sum above. Returns how many
   * particles reach the light node from outside its cells. */
  unsigned int
  check_light_node(const std::string &shape)
  {
    constexpr int dim        = 2;
    auto          simulation = test::make_simulation<dim>(
      "subsection Grid\n set Upper corner = 1, 1\n set Cells = 4, 4\nend\n"
               "subsection Body 1\n set Upper corner = 1, 1\nend\n"
               "subsection MPM\n set Shape function = " +
      shape + "\nend\n");
    ParticleSet<dim>          &particles = simulation->particle_set();
    const BackgroundGrid<dim> &grid      = simulation->background_grid();
    const CoreFields          &f         = particles.fields;
    std::mt19937               rng(3);
    test::scatter_particles_in_cells(*simulation, rng);
    NodalFields<dim> fields;
    fields.reinit(grid.partitioner);
    test::randomize_state(particles, grid, fields, rng);
    EXPECT_TRUE(grid.has_neighbors()); // GIMP's set-up finds them
    if (!grid.has_neighbors())
      return 0;
    Stencil<dim> stencil;
    compute_gimp_stencil(grid, particles, shape == "cpGIMP", stencil);

    // Every node full but the one at (0.5, 0.5).
    unsigned int light = numbers::invalid_unsigned_int;
    for (unsigned int i = 0; i < grid.node_positions.size(); ++i)
      {
        const bool middle =
          grid.node_positions[i].distance(Point<dim>(0.5, 0.5)) < 1e-12;
        fields.increment_weight.local_element(i) = middle ? 0.25 : 1.;
        if (middle)
          light = i;
      }
    EXPECT_NE(light, numbers::invalid_unsigned_int);

    const double                                    dt = 0.01;
    std::map<types::particle_index, Tensor<2, dim>> expected;
    unsigned int                                    from_outside = 0;
    for_each_particle_in_stencil_order(
      grid,
      std::as_const(particles),
      [&](const std::size_t k, const auto &p, const GridCell<dim> &cell) {
        Tensor<1, dim> dv;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          for (unsigned int d = 0; d < dim; ++d)
            dv[d] += stencil.N[e] * fields.velocity_increment[d].local_element(
                                      stencil.node[e]);
        Tensor<2, dim> L;
        bool           reaches = false;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          {
            const unsigned int n = stencil.node[e];
            const double       w = fields.increment_weight.local_element(n);
            reaches              = reaches || n == light;
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int b = 0; b < dim; ++b)
                L[d][b] +=
                  (fields.velocity[d].local_element(n) -
                   (1 - w) *
                     (fields.velocity_increment[d].local_element(n) - dv[d])) *
                  stencil.grad_N[e][b];
          }
        bool own = false;
        for (unsigned int j = 0; j < cell.n_nodes; ++j)
          own = own || grid.cell_nodes[cell.first_node + j] == light;
        from_outside += reaches && !own;
        Tensor<2, dim> dF = dt * L;
        for (unsigned int d = 0; d < dim; ++d)
          dF[d][d] += 1.;
        expected[p.get_id()] =
          dF * deformation_gradient<dim>(p.get_properties(), f);
      });

    grid_to_particle<G2P::motion_and_deformation>(grid,
                                                  stencil,
                                                  WithLightNodes<dim>{fields},
                                                  dt,
                                                  /*flip_fraction=*/0.9,
                                                  particles);
    unsigned int differ = 0;
    for (const auto &p : particles.handler)
      differ += (deformation_gradient<dim>(p.get_properties(), f) -
                 expected.at(p.get_id()))
                  .norm() > 1e-12;
    EXPECT_EQ(differ, 0u) << shape;
    return from_outside;
  }
} // namespace

// The stencil's nodes, not only the cell's: on the old code, which looked
// at the cell's nodes, every particle reaching the light node from a next
// cell kept the full increment there (F off by about dt 0.75 |dv| |grad N|,
// 1e-3, against round-off's 1e-15).
TEST(LightNodes, CountOverTheWholeGimpStencil)
{
  for (const std::string shape : {"uGIMP", "cpGIMP"})
    EXPECT_GT(check_light_node(shape), 0u) << shape;
}
