// What a user can add from C++ without touching the library: an effect that
// declares a particle field and a per-body nodal field, a shape function and
// a boundary condition. A scene that does not name them pays nothing.
#include <deal.II/base/mpi.h>

#include <dealmpm/transfer/stencil_order.h>

#include <gtest/gtest.h>

#include <cmath>

#include "test_scene.h"

using namespace dealmpm;

namespace
{
  /** Spreads each body's mass to its own nodal field, and counts the steps
   * in a particle field of its own; adds no force. */
  class BodyMassEffect : public Effect<2>
  {
  public:
    std::vector<FieldDescription>
    particle_fields() const override
    {
      return {{"visits", 1}};
    }

    std::vector<FieldDescription>
    nodal_fields_per_body() const override
    {
      return {{"body mass", 1}};
    }

    void
    add_nodal_forces(const EffectContext<2> &state, NodalFields<2> &) override
    {
      const ParticleSet<2> &particles = state.particles;
      const unsigned int    n_bodies  = 2;
      for (unsigned int b = 0; b < n_bodies; ++b)
        state.field_set.per_body("body mass", b, 0) = 0;
      for_each_particle_in_stencil_order(
        state.grid,
        particles,
        [&](const std::size_t k, const auto &p, const GridCell<2> &) {
          const auto   props = p.get_properties();
          NodalVector &mass =
            state.field_set.per_body("body mass", particles.body_of(props), 0);
          for (unsigned int e = state.stencil.begin[k];
               e < state.stencil.begin[k + 1];
               ++e)
            mass.local_element(state.stencil.node[e]) +=
              state.stencil.N[e] * props[particles.fields.mass];
        });
      for (unsigned int b = 0; b < n_bodies; ++b)
        state.field_set.per_body("body mass", b, 0)
          .compress(VectorOperation::add);
    }

    /** The particles are writable here: count this step on each. */
    void
    after_g2p(const EffectContext<2> &, ParticleSet<2> &particles) override
    {
      const unsigned int visits = particles.layout.offset("visits");
      for (auto &p : particles.handler)
        p.get_properties()[visits] += 1;
    }
  };

  /** The grid's Q1 functions under another name, counting its calls. */
  unsigned int n_stencils = 0;
  class CountingLinear : public ShapeFunction<2>
  {
  public:
    std::string
    setup(BackgroundGrid<2> &) override
    {
      return "";
    }
    void
    compute_stencil(const BackgroundGrid<2> &grid,
                    const ParticleSet<2>    &particles,
                    Stencil<2>              &stencil) const override
    {
      ++n_stencils;
      compute_linear_stencil(grid, particles, stencil);
    }
  };

  /** A roller: the x velocity is removed, whatever the wall's normal. */
  class FixedX : public BoundaryCondition<2>
  {
  public:
    std::vector<Tensor<1, 2>>
    removed_directions(const Tensor<1, 2> &) const override
    {
      return {Tensor<1, 2>({1., 0.})};
    }
  };

  void
  register_test_parts()
  {
    effect_registry<2>().add(
      "body mass",
      "test: each body's mass on its own nodal field.",
      [](ParameterHandler &) {},
      [](SceneReader &) { return std::make_unique<BodyMassEffect>(); });
    shape_function_registry<2>().add(
      "counting linear", "test: linear, counted.", [] {
        return std::make_unique<CountingLinear>();
      });
    boundary_condition_registry<2>().add("fixed x", "test: a roller.", [] {
      return std::make_unique<FixedX>();
    });
  }

  std::string
  two_bodies(const std::string &extra)
  {
    return "set Effects = gravity" + extra +
           "\nsubsection Grid\n set Cells = 8, 8\n"
           " set Boundary conditions = 2: no-slip\nend\n"
           "subsection Body 1\n set Lower corner = 0.1, 0.1\n"
           " set Upper corner = 0.4, 0.5\n set Velocity = 1, 0\nend\n"
           "subsection Body 2\n set Lower corner = 0.6, 0.3\n"
           " set Upper corner = 0.9, 0.6\nend\n";
  }

  double
  body_mass(Simulation<2> &simulation, const unsigned int b)
  {
    const ParticleSet<2> &particles = simulation.particle_set();
    double                mass      = 0;
    for (const auto &p : particles.handler)
      if (particles.body_of(p.get_properties()) == b)
        mass += p.get_properties()[particles.fields.mass];
    return Utilities::MPI::sum(mass, MPI_COMM_WORLD);
  }

