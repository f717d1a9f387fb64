// Linear weights computed where P2G and G2P use them (Stencil::where_used)
// give what the stored linear stencil gives, to round-off: G2P's velocity,
// position, reference location and F in USL's sweep (with the light-node
// weights; in a box cell by multilinear interpolation, BoxQ1Component),
// P2G's nodal mass, momentum and force (it sums a cell's particles first,
// in a box cell the force by direction, BoxCellSums) and so MUSL's G2P,
// re-map and stress update (which keep the reference location until the
// stress update), the re-map also made in MUSL's G2P sweep; on grids with
// hanging nodes in 2D and 3D and on distorted (non-affine) cells. The weights
// themselves are deal.II's Q1 functions. The same for the quadratic
// B-spline's and uGIMP's weights computed where used.
#include <deal.II/fe/fe_q.h>

#include <dealmpm/transfer/grid_to_particle.h>
#include <dealmpm/transfer/particle_to_grid.h>

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  const std::string refined_scene = R"(
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

  /** Box cells of three sizes (h = 0.25 to 1/12 along x, unequal edges)
   * with hanging nodes between them. */
  const std::string refined_scene_3d = R"(
set Dimension = 3
subsection Grid
  set Lower corner = 0, 0, 0
  set Upper corner = 1, 2, 1
  set Cells = 3, 4, 2
  subsection Local refinement
    set Levels = 2
    set Lower corner = 0, 0, 0
    set Upper corner = 0.5, 0.7, 0.5
  end
end
subsection Body 1
  set Lower corner = 0, 0, 0
  set Upper corner = 1, 2, 1
  set Particles per cell = 2
end
)";

  /** Quadratic B-splines on a grid of unequal edges (h = 2/7 by 1/5, in
   * 3D by 1/3) that the body fills, so that the half cells next to the
   * boundaries, where the splines turn into hats, hold particles. */
  const std::string bspline_scene = R"(
set Dimension = 2
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 2, 1
  set Cells = 7, 5
end
subsection Body 1
  set Lower corner = 0, 0
  set Upper corner = 2, 1
  set Particles per cell = 2
end
subsection MPM
  set Shape function = quadratic B-spline
end
)";

  const std::string bspline_scene_3d = R"(
set Dimension = 3
subsection Grid
  set Lower corner = 0, 0, 0
  set Upper corner = 2, 1, 1
  set Cells = 7, 5, 3
end
subsection Body 1
  set Lower corner = 0, 0, 0
  set Upper corner = 2, 1, 1
  set Particles per cell = 2
end
subsection MPM
  set Shape function = quadratic B-spline
