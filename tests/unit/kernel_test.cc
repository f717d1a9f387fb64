// Every shape function at random particle positions: partition of unity,
// zero gradient sum, reproduction of linear fields (sum N_i x_i = x_p and
// sum x_i (x) grad N_i = I), on uniform grids and, where the kernel allows,
// next to hanging nodes and in distorted cells; gradients against finite
// differences; the quadratic B-spline against its closed form and its
// refusal of refined grids; the weights on uniform patches' lattices
// against the general path.
#include <dealmpm/base/errors.h>
#include <dealmpm/transfer/kernel.h>
#include <dealmpm/transfer/lattice_blocks.h>
#include <dealmpm/transfer/quadratic_bspline.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  template <int dim>
  std::string
  box_scene(const std::string &kernel, const bool refined)
  {
    const std::string lower = dim == 2 ? "0, 0" : "0, 0, 0";
    const std::string half  = dim == 2 ? "0.5, 0.5" : "0.5, 0.5, 0.5";
    const std::string upper = dim == 2 ? "1, 1" : "1, 1, 1";
    std::string       scene = "set Dimension = " + std::to_string(dim) +
                        "\nsubsection Grid\n set Lower corner = " + lower +
                        "\n set Upper corner = " + upper +
                        "\n set Cells = " + (dim == 2 ? "5, 4" : "3, 4, 3") +
                        "\n";
    if (refined)
      scene += " subsection Local refinement\n  set Levels = 1\n"
               "  set Lower corner = " +
               lower + "\n  set Upper corner = " + half + "\n end\n";
    return scene + "end\nsubsection Body 1\n set Shape = box\n" +
           " set Lower corner = " + lower + "\n set Upper corner = " + upper +
           "\n set Particles per cell = 2\nend\n"
           "subsection MPM\n set Shape function = " +
           kernel + "\nend\n";
  }

  /** Give every particle a random deformation gradient near I (CPDI and
   * cpGIMP domains then stretch, shear and rotate). */
  template <int dim>
  void
  deform_particles(Simulation<dim> &simulation, std::mt19937 &rng)
  {
    std::uniform_real_distribution<double> perturbation(-0.3, 0.3);
    ParticleSet<dim> &particles = simulation.particle_set();
    for (auto &p : particles.handler)
      {
        Tensor<2, dim> F = unit_symmetric_tensor<dim>();
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            F[a][b] += perturbation(rng);
        write_tensor<dim>(
          &p.get_properties()[particles.fields.deformation_gradient], F);
      }
  }

  /** Whether particle p's (GIMP) domain lies inside the grid: only then is
   * its covered volume centred on it. */
  template <int dim, typename Particle>
  bool
  domain_inside(Simulation<dim> &simulation, const Particle &p)
  {
    const auto &box    = simulation.background_grid().bounding_box;
    const auto  f      = simulation.get_kernel().name();
    const auto &fields = simulation.particle_set().fields;
    for (unsigned int d = 0; d < dim; ++d)
      {
        double l = p.get_properties()[fields.domain_half_length + d];
        if (f == "cpGIMP")
          l *= p.get_properties()[fields.deformation_gradient + d * dim + d];
        if (p.get_location()[d] - l < box.get_boundary_points().first[d] ||
            p.get_location()[d] + l > box.get_boundary_points().second[d])
          return false;
      }
    return true;
  }

  template <int dim>
  void
  check_kernel(const std::string &kernel,
               const bool         refined,
               const bool         deformed,
               const std::string &scene = "")
  {
    auto simulation = test::make_simulation<dim>(
      scene.empty() ? box_scene<dim>(kernel, refined) : scene);
    std::mt19937 rng(17);
    test::scatter_particles_in_cells(*simulation, rng);
    if (deformed)
      deform_particles(*simulation, rng);
    const auto       &grid = simulation->background_grid();
    const std::string kind = simulation->get_kernel().name();
    ASSERT_EQ(kind, kernel);

    Stencil<dim> stencil;
    simulation->get_kernel().compute_stencil(grid,
                                             simulation->particle_set(),
                                             stencil);
    ASSERT_FALSE(stencil.failed) << stencil.failure;
    const bool  gimp = kind == "uGIMP" || kind == "cpGIMP";
    std::size_t k = 0, n_checked_linear = 0;
    for (const auto &c : grid.cells)
      for (const auto &p :
           simulation->particle_set().handler.particles_in_cell(c.cell))
        {
          double         sum = 0, scale = 0;
          Tensor<1, dim> gradient_sum;
          Point<dim>     x;
          Tensor<2, dim> x_grad;
          for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
            {
              const Point<dim> &x_i = grid.node_positions[stencil.node[e]];
              sum += stencil.N[e];
              gradient_sum += stencil.grad_N[e];
              scale = std::max(scale, stencil.grad_N[e].norm());
              x += stencil.N[e] * x_i;
              x_grad += outer_product(x_i, stencil.grad_N[e]);
              if (kind != "CPDI") // CPDI may extrapolate
                {
                  EXPECT_GE(stencil.N[e], -1e-14);
                }
            }
          EXPECT_NEAR(sum, 1., 1e-13);
          EXPECT_LT(gradient_sum.norm(), 1e-12 * scale);
          if (!gimp || domain_inside(*simulation, p))
            {
              ++n_checked_linear;
              EXPECT_LT(x.distance(p.get_location()), 1e-13)
                << kernel << " at " << p.get_location();
              EXPECT_LT((x_grad - unit_symmetric_tensor<dim>()).norm(), 1e-12)
                << kernel << " at " << p.get_location();
            }
          ++k;
        }
    EXPECT_EQ(k,
              simulation->particle_set().handler.n_locally_owned_particles());
    EXPECT_GT(n_checked_linear, k / 4);
  }
} // namespace