  /** The same run up to the order of sums: a scene whose parts read the
   * stored weights and one whose P2G computes them where used and sums a
   * cell's particles first differ at round-off, 1e-12 of the energy and
   * of the momentum m |v| (a wrong weight or field is O(1) off). */
  void
  expect_same_statistics(const Statistics &a, const Statistics &b)
  {
    const double energy = std::abs(a.kinetic_energy) +
                          std::abs(a.strain_energy) +
                          std::abs(a.gravitational_energy);
    const double momentum = std::sqrt(2. * a.kinetic_energy * a.mass);
    ASSERT_GT(momentum, 0.);
    EXPECT_NEAR(a.kinetic_energy, b.kinetic_energy, 1e-12 * energy);
    EXPECT_NEAR(a.strain_energy, b.strain_energy, 1e-12 * energy);
    EXPECT_NEAR(a.gravitational_energy, b.gravitational_energy, 1e-12 * energy);
    for (unsigned int d = 0; d < 2; ++d)
      EXPECT_NEAR(a.momentum[d], b.momentum[d], 1e-12 * momentum);
  }
} // namespace

TEST(Extension, EffectDeclaresParticleAndPerBodyNodalFields)
{
  register_test_parts();
  auto plain = test::make_simulation<2>(two_bodies(""), 2);
  auto with  = test::make_simulation<2>(two_bodies(", body mass"), 2);

  EXPECT_FALSE(plain->particle_set().layout.has("visits"));
  ASSERT_TRUE(with->particle_set().layout.has("visits"));
  EXPECT_EQ(with->particle_set().layout.size(),
            plain->particle_set().layout.size() + 1);
  EXPECT_FALSE(plain->nodal_field_set().has("body mass"));
  EXPECT_EQ(plain->nodal_field_set().n_vectors(), 1u + 4 * 2);
  EXPECT_EQ(with->nodal_field_set().n_vectors(), 1u + 4 * 2 + 2);

  for (unsigned int i = 0; i < 5; ++i)
    {
      plain->advance(1e-3);
      with->advance(1e-3);
    }
  expect_same_statistics(plain->statistics(), with->statistics());

  // Each body's field holds its mass (the weights sum to one), and every
  // particle was counted once per step.
  const NodalFieldSet<2> &set = with->nodal_field_set();
  for (unsigned int b = 0; b < 2; ++b)
    {
      const double total = set.per_body("body mass", b, 0).l1_norm();
      EXPECT_NEAR(total, body_mass(*with, b), 1e-12 * total);
      EXPECT_GT(total, 0.);
    }
  const ParticleSet<2> &particles = with->particle_set();
  const unsigned int    visits    = particles.layout.offset("visits");
  for (const auto &p : particles.handler)
    EXPECT_EQ(p.get_properties()[visits], 5.);
}

TEST(Extension, RegisteredShapeFunctionAndBoundaryCondition)
{
  register_test_parts();
  auto linear = test::make_simulation<2>(two_bodies(""), 2);
  auto counted =
    test::make_simulation<2>(two_bodies(
                               "\nsubsection MPM\n set Shape function = "
                               "counting linear\nend"),
                             2);
  EXPECT_EQ(counted->get_kernel().name(), "counting linear");
  n_stencils = 0;
  for (unsigned int i = 0; i < 5; ++i)
    {
      linear->advance(1e-3);
      counted->advance(1e-3);
    }
  EXPECT_GE(n_stencils, 5u);
  expect_same_statistics(linear->statistics(), counted->statistics());

  // A block thrown into the corner: on the left wall (id 0, normal x) the
  // roller is slip; on the floor (id 2, normal y) it stops the x motion of
  // the floor's nodes where slip stops their y motion.
  const auto walls = [](const std::string &conditions) {
    return "set Effects = gravity\nsubsection Grid\n set Cells = 8, 8\n"
           " set Boundary conditions = " +
           conditions +
           "\nend\nsubsection Body 1\n set Lower corner = 0, 0\n"
           " set Upper corner = 0.5, 0.5\n set Velocity = -1, -1\nend\n";
  };
  auto roller_left  = test::make_simulation<2>(walls("0: fixed x"));
  auto slip_left    = test::make_simulation<2>(walls("0: slip"));
  auto roller_floor = test::make_simulation<2>(walls("2: fixed x"));
  auto slip_floor   = test::make_simulation<2>(walls("2: slip"));
  for (unsigned int i = 0; i < 5; ++i)
    for (auto *s : {&roller_left, &slip_left, &roller_floor, &slip_floor})
      (*s)->advance(1e-3);
  expect_same_statistics(roller_left->statistics(), slip_left->statistics());
  const Statistics roller = roller_floor->statistics();
  const Statistics slip   = slip_floor->statistics();
  EXPECT_LT(std::abs(roller.momentum[0]), 0.95 * std::abs(slip.momentum[0]));
  EXPECT_GT(std::abs(roller.momentum[1]), 1.05 * std::abs(slip.momentum[1]));
}
