#include <dealmpm/effects/frictional_contact.h>
#include <dealmpm/grid/grid_update.h>
#include <dealmpm/grid/nodal_exchange.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace dealmpm
{
  template <int dim>
  void
  FrictionalContact<dim>::setup(const EffectSetup<dim> &setup,
                                SceneReader            &reader)
  {
    conditions = &setup.conditions;
    grid_changed(setup.grid);
    for (const auto &item : pair_friction)
      if (item.first.second >= setup.n_bodies)
        reader.fail("Pair friction coefficients",
                    "pairs of body numbers from 1 to " +
                      std::to_string(setup.n_bodies) +
                      " ('Number of bodies'), not " +
                      std::to_string(item.first.second + 1));
  }

  template <int dim>
  void
  FrictionalContact<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    if (!(separation_check > 0))
      return;
    // integral N_i dx: each cell gives each vertex its measure / 2^dim
    // (exact on parallelograms), passed on to the effective nodes.
    full_volume.reinit(grid.partitioner);
    constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
    for (const GridCell<dim> &c : grid.cells)
      for (unsigned int j = 0; j < c.n_nodes; ++j)
        {
          double share = 0;
          for (unsigned int v = 0; v < n_vertices; ++v)
            share +=
              c.first_weight == numbers::invalid_unsigned_int ?
                (v == j ? 1. : 0.) :
                grid.cell_node_weights[c.first_weight + j * n_vertices + v];
          full_volume.local_element(grid.cell_nodes[c.first_node + j]) +=
            share * c.measure / n_vertices;
        }
    full_volume.compress(VectorOperation::add);
  }

  template <int dim>
  void
  FrictionalContact<dim>::add_nodal_forces(const EffectContext<dim> &state,
                                           NodalFields<dim> & /*fields*/)
  {
    if (!(separation_check > 0))
      return;
    NodalFieldSet<dim>        &set      = state.field_set;
    const unsigned int         n_bodies = set.body.size();
    std::vector<NodalVector *> volumes;
    for (unsigned int b = 0; b < n_bodies; ++b)
      {
        volumes.push_back(&set.per_body("contact volume", b, 0));
        *volumes.back() = 0;
      }
    const CoreFields &f = state.particles.fields;
    for_each_particle_in_stencil_order(
      state.grid,
      state.particles,
      [&](const std::size_t k, const auto &p, const GridCell<dim> &) {
        const auto   props  = p.get_properties();
        const double V      = current_volume<dim>(&props[0], f);
        NodalVector &volume = *volumes[state.particles.body_of(props)];
        for (unsigned int e = state.stencil.begin[k];
             e < state.stencil.begin[k + 1];
             ++e)
          volume.local_element(state.stencil.node[e]) += V * state.stencil.N[e];
      });
    for (NodalVector *volume : volumes)
      volume->compress(VectorOperation::add);
  }

  template <int dim>
  double
  FrictionalContact<dim>::coefficient(const unsigned int b,
                                      const unsigned int c) const
  {
    const auto found = pair_friction.find({std::min(b, c), std::max(b, c)});
    return found == pair_friction.end() ? friction : found->second;
  }

  template <int dim>
  void
  FrictionalContact<dim>::after_grid_update(const EffectContext<dim> &state,
                                            NodalFields<dim>         &fields)
  {
    NodalFieldSet<dim> &set       = state.field_set;
    const double        threshold = state.mass_threshold;
    const unsigned int  n_owned   = fields.mass.locally_owned_size();
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const double m = fields.mass.local_element(i);
        // The external forces: what the core force has beyond the bodies'
        // internal ones.
        Tensor<1, dim> external;
        for (unsigned int d = 0; d < dim; ++d)
          {
            external[d] = fields.force[d].local_element(i);
            for (const NodalFields<dim> &body : set.body)
              external[d] -= body.force[d].local_element(i);
          }
        for (NodalFields<dim> &body : set.body)
          {
            const double m_b = body.mass.local_element(i);
            for (unsigned int d = 0; d < dim; ++d)
              {
                double &v  = body.velocity[d].local_element(i);
                double &dv = body.velocity_increment[d].local_element(i);
                if (m_b > threshold)
                  {
                    dv =
                      state.dt *
                      (body.force[d].local_element(i) + m_b / m * external[d]) /
                      m_b;
                    v = body.momentum[d].local_element(i) / m_b + dv;
                  }
                else
                  {
                    // Too light to have a velocity of its own: the node's.
                    v  = fields.velocity[d].local_element(i);
                    dv = fields.velocity_increment[d].local_element(i);
                  }
              }
          }
      }
    for (NodalFields<dim> &body : set.body)
      conditions->project_with_increment(body.velocity,
                                         body.velocity_increment);
    if (state.stable_mass > 0)
      for (NodalFields<dim> &body : set.body)
        set_increment_weights(body, state.stable_mass);
    const auto [taken, by_friction] = correct(set, threshold);
    work += taken;
    friction_part += by_friction;
    NodalExchange ghosts;
    for (NodalFields<dim> &body : set.body)
      ghosts.add(body.velocity).add(body.velocity_increment);
    ghosts.copy_owners_to_ghosts();
  }

  template <int dim>
  void
  FrictionalContact<dim>::after_remap(const EffectContext<dim> &state,
                                      NodalFields<dim>         &fields)
  {
    NodalFieldSet<dim> &set       = state.field_set;
    const double        threshold = state.mass_threshold;
    const unsigned int  n_owned   = fields.mass.locally_owned_size();
    for (NodalFields<dim> &body : set.body)
      {
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const double m_b = body.mass.local_element(i);
            for (unsigned int d = 0; d < dim; ++d)
              body.velocity[d].local_element(i) =
                m_b > threshold ? body.momentum[d].local_element(i) / m_b :
                                  fields.velocity[d].local_element(i);
          }
        conditions->project(body.velocity);
      }
    NodalExchange ghosts;
    for (NodalFields<dim> &body : set.body)
      ghosts.add(body.velocity);
    ghosts.copy_owners_to_ghosts();
  }

  namespace
  {
    /** The bodies with more than @p threshold mass at owned node @p i. */
    template <int dim>
    void
    bodies_at(const NodalFieldSet<dim>  &set,
              const unsigned int         i,
              const double               threshold,
              std::vector<unsigned int> &present)
    {
      present.clear();
      for (unsigned int b = 0; b < set.body.size(); ++b)
        if (set.body[b].mass.local_element(i) > threshold)
          present.push_back(b);
    }

    /** Body @p b's g_b = sum_{p in b} m_p grad N_i(x_p) at owned node @p i. */
    template <int dim>
    Tensor<1, dim>
    gradient_of(const NodalFieldSet<dim> &set,
                const unsigned int        b,
                const unsigned int        i)
    {
      Tensor<1, dim> g;
      for (unsigned int d = 0; d < dim; ++d)
        g[d] = set.mass_gradient[b][d].local_element(i);
      return g;
    }

    /** The other body of @p present that @p b presses on at node @p i: the
     * one with the steepest mass gradient (the fullest surface at the
     * node); and that gradient. */
    template <int dim>
    std::pair<unsigned int, Tensor<1, dim>>
    pressed_body(const NodalFieldSet<dim>        &set,
                 const std::vector<unsigned int> &present,
                 const unsigned int               b,
                 const unsigned int               i)
    {
      unsigned int   other = b;
      Tensor<1, dim> g_other;
      for (const unsigned int c : present)
        if (c != b && (other == b || gradient_of(set, c, i).norm_square() >
                                       g_other.norm_square()))
          {
            other   = c;
            g_other = gradient_of(set, c, i);
          }
      return {other, g_other};
    }
  } // namespace

  template <int dim>
  bool
  FrictionalContact<dim>::filled(
    const std::vector<const NodalVector *> &volumes,
    const std::vector<unsigned int>        &present,
    const unsigned int                      i) const
  {
    if (!(separation_check > 0))
      return true;
    // A gap at the node: the bodies' particles leave part of it
    // empty, and they do not touch there yet.
    double filled = 0;
    for (const unsigned int b : present)
      filled += volumes[b]->local_element(i);
    return !(filled < separation_check * full_volume.local_element(i));
  }

  template <int dim>
  Tensor<1, dim>
  FrictionalContact<dim>::normal_direction(
    const unsigned int    b,
    const Tensor<1, dim> &g_b,
    const unsigned int    other,
    const Tensor<1, dim> &g_other,
    const Tensor<1, dim> &gradient_sum) const
  {
    // sum_p m_p grad N_i(x_p) points from the particles towards
    // the node: out of the body (it is minus the gradient of the
    // nodal mass with respect to the node's position).
    Tensor<1, dim> direction;
    switch (normals)
      {
        case Normals::own_mass_gradient:
          direction = g_b;
          break;
        case Normals::difference_of_bodies:
          direction = 2. * g_b - gradient_sum;
          break;
        case Normals::steepest_mass_gradient:
          // Of the pair, the body whose surface the node sees
          // best gives the normal (the base, at a block's corner
          // sliding on it); ties go to the lower number.
          direction =
            g_b.norm_square() > g_other.norm_square() ||
                (g_b.norm_square() == g_other.norm_square() && b < other) ?
              g_b :
              -g_other;
          break;
      }
    return direction;
  }

  template <int dim>
  void
  FrictionalContact<dim>::correct_body(NodalFields<dim>     &body,
                                       const unsigned int    i,
                                       const Tensor<1, dim> &v_cm,
                                       const Tensor<1, dim> &n,
                                       const unsigned int    b,
                                       const unsigned int    other,
                                       double               &taken,
                                       double               &by_friction) const
  {
    const double   m_b = body.mass.local_element(i);
    Tensor<1, dim> v;
    for (unsigned int d = 0; d < dim; ++d)
      v[d] = body.velocity[d].local_element(i);
    const Tensor<1, dim> relative = v - v_cm;
    const double         approach = relative * n;
    if (!(approach > 0.))
      return;
    const double         mu          = coefficient(b, other);
    const Tensor<1, dim> tangential  = relative - approach * n;
    const double         slip        = tangential.norm();
    Tensor<1, dim>       change      = -approach * n;
    const Tensor<1, dim> normal_only = v + change;
    if (slip > 0.)
      change -= std::min(1., mu * approach / slip) * tangential;
    const Tensor<1, dim> v_new = v + change;
    // The contact force m_b change / dt works on the velocity the
    // particles move with, v_new: the normal parts of a pair cancel
    // (both end at the centre of mass's normal velocity), friction
    // works on the slip that is left. (The kinetic energy the
    // change takes off the node, 1/2 m_b (|v_new|^2 - |v|^2), has
    // an extra -1/2 m_b |change|^2 that FLIP particles do not
    // lose: counted, it made frictionless disks gain 4 % of their
    // energy in the balance while their total energy held.)
    taken += m_b * (change * v_new);
    by_friction += m_b * ((v_new - normal_only) * v_new);
    for (unsigned int d = 0; d < dim; ++d)
      {
        body.velocity[d].local_element(i) = v_new[d];
        body.velocity_increment[d].local_element(i) += change[d];
      }
  }

  template <int dim>
  void
  FrictionalContact<dim>::correct_node(NodalFieldSet<dim>              &set,
                                       const unsigned int               i,
                                       const std::vector<unsigned int> &present,
                                       double                          &taken,
                                       double &by_friction) const
  {
    Tensor<1, dim> v_cm, gradient_sum;
    for (unsigned int d = 0; d < dim; ++d)
      {
        v_cm[d] = set.core.velocity[d].local_element(i);
        for (const unsigned int b : present)
          gradient_sum[d] += set.mass_gradient[b][d].local_element(i);
      }
    for (const unsigned int b : present)
      {
        const auto [other, g_other]    = pressed_body(set, present, b, i);
        const Tensor<1, dim> direction = normal_direction(
          b, gradient_of(set, b, i), other, g_other, gradient_sum);
        if (!(direction.norm() > 0.))
          continue;
        const Tensor<1, dim> n = direction / direction.norm();
        correct_body(set.body[b], i, v_cm, n, b, other, taken, by_friction);
      }
  }

  template <int dim>
  std::pair<double, double>
  FrictionalContact<dim>::correct(NodalFieldSet<dim> &set,
                                  const double        threshold) const
  {
    const unsigned int        n_bodies = set.body.size();
    const unsigned int        n_owned  = set.core.mass.locally_owned_size();
    double                    taken = 0, by_friction = 0;
    std::vector<unsigned int> present;
    std::vector<const NodalVector *> volumes;
    if (separation_check > 0)
      for (unsigned int b = 0; b < n_bodies; ++b)
        volumes.push_back(&set.per_body("contact volume", b, 0));
    dissipated.clear();
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        bodies_at(set, i, threshold, present);
        if (present.size() < 2 || !filled(volumes, present, i))
          continue;
        const double before = taken;
        correct_node(set, i, present, taken, by_friction);
        if (taken != before)
          dissipated.emplace_back(i, before - taken);
      }
    return {taken, by_friction};
  }

  template class FrictionalContact<2>;
  template class FrictionalContact<3>;

  namespace
  {
    /** "1 2: 0.4, 2 3: 0.1": body pairs (1-based in the scene, 0-based
     * and ordered in the map) to friction coefficients. */
    std::map<std::pair<unsigned int, unsigned int>, double>
    read_pair_friction(SceneReader &reader, const std::string &entry)
    {
      const std::string expected =
        "a list of 'b c: mu' items (two different body numbers, each pair "
        "once, and a number mu >= 0)";
      std::map<std::pair<unsigned int, unsigned int>, double> pairs;
      for (const auto &item :
           Utilities::split_string_list(reader.get(entry), ','))
        {
          const auto parts = Utilities::split_string_list(item, ':');
          if (parts.size() != 2)
            reader.fail(entry, expected);
          std::vector<long> bodies;
          double            mu = -1;
          try
            {
              for (const auto &word :
                   Utilities::split_string_list(parts[0], ' '))
                if (!word.empty())
                  bodies.push_back(Utilities::string_to_int(word));
              mu = Utilities::string_to_double(parts[1]);
            }
          catch (...)
            {
              reader.fail(entry, expected);
            }
          if (bodies.size() != 2 || bodies[0] < 1 || bodies[1] < 1 ||
              bodies[0] == bodies[1] || !(mu >= 0.) || !std::isfinite(mu))
            reader.fail(entry, expected);
          const std::pair<unsigned int, unsigned int> key(
            std::min(bodies[0], bodies[1]) - 1,
            std::max(bodies[0], bodies[1]) - 1);
          if (pairs.count(key) > 0)
            reader.fail(entry, expected);
          pairs[key] = mu;
        }
      return pairs;
    }
  } // namespace

  template <int dim>
  void
  add_frictional_contact_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "frictional contact",
      "contact between bodies with Coulomb friction: each body moves in "
      "its own nodal velocity field, corrected where bodies meet and "
      "approach (section Frictional contact: Friction coefficient, Pair "
      "friction coefficients, Normals).",
      [](ParameterHandler &prm) {
        prm.declare_entry("Friction coefficient",
                          "0",
                          Patterns::Double(0),
                          "Coulomb coefficient mu >= 0 between any two "
                          "bodies (0: frictionless).");
        prm.declare_entry(
          "Pair friction coefficients",
          "",
          Patterns::Anything(),
          "Coefficients for particular pairs of bodies, e.g. '1 2: 0.4, "
          "2 3: 0.1'; the other pairs take 'Friction coefficient'.");
        prm.declare_entry(
          "Normals",
          "steepest mass gradient",
          Patterns::Selection(
            "steepest mass gradient|difference of bodies|mass gradient"),
          "The contact normal of body b at node i, from g_b = sum over "
          "b's particles of m_p grad N_i(x_p), which points out of b: "
          "'steepest mass gradient' along g_b or -g_c, whichever of b "
          "and the other body c is steeper (Nairn's maximum volume "
          "gradient: the flat face of a base, not the corner of a block "
          "sliding on it), 'difference of bodies' along g_b - g_others, "
          "'mass gradient' along g_b alone (Bardenhagen's). The first two "
          "give two bodies opposite normals, so that momentum is kept to "
          "round-off.");
        prm.declare_entry(
          "Separation check",
          "0",
          Patterns::Double(0, 1),
          "Contact at a node only where the bodies' particles fill at "
          "least this fraction of the node's volume (integral of N_i; "
          "Uintah's volume constraint): bodies that share a node across "
          "a gap narrower than a cell then do not touch before the gap "
          "closes. 0: off (contact wherever two bodies have mass at a "
          "node); 0.9 is a usual value. Costs a sweep over the particles.");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        return std::make_unique<FrictionalContact<dim>>(
          reader.get_nonnegative("Friction coefficient"),
          read_pair_friction(reader, "Pair friction coefficients"),
          reader.get("Normals") == "mass gradient" ?
            FrictionalContact<dim>::Normals::own_mass_gradient :
          reader.get("Normals") == "difference of bodies" ?
            FrictionalContact<dim>::Normals::difference_of_bodies :
            FrictionalContact<dim>::Normals::steepest_mass_gradient,
          reader.get_double("Separation check"));
      });
  }

  template void
  add_frictional_contact_effect(Registry<Effect<2>> &);
  template void
  add_frictional_contact_effect(Registry<Effect<3>> &);
} // namespace dealmpm