TEST(Kernel, AllKernelsOnUniformGrid2D)
{
  for (const std::string kernel :
       {"linear", "uGIMP", "cpGIMP", "CPDI", "quadratic B-spline"})
    check_kernel<2>(kernel, false, false);
}

TEST(Kernel, AllKernelsOnUniformGrid3D)
{
  for (const std::string kernel :
       {"linear", "uGIMP", "cpGIMP", "CPDI", "quadratic B-spline"})
    check_kernel<3>(kernel, false, false);
}

TEST(Kernel, DeformedDomains)
{
  for (const std::string kernel : {"cpGIMP", "CPDI"})
    {
      check_kernel<2>(kernel, false, true);
      check_kernel<3>(kernel, false, true);
    }
}

TEST(Kernel, NextToHangingNodes)
{
  for (const std::string kernel : {"linear", "uGIMP", "cpGIMP", "CPDI"})
    check_kernel<2>(kernel, true, kernel == "CPDI");
  check_kernel<3>("CPDI", true, true);
}

TEST(Kernel, CPDIOnDistortedCells)
{
  check_kernel<2>(
    "CPDI",
    false,
    true,
    "subsection Grid\n set Type = mesh file\n set Mesh file = " DEALMPM_SOURCE_DIR
    "/tests/data/distorted_square.msh\n set Global refinements = 2\nend\n"
    "subsection Body 1\n set Particles per cell = 2\nend\n"
    "subsection MPM\n set Shape function = CPDI\nend\n");
}

namespace
{
  /** grad N against central differences of N in the particle position,
   * for kernels whose gradient is the derivative of the weight. */
  void
  check_gradient_is_derivative(const std::string &kernel)
  {
    auto  simulation = test::make_simulation<2>(box_scene<2>(kernel, false));
    auto &grid       = simulation->background_grid();
    std::mt19937                           rng(23);
    std::uniform_real_distribution<double> unit(0.1, 0.9);
    auto &handler = simulation->particle_set().handler;
    for (const auto &c : grid.cells)
      for (auto &p : handler.particles_in_cell(c.cell))
        {
          const Point<2> xi(unit(rng), unit(rng));
          p.set_reference_location(xi);
          p.set_location(c.real_point(xi));
        }
    const double eps     = 1e-6;
    const auto   weights = [&](const Tensor<1, 2> &shift) {
      for (const auto &c : grid.cells)
        for (auto &p : handler.particles_in_cell(c.cell))
          {
            const Point<2> x = p.get_location() + shift;
            p.set_location(x);
            p.set_reference_location(c.reference_point(x));
          }
      Stencil<2> stencil;
      simulation->get_kernel().compute_stencil(grid,
                                               simulation->particle_set(),
                                               stencil);
      return stencil;
    };
    const Stencil<2> centre = weights(Tensor<1, 2>());
    for (unsigned int d = 0; d < 2; ++d)
      {
        Tensor<1, 2> shift;
        shift[d]               = eps;
        const Stencil<2> plus  = weights(shift);
        const Stencil<2> minus = weights(-2. * shift);
        weights(shift);
        const auto value = [](const Stencil<2> &s, std::size_t k, unsigned n) {
          for (unsigned int e = s.begin[k]; e < s.begin[k + 1]; ++e)
            if (s.node[e] == n)
              return s.N[e];
          return 0.;
        };
        // GIMP domains cut by the boundary are renormalised: their weights'
        // derivative is not the mean gradient, so only whole domains count.
        std::size_t k = 0, n_checked = 0;
        for (const auto &c : grid.cells)
          for (const auto &p : handler.particles_in_cell(c.cell))
            {
              if (kernel != "uGIMP" || domain_inside(*simulation, p))
                for (unsigned int e = centre.begin[k]; e < centre.begin[k + 1];
                     ++e)
                  {
                    ++n_checked;
                    const double derivative =
                      (value(plus, k, centre.node[e]) -
                       value(minus, k, centre.node[e])) /
                      (2 * eps);
                    EXPECT_NEAR(centre.grad_N[e][d], derivative, 1e-6)
                      << kernel << " at " << p.get_location();
                  }
              ++k;
            }
        EXPECT_GT(n_checked, centre.n_particles());
      }
  }
} // namespace