end
)";

  /** uGIMP on the B-spline's grids: domains of a quarter cell (two
   * particles a cell a direction), those next to the grid's edge clipped
   * there. */
  const std::string ugimp_scene =
    bspline_scene + "subsection MPM\n set Shape function = uGIMP\nend\n";
  const std::string ugimp_scene_3d =
    bspline_scene_3d + "subsection MPM\n set Shape function = uGIMP\nend\n";
  /** Domains of half a cell, the most the windows take: every domain
   * reaches into a neighbour. */
  const std::string ugimp_scene_one_a_cell =
    ugimp_scene + "subsection Body 1\n set Particles per cell = 1\nend\n";

  /** The same with cpGIMP. */
  const std::string cpgimp =
    "subsection MPM\n set Shape function = cpGIMP\nend\n";
  const std::string cpgimp_scene            = ugimp_scene + cpgimp;
  const std::string cpgimp_scene_3d         = ugimp_scene_3d + cpgimp;
  const std::string cpgimp_scene_one_a_cell = ugimp_scene_one_a_cell + cpgimp;

  /** Appended to a scene: the particles carry APIC's B. */
  const std::string apic = "subsection MPM\n set Velocity update = APIC\nend\n";

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

  /** How many entries of two particle states differ by more than
   * round-off: in a box cell G2P interpolates the nodal values by
   * successive linear interpolation (BoxQ1Component), not as
   * sum_v N_v u_v, so v, L and what follows from them change by a few
   * ulps of the nodal values (of order 1 here); 1e-12 is far above that
   * and far below a wrong weight's O(0.01 to 1) error. */
  unsigned int
  n_differ(const std::vector<double> &a, const std::vector<double> &b)
  {
    unsigned int differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      differ += std::abs(a[i] - b[i]) > 1e-12 * std::max(1., std::abs(a[i]));
    return differ;
  }

  /** A scene's particles scattered at random in their cells, with a
   * random state and random nodal velocities (fields), and the linear
   * stencil both stored and computed where used. */
  template <int dim>
  struct RandomState
  {
    decltype(test::make_simulation<dim>(std::string())) simulation;
    ParticleSet<dim>                                   &particles;
    const BackgroundGrid<dim>                          &grid;
    NodalFields<dim>                                    fields;
    Stencil<dim>                                        stored, where_used;
    std::vector<double>                                 before;

    /** GIMP's domain half-lengths times @p half_length_scale. */
    RandomState(const std::string &scene,
                const unsigned int seed,
                const double       half_length_scale = 1.)
      : simulation(test::make_simulation<dim>(scene))
      , particles(simulation->particle_set())
      , grid(simulation->background_grid())
    {
      std::mt19937 rng(seed);
      test::scatter_particles_in_cells(*simulation, rng);
      fields.reinit(grid.partitioner);
      test::randomize_state(particles, grid, fields, rng);
      const unsigned int half_length = particles.fields.domain_half_length;
      if (half_length != numbers::invalid_unsigned_int)
        for (auto &p : particles.handler)
          for (unsigned int d = 0; d < dim; ++d)
            p.get_properties()[half_length + d] *= half_length_scale;
      const Kernel<dim> &kernel = simulation->get_kernel();
      kernel.compute_stencil(grid, particles, stored);
      if (particles.fields.affine_velocity != numbers::invalid_unsigned_int)
        record_positions(grid, particles, stored);
      where_used.where_used               = true;
      where_used.spline                   = kernel.spline_grid();
      where_used.gimp_lattice             = kernel.gimp_lattice();
      where_used.gimp_half_length         = half_length;
      where_used.gimp_follows_deformation = kernel.name() == "cpGIMP";
      if (where_used.gimp_lattice != nullptr)
        {
          EXPECT_TRUE(domains_fit_windows(grid,
                                          particles,
                                          where_used.gimp_follows_deformation));
        }
      before = test::particle_state(particles);
    }

    /** @p more sized for the grid. */
    template <typename... Fields>
    void
    reinit(Fields &...more) const
    {
      (more.reinit(grid.partitioner), ...);
    }
  };

  template <int dim>
  void
  check_weights_where_used(const std::string &scene,
                           const double       half_length_scale = 1.)
  {
    RandomState<dim>           state(scene, 7, half_length_scale);
    ParticleSet<dim>          &particles  = state.particles;
    const BackgroundGrid<dim> &grid       = state.grid;
    NodalFields<dim>          &fields     = state.fields;
    const Stencil<dim>        &stored     = state.stored;
    const Stencil<dim>        &where_used = state.where_used;
    const std::vector<double> &before     = state.before;
    NodalFields<dim>           fields_where_used, fields_stored_remap;
    state.reinit(fields_where_used, fields_stored_remap);
    particle_to_grid(grid, particles, stored, fields);
    particle_to_grid(grid, particles, where_used, fields_where_used);
    expect_same_sums(fields.mass, fields_where_used.mass);
    for (unsigned int d = 0; d < dim; ++d)
      {
        expect_same_sums(fields.momentum[d], fields_where_used.momentum[d]);
        expect_same_sums(fields.force[d], fields_where_used.force[d]);
      }

    // USL's sweep: gather with the light-node pass, then move (which
    // changes the reference location the weights are computed from).
    const auto g2p = [&](const Stencil<dim> &stencil) {
      test::set_particle_state(particles, before);
      grid_to_particle<G2P::motion_and_deformation>(grid,
                                                    stencil,
                                                    WithLightNodes<dim>{fields},
                                                    /*dt=*/0.01,
                                                    /*flip_fraction=*/0.9,
                                                    particles);
      return test::particle_state(particles);
    };
    const std::vector<double> after_stored     = g2p(stored);
    const std::vector<double> after_where_used = g2p(where_used);
    ASSERT_EQ(after_stored.size(), after_where_used.size());
    EXPECT_EQ(n_differ(after_stored, after_where_used), 0u);
    EXPECT_NE(after_stored, before); // the sweep did something

    // MUSL's G2P, re-map and stress update: the stored weights are the
    // step's start's; computed where used, from the reference location
    // its G2P leaves and its stress update sets.
    const auto musl = [&](const Stencil<dim> &stencil,
                          NodalFields<dim>   &remap) {
      test::set_particle_state(particles, before);
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
      return test::particle_state(particles);
    };
    const std::vector<double> musl_stored = musl(stored, fields_stored_remap);
    const std::vector<double> musl_where_used =
      musl(where_used, fields_where_used);
    expect_same_sums(fields_stored_remap.mass, fields_where_used.mass);
    for (unsigned int d = 0; d < dim; ++d)
      expect_same_sums(fields_stored_remap.momentum[d],
                       fields_where_used.momentum[d]);
    // The re-mapped velocity carries P2G's round-off into L and F.
    EXPECT_EQ(n_differ(musl_stored, musl_where_used), 0u);
    EXPECT_NE(musl_stored, before);
  }
} // namespace

