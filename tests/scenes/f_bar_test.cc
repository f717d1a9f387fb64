// F-bar anti-locking ('MPM/Anti-locking = F-bar', FBar): the particles of
// a body in a cell share one volume rate, the mean trace of their velocity
// gradients, each keeping its own rate of shape change. With the
// first-order increment dF = I + dt L, tr dF - dim is the step's volume
// rate dt tr L and dF - I minus a third (half in 2D) of that trace its
// shape rate. Over a step of a deforming column (after 20 steps), the
// particles of each body in a cell all have the same volume rate, where a
// quarter of them or more have another without F-bar: in 2D and 3D, with
// USL, MUSL and USF and with the linear, uGIMP, CPDI and B-spline shape
// functions, and on an adapted grid. Over the first step of four blocks that
// meet in the middle of a cell, each moving its own way (the same state with
// and without F-bar, every J = 1, so that F-bar's weights, the reference
// volumes, are the volumes): each body's mean volume rate in each cell is the
// one it has without F-bar, and each particle's shape rate is its own.
// Tolerances: 1e-12, the round-off of a few sums of numbers of order one.
#include <dealmpm/transfer/stencil_order.h>

#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** What a particle was at a step's start: its cell and body, its
   * volume and F. */
  template <int dim>
  struct Before
  {
    std::size_t    cell;
    unsigned int   body;
    double         volume;
    Tensor<2, dim> F;
  };

  template <int dim>
  std::map<types::particle_index, Before<dim>>
  before_step(Simulation<dim> &simulation)
  {
    std::map<types::particle_index, Before<dim>> before;
    const ParticleSet<dim>    &particles = simulation.particle_set();
    const BackgroundGrid<dim> &grid      = simulation.background_grid();
    const CoreFields          &f         = particles.fields;
    for (std::size_t i = 0; i < grid.cells.size(); ++i)
      for_each_particle_in_cell(grid, particles, i, [&](const auto &p) {
        const auto     props = p.get_properties();
        Tensor<2, dim> F     = read_tensor<dim>(&props[f.deformation_gradient]);
        before[p.get_id()]   = {i,
                                particles.body_of(props),
                                props[f.initial_volume] * determinant(F),
                                F};
      });
    return before;
  }

  template <int dim>
  std::map<types::particle_index, Tensor<2, dim>>
  deformation_gradients(Simulation<dim> &simulation)
  {
    std::map<types::particle_index, Tensor<2, dim>> F;
    const ParticleSet<dim> &particles = simulation.particle_set();
    for (const auto &p : particles.handler)
      F[p.get_id()] = read_tensor<dim>(
        &p.get_properties()[particles.fields.deformation_gradient]);
    return F;
  }

  /** The increment dF = F_new F_old^-1 of every particle over step
   * @p steps + 1, with @p anti_locking in every step; @p before gets the
   * particles at that step's start. */
  template <int dim>
  std::map<types::particle_index, Tensor<2, dim>>
  increments(const std::string                            &scene,
             const std::string                            &anti_locking,
             const unsigned int                            n_bodies,
             const unsigned int                            steps,
             std::map<types::particle_index, Before<dim>> &before)
  {
    auto simulation =
      test::make_simulation<dim>(scene +
                                   "\nsubsection MPM\n set Anti-locking = " +
                                   anti_locking + "\nend\n",
                                 n_bodies,
                                 1);
    const double dt = simulation->time_step();
    for (unsigned int step = 0; step < steps; ++step)
      simulation->advance(dt);
    before = before_step(*simulation);
    simulation->advance(dt);
    std::map<types::particle_index, Tensor<2, dim>> dF;
    for (const auto &[id, F] : deformation_gradients(*simulation))
      dF[id] = F * invert(before.at(id).F);
    return dF;
  }

  /** The step's volume rate dt tr L of the increment dF = I + dt L. */
  template <int dim>
  double
  volume_rate(const Tensor<2, dim> &dF)
  {
    return trace(dF) - dim;
  }

  /** The step's shape rate: dt L less its volume rate's share. */
  template <int dim>
  Tensor<2, dim>
  shape_rate(const Tensor<2, dim> &dF)
  {
    return dF - (1. + volume_rate(dF) / dim) * unit_symmetric_tensor<dim>();
  }

  using Group = std::pair<std::size_t, unsigned int>; // cell, body

  /** Per group: its volume at the step's start and the volume-weighted
   * mean of @p dF's volume rate. */
  template <int dim>
  std::map<Group, std::array<double, 2>>
  group_means(const std::map<types::particle_index, Before<dim>>    &before,
              const std::map<types::particle_index, Tensor<2, dim>> &dF)
  {
    std::map<Group, std::array<double, 2>> sums;
    for (const auto &[id, b] : before)
      {
        auto &s = sums[{b.cell, b.body}];
        s[0] += b.volume;
        s[1] += b.volume * volume_rate(dF.at(id));
      }
    for (auto &[group, s] : sums)
      s[1] /= s[0];
    return sums;
  }

  /** How many particles have a volume rate other than their group's
   * mean. */
  template <int dim>
  unsigned int
  n_off_the_mean(const std::map<types::particle_index, Before<dim>>    &before,
                 const std::map<types::particle_index, Tensor<2, dim>> &dF)
  {
    const auto   means = group_means(before, dF);
    unsigned int n     = 0;
    for (const auto &[id, b] : before)
      n +=
        std::abs(volume_rate(dF.at(id)) - means.at({b.cell, b.body})[1]) > 1e-9;
    return n;
  }

  /** After @p steps steps: with F-bar, every particle of a group has the
   * group's mean volume rate; without, a quarter of them or more do not
   * (else the scene would not test it). */
  template <int dim>
  void
  check_one_volume_change(const std::string &scene,
                          const unsigned int n_bodies = 1,
                          const unsigned int steps    = 20)
  {
    std::map<types::particle_index, Before<dim>> before;
    const auto f_bar = increments<dim>(scene, "F-bar", n_bodies, steps, before);
    EXPECT_EQ(n_off_the_mean(before, f_bar), 0u);
    const auto plain = increments<dim>(scene, "none", n_bodies, steps, before);
    EXPECT_GT(n_off_the_mean(before, plain), before.size() / 4);
  }

  /** The first step from the same state, with and without F-bar: the same
   * group mean volume rates and each particle the same shape rate. */
  template <int dim>
  void
  check_against_none(const std::string &scene, const unsigned int n_bodies)
  {
    std::map<types::particle_index, Before<dim>> before;
    const auto plain   = increments<dim>(scene, "none", n_bodies, 0, before);
    const auto f_bar   = increments<dim>(scene, "F-bar", n_bodies, 0, before);
    const auto with    = group_means(before, f_bar),
               without = group_means(before, plain);
    for (const auto &[group, s] : without)
      EXPECT_NEAR(with.at(group)[1], s[1], 1e-12)
        << "cell " << group.first << ", body " << group.second;
    for (const auto &[id, b] : before)
      {
        EXPECT_LT((shape_rate(plain.at(id)) - shape_rate(f_bar.at(id))).norm(),
                  1e-12)
          << "particle " << id << ": F-bar changed its shape rate";
        EXPECT_NEAR(volume_rate(f_bar.at(id)),
                    with.at({b.cell, b.body})[1],
                    1e-12);
      }
    EXPECT_GE(n_off_the_mean(before, plain), 8u);
  }

  /** The elastic column settling under gravity (2D or 3D), coarse. */
  std::string
  column(const unsigned int dim, const std::string &method)
  {
    std::ostringstream s;
    const std::string  zero = dim == 2 ? "0, " : "0, 0, ";
    s << "set Dimension = " << dim << "\nset Effects = gravity\n"
      << "subsection Grid\n set Lower corner = " << zero << "0\n"
      << " set Upper corner = " << (dim == 2 ? "0.4, 1.2" : "0.4, 0.4, 1.2")
      << "\n set Cells = " << (dim == 2 ? "4, 12" : "4, 4, 12")
      << "\n set Boundary conditions = 0: slip, 1: slip, 2: slip, 3: slip"
      << (dim == 2 ? "" : ", 4: slip, 5: slip") << "\nend\n"
      << "subsection Material 1\n set Model = linear elastic\n"
      << " set Density = 1000\n subsection linear elastic\n"
      << "  set Young's modulus = 1e6\n  set Poisson's ratio = 0.45\n end\n"
      << "end\n"
      << "subsection Body 1\n set Shape = box\n set Lower corner = " << zero
      << "0\n set Upper corner = " << (dim == 2 ? "0.4, 0.9" : "0.4, 0.4, 0.9")
      << "\n set Velocity = " << (dim == 2 ? "0.3, -0.5" : "0.3, 0.1, -0.5")
      << "\nend\n"
      << "subsection Gravity\n set Acceleration = " << zero << "-9.81\nend\n"
      << "subsection MPM\n"
      << method << "end\n";
    return s.str();
  }

  /** Four blocks meeting in the middle of a cell, each moving another
   * way: at the first step the cells where they meet deform unevenly,
   * each body's particles apart. */
  std::string
  four_blocks(const std::string &method)
  {
    std::ostringstream s;
    s << "set Dimension = 2\nset Number of bodies = 4\n"
      << "subsection Grid\n set Lower corner = 0, 0\n"
      << " set Upper corner = 1, 1\n set Cells = 10, 10\nend\n"
      << "subsection Material 1\n set Model = linear elastic\n"
      << " set Density = 1000\n subsection linear elastic\n"
      << "  set Young's modulus = 1e6\n  set Poisson's ratio = 0.45\n end\n"
      << "end\n";
    const char *lower[4]    = {"0.12, 0.12",
                               "0.53, 0.12",
                               "0.12, 0.53",
                               "0.53, 0.53"};
    const char *upper[4]    = {"0.53, 0.53",
                               "0.88, 0.53",
                               "0.53, 0.88",
                               "0.88, 0.88"};
    const char *velocity[4] = {"1, 0.6", "-0.7, 1", "0.8, -1", "-1, -0.9"};
    for (unsigned int b = 0; b < 4; ++b)
      s << "subsection Body " << b + 1 << "\n set Shape = box\n"
        << " set Lower corner = " << lower[b]
        << "\n set Upper corner = " << upper[b]
        << "\n set Material = 1\n set Velocity = " << velocity[b] << "\nend\n";
    s << "subsection MPM\n" << method << "end\n";
    return s.str();
  }
} // namespace