TEST(Kernel, GradientIsDerivativeOfWeight)
{
  for (const std::string kernel : {"linear", "uGIMP", "quadratic B-spline"})
    check_gradient_is_derivative(kernel);
}

TEST(Kernel, QuadraticBSplineClosedForm)
{
  // The tensor product of the 1D quadratic B-splines centred on the nodes,
  // and of linear hats within h/2 of the boundary, written out here.
  auto simulation =
    test::make_simulation<2>(box_scene<2>("quadratic B-spline", false));
  const auto  &grid    = simulation->background_grid();
  auto        &handler = simulation->particle_set().handler;
  const double hx = 1. / 5, hy = 1. / 4;
  for (const auto &c : grid.cells)
    for (auto &p : handler.particles_in_cell(c.cell))
      {
        const Point<2> x = c.origin + Tensor<1, 2>({0.3 * hx, 0.001});
        p.set_location(x);
        p.set_reference_location(c.reference_point(x));
      }
  Stencil<2> stencil;
  simulation->get_kernel().compute_stencil(grid,
                                           simulation->particle_set(),
                                           stencil);
  std::size_t k = 0;
  for (const auto &c : grid.cells)
    for (const auto &p : handler.particles_in_cell(c.cell))
      {
        const double t = p.get_location()[0] / hx;
        const double s = p.get_location()[1] / hy;
        // 1D weights of the closed form, along x (interior or boundary) and
        // y (each particle sits 0.001 above a node row).
        const auto bspline = [](const double r) {
          const double a = std::abs(r);
          return a < 0.5 ? 0.75 - r * r :
                           (a < 1.5 ? 0.5 * (1.5 - a) * (1.5 - a) : 0.);
        };
        const auto weight_1d = [&](const double u, const int j, const int n) {
          if (u < 0.5 || u >= n - 0.5)
            return std::max(0., 1. - std::abs(u - j));
          return bspline(u - j);
        };
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          {
            const Point<2> &x_i = grid.node_positions[stencil.node[e]];
            const double    expected =
              weight_1d(t, int(std::round(x_i[0] / hx)), 5) *
              weight_1d(s, int(std::round(x_i[1] / hy)), 4);
            EXPECT_NEAR(stencil.N[e], expected, 1e-14);
          }
        ++k;
      }
}

TEST(Kernel, QuadraticBSplineWindowsAreTheSameInEveryCell)
{
  // A particle's weights depend on where it is in its cell, not on which
  // cell: millions of cells from the origin they are those of the same
  // point in the second cell, to the last bit, and in the half cell next to
  // the far boundary the two hats are 1 - s and s exactly. (Computed from
  // the grid coordinate J + s they lost the low bits of s there.)
  constexpr int           n = 1 << 22;
  QuadraticBSplineGrid<2> spline;
  spline.inverse_h   = Tensor<1, 2>({3., 5.});
  spline.n_cells     = {{n, 8}};
  spline.lower_index = {{{1, 3}}, {{n - 1000, 3}}, {{n - 1, 3}}};
  for (const double s : {1e-3, 0.1234567, 0.4999, 0.5, 0.7654321, 0.999})
    {
      const Point<2> xi(s, 0.3);
      NodeWindow     near[2], far[2], last[2];
      spline.windows_at(0, xi, near);
      spline.windows_at(1, xi, far);
      spline.windows_at(2, xi, last);
      for (unsigned int d = 0; d < 2; ++d)
        {
          EXPECT_EQ(near[d].first, far[d].first) << s;
          EXPECT_EQ(near[d].padded, far[d].padded) << s;
          for (unsigned int k = 0; k < 3; ++k)
            {
              EXPECT_EQ(near[d].value[k], far[d].value[k]) << s;
              EXPECT_EQ(near[d].slope[k], far[d].slope[k]) << s;
            }
        }
      if (s >= 0.5)
        {
          // Nodes J and J + 1 at window positions 1 and 2.
          EXPECT_EQ(last[0].first, 0u) << s;
          EXPECT_EQ(last[0].value[0], 0.) << s;
          EXPECT_EQ(last[0].value[1], 1. - s) << s;
          EXPECT_EQ(last[0].value[2], s) << s;
        }
    }
}