TEST(ParticleWeights, WhereUsedEqualStoredWithHangingNodes)
{
  check_weights_where_used<2>(refined_scene);
}

TEST(ParticleWeights, WhereUsedEqualStoredOnDistortedCells)
{
  check_weights_where_used<2>(distorted_scene);
}

TEST(ParticleWeights, WhereUsedEqualStoredIn3D)
{
  check_weights_where_used<3>(refined_scene_3d);
}

// APIC with weights computed where used: B = L_v D and C = B D^-1 by
// their closed forms in box cells, the sums about the particle's position
// (G2P, MUSL's re-map in its sweep) or the weights' centroid (P2G, also
// MUSL's re-map after its sweep) elsewhere; the stored stencil measures
// from its recorded positions.
TEST(ParticleWeights, ApicWhereUsedEqualsStored)
{
  check_weights_where_used<2>(refined_scene + apic);
  check_weights_where_used<2>(distorted_scene + apic);
  check_weights_where_used<3>(refined_scene_3d + apic);
}

// The quadratic B-spline's weights computed where used (BSplineWeights)
// are those of its stored stencil: P2G into the interleaved block, G2P,
// MUSL's deferred reference location, APIC.
TEST(ParticleWeights, BSplineWhereUsedEqualsStored)
{
  check_weights_where_used<2>(bspline_scene);
  check_weights_where_used<3>(bspline_scene_3d);
  check_weights_where_used<2>(bspline_scene + apic);
  check_weights_where_used<3>(bspline_scene_3d + apic);
}

