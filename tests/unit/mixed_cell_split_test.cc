// The mixed-cell split (MixedCellSplit): in a cell shared by a soft and a
// stiff layer under a uniform compression, the normal strain rate divides in
// inverse proportion to the moduli, the cell's volume change stays the
// grid's, the other components stay the grid's, and different stresses that
// the layers bring are equalised; interleaved materials and a single
// material are left alone.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/mixed_cell_split.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  // One cell; body 1 (material 1) fills its lower half, body 2 (material 2)
  // its upper half, 4 x 4 particles per cell: two rows each.
  const char *layers = R"(
set Dimension = 2
set Number of bodies = 2
set Number of materials = 2
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Cells = 1, 1
end
subsection Body 1
  set Shape = box
  set Lower corner = 0, 0
  set Upper corner = 1, 0.5
  set Particles per cell = 4
  set Material = 1
end
subsection Body 2
  set Shape = box
  set Lower corner = 0, 0.5
  set Upper corner = 1, 1
  set Particles per cell = 4
  set Material = 2
end
)";

  /** The velocity gradient @p A (plus a translation) at every node. */
  void
  set_linear_velocity(const BackgroundGrid<2> &grid,
                      const Tensor<2, 2>      &A,
                      NodalFields<2>          &fields)
  {
    fields.reinit(grid.partitioner);
    std::map<types::global_dof_index, Point<2>> nodes;
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(),
                                         grid.dof_handler,
                                         nodes);
    for (const auto &[dof, x] : nodes)
      for (unsigned int d = 0; d < 2; ++d)
        fields.velocity[d].local_element(
          grid.partitioner->global_to_local(dof)) = (A * x)[d] + 0.1;
  }

  struct Result
  {
    std::vector<Tensor<2, 2>> L;
    std::vector<unsigned int> material;
    std::vector<double>       volume;
    std::vector<double>       stress_yy; ///< before the step
    unsigned int              split_cells;
  };

  /** The split velocity gradient of each particle of the layers under the
   * uniform gradient @p A, with moduli @p modulus and the stress sigma_yy
   * of each material @p stress_yy; with @p checkerboard, the materials are
   * re-assigned in a 4 x 4 checkerboard. */
  Result
  split(const Tensor<2, 2>        &A,
        const std::vector<double> &modulus,
        const std::vector<double> &stress_yy,
        const double               dt,
        const bool                 checkerboard = false)
  {
    auto              simulation = test::make_simulation<2>(layers, 2, 2);
    ParticleSet<2>   &particles  = simulation->particle_set();
    const CoreFields &f          = particles.fields;
    for (auto &p : particles.handler)
      {
        const auto props = p.get_properties();
        // Body b is of material b (the scene above).
        if (checkerboard)
          props[f.body] = (static_cast<int>(4 * p.get_location()[0]) +
                           static_cast<int>(4 * p.get_location()[1])) %
                          2;
        const unsigned int m = particles.material_of(props);
        props[f.stress + 1]  = stress_yy[m]; // deal.II's order: xx, yy, xy
      }
    const auto    &grid = simulation->background_grid();
    NodalFields<2> fields;
    set_linear_velocity(grid, A, fields);
    Stencil<2> stencil;
    compute_linear_stencil(grid, particles, stencil);

    MixedCellSplit<2> mixed_cells(modulus);
    mixed_cells.prepare(grid, particles, stencil, fields, dt);
    Result r;
    r.split_cells = mixed_cells.n_split_cells();
    grid_to_particle<G2P::deformation>(
      grid,
      stencil,
      fields,
      dt,
      1.,
      particles,
      [&](const auto &,
          const ArrayView<double> &props,
          const Tensor<2, 2>      &L,
          const Tensor<2, 2> &,
          double) {
        r.L.push_back(L);
        r.material.push_back(particles.material_of(props));
        r.volume.push_back(props[f.initial_volume]);
        r.stress_yy.push_back(props[f.stress + 1]);
      },
      mixed_cells);
    return r;
  }

  const Tensor<2, 2> compression({{0.2, 0.3}, {-0.4, -1.0}});
} // namespace