TEST(Kernel, QuadraticBSplineRefusesRefinedGrid)
{
  try
    {
      test::make_simulation<2>(box_scene<2>("quadratic B-spline", true));
      FAIL() << "a grid with hanging nodes was accepted";
    }
  catch (const InputError &error)
    {
      EXPECT_NE(std::string(error.what()).find("hanging nodes"),
                std::string::npos)
        << error.what();
    }
}

namespace
{
  /** Particle k's entries (node -> N, grad N) of @p stencil. */
  template <int dim>
  std::map<unsigned int, std::pair<double, Tensor<1, dim>>>
  entries_of(const Stencil<dim> &stencil, const std::size_t k)
  {
    std::map<unsigned int, std::pair<double, Tensor<1, dim>>> entries;
    for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
      entries[stencil.node[e]] = {stencil.N[e], stencil.grad_N[e]};
    return entries;
  }

  /** How many CPDI domains (half-edges F e_d l_d) lie inside their
   * particle's cell, away from its faces. */
  template <int dim>
  unsigned int
  count_cpdi_domains_in_their_cells(const ParticleSet<dim> &particles)
  {
    unsigned int n_inside = 0;
    for (const auto &p : particles.handler)
      {
        const auto cell  = p.get_surrounding_cell();
        const auto lower = cell->vertex(0);
        const auto upper = cell->vertex(cell->n_vertices() - 1);
        const auto props = p.get_properties();
        const auto F =
          read_tensor<dim>(&props[particles.fields.deformation_gradient]);
        bool inside = true;
        for (unsigned int d = 0; d < dim; ++d)
          {
            double reach = 0;
            for (unsigned int j = 0; j < dim; ++j)
              reach += std::abs(F[d][j] *
                                props[particles.fields.domain_half_length + j]);
            inside = inside && p.get_location()[d] - reach > lower[d] &&
                     p.get_location()[d] + reach < upper[d];
          }
        n_inside += inside;
      }
    return n_inside;
  }

  /**
   * GIMP and CPDI weights on the lattices of uniform patches (products of
   * 1D weights, sums by lattice node) against the general path (per-cell
   * integrals or corners gathered node by node), on a grid with a refined
   * corner (cells next to hanging nodes have no lattice) and random
   * deformations; every fifth particle's domain is grown to reach past its
   * patch, so that the fall-back is taken too. The two compute the same
   * sums in another order: equal to round-off. CPDI domains inside their
   * own cell take the closed form of the corners' sums on the lattice
   * path; the test counts that some do.
   */
  template <int dim>
  void
  check_lattice_path(const std::string &kernel)
  {
    const std::string lower      = dim == 2 ? "0, 0" : "0, 0, 0";
    const std::string upper      = dim == 2 ? "1, 1" : "1, 1, 1";
    const std::string part       = dim == 2 ? "0.3, 0.3" : "0.4, 0.4, 0.4";
    auto              simulation = test::make_simulation<dim>(
      "set Dimension = " + std::to_string(dim) +
      "\nsubsection Grid\n set Lower corner = " + lower +
      "\n set Upper corner = " + upper +
      "\n set Cells = " + (dim == 2 ? "9, 8" : "5, 6, 5") +
      "\n subsection Local refinement\n  set Levels = 1\n"
                   "  set Lower corner = " +
      lower + "\n  set Upper corner = " + part +
      "\n end\nend\nsubsection Body 1\n set Shape = box\n"
                   " set Lower corner = " +
      lower + "\n set Upper corner = " + upper +
      "\n set Particles per cell = 2\nend\n"
                   "subsection MPM\n set Shape function = " +
      kernel + "\nend\n");
    std::mt19937 rng(23);
    test::scatter_particles_in_cells(*simulation, rng);
    deform_particles(*simulation, rng);
    ParticleSet<dim> &particles = simulation->particle_set();
    unsigned int      n         = 0;
    for (auto &p : particles.handler)
      if (++n % 5 == 0)
        for (unsigned int d = 0; d < dim; ++d)
          p.get_properties()[particles.fields.domain_half_length + d] *= 3.;
    if (kernel == "CPDI")
      {
        EXPECT_GE(count_cpdi_domains_in_their_cells(particles), 10u);
      }
    const BackgroundGrid<dim> &grid = simulation->background_grid();
    LatticeBlocks<dim>         lattice;
    lattice.setup(grid);
    unsigned int n_with_lattice = 0;
    for (unsigned int i = 0; i < grid.cells.size(); ++i)
      n_with_lattice += lattice.of(i) != nullptr;
    EXPECT_GT(n_with_lattice, grid.cells.size() / 10);
    EXPECT_LT(n_with_lattice, grid.cells.size());

    Stencil<dim> general, on_lattice;
    const auto   compute = [&](Stencil<dim>             &stencil,
                             const LatticeBlocks<dim> *blocks) {
      if (kernel == "CPDI")
        compute_cpdi_stencil(grid, particles, stencil, blocks);
      else
        compute_gimp_stencil(
          grid, particles, kernel == "cpGIMP", stencil, blocks);
    };
    compute(general, nullptr);
    compute(on_lattice, &lattice);
    ASSERT_EQ(general.n_particles(), on_lattice.n_particles());
    for (std::size_t k = 0; k < general.n_particles(); ++k)
      {
        const auto a = entries_of(general, k), b = entries_of(on_lattice, k);
        ASSERT_EQ(a.size(), b.size()) << kernel << " particle " << k;
        double scale = 0;
        for (const auto &[node, value] : a)
          scale = std::max(scale, value.second.norm());
        for (const auto &[node, value] : a)
          {
            ASSERT_EQ(b.count(node), 1u) << kernel << " particle " << k;
            EXPECT_NEAR(b.at(node).first, value.first, 1e-14) << kernel;
            EXPECT_LT((b.at(node).second - value.second).norm(), 1e-14 * scale)
              << kernel << " particle " << k << " node " << node;
          }
      }
  }
} // namespace