namespace
{
  /** MUSL's G2P with the re-map in its sweep (RemapInSweep) leaves the
   * particles as the G2P without it does, and the nodal mass and momentum
   * that particle_to_grid() re-maps after that G2P (to round-off: a cell
   * with hanging nodes or a distorted cell adds its particles in another
   * order), with the weights computed where used and stored; with the
   * mass kept, the same momentum and the mass untouched. */
  template <int dim>
  void
  check_remap_in_sweep(const std::string &scene,
                       const double       half_length_scale = 1.)
  {
    RandomState<dim>           state(scene, 11, half_length_scale);
    ParticleSet<dim>          &particles = state.particles;
    const BackgroundGrid<dim> &grid      = state.grid;
    const NodalFields<dim>    &fields    = state.fields;
    const std::vector<double> &before    = state.before;
    NodalFields<dim>           after_sweep, in_sweep;
    state.reinit(after_sweep, in_sweep);
    for (const Stencil<dim> *stencil : {&state.stored, &state.where_used})
      {
        // MUSL's G2P as stages::g2p() runs it for each kind of stencil.
        const auto run = [&](const auto what, auto &&remap) {
          grid_to_particle<decltype(what)::value>(grid,
                                                  *stencil,
                                                  fields,
                                                  0.01,
                                                  0.9,
                                                  particles,
                                                  NoAfterDeformation(),
                                                  NoGradientAdjustment(),
                                                  FirstOrderIncrement(),
                                                  remap);
        };
        const auto g2p = [&](auto &&remap) {
          test::set_particle_state(particles, before);
          if (stencil->where_used)
            run(std::integral_constant<G2P, G2P::motion_keeping_reference>(),
                remap);
          else
            run(std::integral_constant<G2P, G2P::motion>(), remap);
          return test::particle_state(particles);
        };
        const std::vector<double> moved = g2p(NoRemap());
        particle_to_grid(grid, particles, *stencil, after_sweep, true, false);
        in_sweep.mass           = 1.; // what the re-map must not add to
        const auto in_the_sweep = [&](auto &&remap) {
          EXPECT_EQ(g2p(remap), moved);
          remap.finish();
        };
        if (particles.fields.affine_velocity != numbers::invalid_unsigned_int)
          in_the_sweep(RemapInSweep<dim, true>(in_sweep, grid));
        else
          in_the_sweep(RemapInSweep<dim>(in_sweep, grid));
        EXPECT_NE(moved, before);
        expect_same_sums(after_sweep.mass, in_sweep.mass);
        for (unsigned int d = 0; d < dim; ++d)
          expect_same_sums(after_sweep.momentum[d], in_sweep.momentum[d]);

        // Keeping P2G's mass (no bonded FE region): the same momentum, and
        // the mass as it was, to the bit.
        in_sweep.mass = 7.;
        const NodalVector kept(in_sweep.mass);
        if (particles.fields.affine_velocity != numbers::invalid_unsigned_int)
          in_the_sweep(RemapInSweep<dim, true, true>(in_sweep, grid));
        else
          in_the_sweep(RemapInSweep<dim, false, true>(in_sweep, grid));
        for (unsigned int i = 0; i < kept.locally_owned_size(); ++i)
          EXPECT_EQ(in_sweep.mass.local_element(i), kept.local_element(i));
        for (unsigned int d = 0; d < dim; ++d)
          expect_same_sums(after_sweep.momentum[d], in_sweep.momentum[d]);
      }
  }
} // namespace

TEST(ParticleWeights, MuslRemapInTheSweepEqualsTheRemapAfterIt)
{
  check_remap_in_sweep<2>(refined_scene);
  check_remap_in_sweep<2>(distorted_scene);
  check_remap_in_sweep<3>(refined_scene_3d);
}

TEST(ParticleWeights, ApicMuslRemapInTheSweepEqualsTheRemapAfterIt)
{
  check_remap_in_sweep<2>(refined_scene + apic);
  check_remap_in_sweep<2>(distorted_scene + apic);
  check_remap_in_sweep<3>(refined_scene_3d + apic);
}

TEST(ParticleWeights, BSplineMuslRemapInTheSweepEqualsTheRemapAfterIt)
{
  check_remap_in_sweep<2>(bspline_scene);
  check_remap_in_sweep<3>(bspline_scene_3d + apic);
}