TEST(FBar, OneVolumeChangePerCellLinear2dMusl)
{
  check_one_volume_change<2>(column(2, ""));
}

TEST(FBar, OneVolumeChangePerCellLinear2dUsl)
{
  check_one_volume_change<2>(column(2, " set Stress update = USL\n"));
}

TEST(FBar, OneVolumeChangePerCellGimp2dUsf)
{
  check_one_volume_change<2>(
    column(2, " set Stress update = USF\n set Shape function = uGIMP\n"));
}

TEST(FBar, OneVolumeChangePerCellCpdi2dMusl)
{
  check_one_volume_change<2>(column(2, " set Shape function = CPDI\n"));
}

TEST(FBar, OneVolumeChangePerCellBspline2dUsl)
{
  check_one_volume_change<2>(column(
    2, " set Stress update = USL\n set Shape function = quadratic B-spline\n"));
}

TEST(FBar, OneVolumeChangePerCellLinear3dMusl)
{
  check_one_volume_change<3>(column(3, ""));
}

TEST(FBar, KeepsEachBodysCellVolumeAndEachShapeChange)
{
  for (const std::string method : {"",
                                   " set Stress update = USL\n",
                                   " set Stress update = USF\n",
                                   " set Shape function = cpGIMP\n"})
    {
      SCOPED_TRACE(method);
      check_against_none<2>(four_blocks(method), 4);
    }
}

// On an adapted grid: the column's cells refined once (the particles
// criterion, adapted every 5 steps as it settles), the empty cells above
// left coarse, so that the refined cells at the surface have hanging
// nodes. A cell is a cell: its particles share one volume rate.
TEST(FBar, OneVolumeChangePerCellOnAnAdaptedGrid)
{
  const std::string scene = column(2, "") +
                            "subsection Adaptivity\n set Criteria = particles\n"
                            " set Maximum level = 1\n"
                            " set Steps between adaptations = 5\nend\n";
  // Refined where the column is, coarse above it: between 48 and 192
  // cells.
  auto simulation = test::make_simulation<2>(scene);
  for (unsigned int step = 0; step < 20; ++step)
    simulation->advance(simulation->time_step());
  const auto cells =
    simulation->background_grid().triangulation.n_global_active_cells();
  std::cout << "F-bar on an adapted grid: " << cells << " cells" << std::endl;
  EXPECT_GT(cells, 48u);
  EXPECT_LT(cells, 192u);
  check_one_volume_change<2>(scene);
}