TEST(Kernel, LatticePathEqualsGeneralPath)
{
  for (const std::string kernel : {"uGIMP", "cpGIMP", "CPDI"})
    {
      check_lattice_path<2>(kernel);
      check_lattice_path<3>(kernel);
    }
}

namespace
{
  /**
   * CPDI domains at rest that fill a part of their cell exactly (two
   * particles per cell and direction: each domain is a quarter (2D) or an
   * eighth (3D) of its cell, its corners on the cell's faces): only the
   * 2^dim nodes of the particle's own cell carry weight, so the stencil
   * lists those and no neighbour's nodes with zero weight, on the lattice
   * path and on the general path alike. Cell sizes 1/5 and 1/3 are not
   * binary fractions, so corners land on the faces only to round-off.
   */
  template <int dim>
  void
  check_cpdi_domains_in_their_cells(const bool with_lattice)
  {
    std::string scene = box_scene<dim>("CPDI", false);
    // Cells of 1/5 by 1/3 (by 1/5): a refined corner would leave some
    // cells without a lattice, so none is refined here.
    const std::string cells = dim == 2 ? "5, 3" : "5, 3, 5";
    scene.replace(scene.find(dim == 2 ? "5, 4" : "3, 4, 3"),
                  cells.size(),
                  cells);
    auto               simulation = test::make_simulation<dim>(scene);
    const auto        &grid       = simulation->background_grid();
    ParticleSet<dim>  &particles  = simulation->particle_set();
    LatticeBlocks<dim> lattice;
    lattice.setup(grid);
    Stencil<dim> stencil;
    compute_cpdi_stencil(grid,
                         particles,
                         stencil,
                         with_lattice ? &lattice : nullptr);
    ASSERT_FALSE(stencil.failed) << stencil.failure;
    ASSERT_EQ(stencil.n_particles(),
              particles.handler.n_locally_owned_particles());
    ASSERT_EQ(stencil.n_particles(), grid.cells.size() * (1u << dim));
    for (std::size_t k = 0; k < stencil.n_particles(); ++k)
      {
        ASSERT_EQ(stencil.begin[k + 1] - stencil.begin[k], 1u << dim)
          << "particle " << k;
        double sum = 0;
        for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
          {
            // The smallest weight of such a domain is (1/4)^dim.
            EXPECT_GT(stencil.N[e], 0.9 / Utilities::pow(4, dim));
            sum += stencil.N[e];
          }
        EXPECT_NEAR(sum, 1., 1e-13);
      }
  }
} // namespace

TEST(Kernel, CPDIDomainsAtRestUseOnlyTheirCellsNodes)
{
  for (const bool with_lattice : {true, false})
    {
      check_cpdi_domains_in_their_cells<2>(with_lattice);
      check_cpdi_domains_in_their_cells<3>(with_lattice);
    }
}