// uGIMP's weights computed where used (GimpWindows) are those of its stored
// stencil (the lattice path inside the grid, the general path, normalised
// by the covered volume, where a domain reaches past the grid's edge):
// P2G, G2P, MUSL's deferred reference location and re-map in its sweep;
// domains of a quarter and of half a cell. Not with APIC, which keeps
// stored weights (Simulation::weights_where_used()): where used, P2G
// measures from the weights' centroid, which for a domain clipped at the
// grid's edge is not the particle's position the stored path measures from.
TEST(ParticleWeights, UGimpWhereUsedEqualsStored)
{
  check_weights_where_used<2>(ugimp_scene);
  check_weights_where_used<2>(ugimp_scene_one_a_cell);
  check_weights_where_used<3>(ugimp_scene_3d);
  check_remap_in_sweep<2>(ugimp_scene_one_a_cell);
  check_remap_in_sweep<3>(ugimp_scene_3d);
}

// cpGIMP's domains stretched by F's diagonal (0.9 to 1.1 here), so that
// they reach into a neighbour or stay in their cell where uGIMP's would
// not: the windows give the stored weights, also with domains of half a
// cell after the stretch (one particle a cell, half-lengths scaled by
// 1 / 1.1), and G2P's new F does not change the weights of the sweep that
// updates it.
TEST(ParticleWeights, CpGimpWhereUsedEqualsStored)
{
  check_weights_where_used<2>(cpgimp_scene);
  check_weights_where_used<2>(cpgimp_scene_one_a_cell, 1. / 1.1);
  check_weights_where_used<3>(cpgimp_scene_3d);
  check_remap_in_sweep<2>(cpgimp_scene_one_a_cell, 1. / 1.1);
  check_remap_in_sweep<3>(cpgimp_scene_3d);
}

namespace
{
  /** Visits WindowWeights make of @p state's particles; each visited node
   * must carry weight (a visit of zero weight is padding the sweeps pay
   * for), and the weights must sum to one and their gradients to zero.
   * Returns the visits per particle, at most and at least. */
  template <int dim>
  std::pair<unsigned int, unsigned int>
  check_window_visits(const RandomState<dim> &state)
  {
    const auto   weights = WindowWeights<dim>::of(state.grid, state.where_used);
    unsigned int most = 0, least = std::numeric_limits<unsigned int>::max();
    for_each_particle_in_stencil_order(
      state.grid,
      state.particles,
      [&](const std::size_t k, const auto &p, const GridCell<dim> &c) {
        unsigned int   visits = 0, zero = 0;
        double         sum = 0;
        Tensor<1, dim> sum_grad;
        weights(k,
                p,
                c,
                [&](unsigned int, const double N, const Tensor<1, dim> &grad) {
                  ++visits;
                  zero += N == 0.;
                  sum += N;
                  sum_grad += grad;
                });
        EXPECT_EQ(zero, 0u) << "particle " << k;
        EXPECT_NEAR(sum, 1., 1e-14);
        // Gradients of order 1 / h (h = 1/7 to 1/5 here).
        EXPECT_LT(sum_grad.norm(), 1e-12);
        most  = std::max(most, visits);
        least = std::min(least, visits);
      });
    return {most, least};
  }
} // namespace

// GIMP's windows visit the nodes that carry weight and no other: a domain
// inside its cell along a direction has two there, along x too (no padded
// third node), so a particle whose domain stays in its cell visits 2^dim
// nodes, as linear weights do; scattered, the domains reach into
// neighbours and a particle visits up to 3^dim.
TEST(ParticleWeights, GimpWindowsVisitOnlyNodesWithWeight)
{
  const auto check = [](const std::string &scene, auto dimension) {
    constexpr int    dim = decltype(dimension)::value;
    RandomState<dim> state(scene, 7);
    EXPECT_EQ(check_window_visits(state).first, dim == 2 ? 9u : 27u);
    // Each particle at its cell's centre: its domain (a quarter cell,
    // cpGIMP's stretched by at most 1.1) stays in the cell.
    for (const GridCell<dim> &c : state.grid.cells)
      for (auto &p : state.particles.handler.particles_in_cell(c.cell))
        {
          Point<dim> centre;
          for (unsigned int d = 0; d < dim; ++d)
            centre[d] = 0.5;
          p.set_reference_location(centre);
          p.set_location(c.real_point(centre));
        }
    const auto [most, least] = check_window_visits(state);
    EXPECT_EQ(most, 1u << dim);
    EXPECT_EQ(least, 1u << dim);
  };
  check(ugimp_scene, std::integral_constant<int, 2>());
  check(cpgimp_scene, std::integral_constant<int, 2>());
  check(ugimp_scene_3d, std::integral_constant<int, 3>());
  check(cpgimp_scene_3d, std::integral_constant<int, 3>());
}