TEST(MixedCellSplit, DividesTheNormalRateByStiffnessAndKeepsTheVolumeChange)
{
  const std::vector<double> M = {1e5, 1e9};
  const Result              r = split(compression, M, {0., 0.}, 1e-3);
  ASSERT_EQ(r.split_cells, 1u);
  ASSERT_EQ(r.L.size(), 16u);
  double volume = 0, rate = 0;
  for (unsigned int p = 0; p < r.L.size(); ++p)
    {
      volume += r.volume[p];
      rate += r.volume[p] * r.L[p][1][1];
      // Only the normal (y) component changes.
      Tensor<2, 2> difference = r.L[p] - compression;
      difference[1][1]        = 0;
      EXPECT_LT(difference.norm(), 1e-12);
    }
  // The cell's volume change is the grid's.
  EXPECT_NEAR(rate / volume, compression[1][1], 1e-12);
  // Equal stress increments: M_m L_yy of each material agree.
  for (unsigned int p = 0; p < r.L.size(); ++p)
    EXPECT_NEAR(M[r.material[p]] * r.L[p][1][1],
                M[r.material[0]] * r.L[0][1][1],
                1e-9 * M[1] * std::abs(compression[1][1]));
  // The soft half takes nearly all of it: 2 L_yy over its half volume.
  for (unsigned int p = 0; p < r.L.size(); ++p)
    {
      if (r.material[p] == 0)
        {
          EXPECT_NEAR(r.L[p][1][1], 2 * compression[1][1], 1e-3);
        }
    }
}

TEST(MixedCellSplit, EqualisesTheStressesTheLayersBring)
{
  // A stiff layer at -5 kPa on a soft one at -4 kPa: after the step both
  // carry the same normal stress, reached by straining the stiff layer
  // (1 kPa / 1e9 = 1e-6, within the relaxation limit).
  const std::vector<double> M  = {1e5, 1e9};
  const double              dt = 1e-3;
  const Result              r  = split(compression, M, {-4e3, -5e3}, dt);
  double                    after[2];
  for (unsigned int p = 0; p < r.L.size(); ++p)
    after[r.material[p]] =
      r.stress_yy[p] + M[r.material[p]] * r.L[p][1][1] * dt;
  EXPECT_NEAR(after[0], after[1], 1e-9 * 5e3);
  // The shared stress is the soft layer's, moved by the cell's compression.
  EXPECT_NEAR(after[0], -4e3 + 2 * M[0] * compression[1][1] * dt, 1.);
}

TEST(MixedCellSplit, LimitsTheStrainThatEqualisesSimilarMaterials)
{
  // Moduli 1 and 2 MPa with stresses 1 MPa apart: equalising in one step
  // would strain by about 0.3; the relaxation limit allows 1e-3.
  const std::vector<double> M  = {1e6, 2e6};
  const double              dt = 1e-3;
  const Result              r  = split(Tensor<2, 2>(), M, {0., -1e6}, dt);
  for (unsigned int p = 0; p < r.L.size(); ++p)
    EXPECT_LE(std::abs(r.L[p][1][1]) * dt, 1e-3 * (1 + 1e-12));
  EXPECT_GT(std::abs(r.L[0][1][1]) * dt, 0.9e-3 / 2);
}

TEST(MixedCellSplit, LeavesEquallyStiffAndInterleavedMaterialsAlone)
{
  EXPECT_FALSE(MixedCellSplit<2>(std::vector<double>{3., 3.}).needed());
  EXPECT_TRUE(MixedCellSplit<2>(std::vector<double>{3., 4.}).needed());
  // The two materials in a checkerboard have coinciding centroids: no
  // layer, no split.
  const Result r = split(compression, {1e5, 1e9}, {0., 0.}, 1e-3, true);
  EXPECT_EQ(r.split_cells, 0u);
  for (const Tensor<2, 2> &L : r.L)
    EXPECT_LT((L - compression).norm(), 1e-12);
}