// GIMP's windows are used only where they give the stored weights: not
// on grids with one cell across (no node to pad with), local refinement
// (no lattice) or cells missing from a patch that are not whole rows (the
// inner corner of an L: the covered part of a domain is no box), nor with
// a domain wider than half its cell (for cpGIMP, once stretched by F).
TEST(ParticleWeights, GimpWindowsOnlyWhereTheyFit)
{
  const auto fit = [](const std::string &scene) {
    auto simulation = test::make_simulation<2>(scene);
    return simulation->get_kernel().gimp_lattice() != nullptr;
  };
  const std::string ugimp =
    "subsection MPM\n set Shape function = uGIMP\nend\n";
  EXPECT_TRUE(fit(ugimp_scene));
  EXPECT_TRUE(fit(cpgimp_scene));
  EXPECT_FALSE(fit(ugimp_scene + "subsection Grid\n set Cells = 7, 1\nend\n"));
  EXPECT_FALSE(fit(refined_scene + ugimp));
  EXPECT_FALSE(fit(
    "subsection Grid\n set Type = mesh file\n set Mesh file = " DEALMPM_SOURCE_DIR
    "/tests/data/l_shaped.msh\n set Global refinements = 1\nend\n"
    "subsection Body 1\n set Lower corner = 0.1, 0.1\n set Upper "
    "corner = 0.9, 0.9\nend\n" +
    ugimp));

  auto                     simulation = test::make_simulation<2>(ugimp_scene);
  ParticleSet<2>          &particles  = simulation->particle_set();
  const BackgroundGrid<2> &grid       = simulation->background_grid();
  EXPECT_TRUE(domains_fit_windows(grid, particles));
  const unsigned int half_length = particles.fields.domain_half_length;
  for_each_particle_in_stencil_order(
    grid,
    particles,
    [&](const std::size_t k, const auto &p, const GridCell<2> &c) {
      if (k == 5)
        p.get_properties()[half_length + 1] = 0.51 / c.inverse_jacobian[1][1];
    });
  EXPECT_FALSE(domains_fit_windows(grid, particles));

  // cpGIMP: a domain of 0.3 cells fits, stretched by 1.7 it does not; the
  // grid-wide limit (Stencil::gimp_stretch_limit) is half the shortest
  // edge along each direction (2/7 by 1/5 here).
  auto                     cp        = test::make_simulation<2>(cpgimp_scene);
  ParticleSet<2>          &stretched = cp->particle_set();
  const BackgroundGrid<2> &cp_grid   = cp->background_grid();
  EXPECT_TRUE(domains_fit_windows(cp_grid, stretched, true));
  for_each_particle_in_stencil_order(
    cp_grid,
    stretched,
    [&](const std::size_t k, const auto &p, const GridCell<2> &c) {
      const auto props = p.get_properties();
      if (k == 5)
        {
          props[stretched.fields.domain_half_length + 1] =
            0.3 / c.inverse_jacobian[1][1];
          props[stretched.fields.deformation_gradient + 3] = 1.7;
        }
    });
  EXPECT_TRUE(domains_fit_windows(cp_grid, stretched, false));
  EXPECT_FALSE(domains_fit_windows(cp_grid, stretched, true));
  const Tensor<1, 2> limit = gimp_stretch_limit(cp_grid);
  EXPECT_NEAR(limit[0], 1. / 7, 1e-12);
  EXPECT_NEAR(limit[1], 0.1, 1e-12);
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
