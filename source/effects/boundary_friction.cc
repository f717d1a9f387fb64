#include <deal.II/base/mpi.h>

#include <dealmpm/effects/boundary_friction.h>
#include <dealmpm/effects/coulomb_friction.h>
#include <dealmpm/grid/nodal_exchange.h>

#include <algorithm>
#include <array>

namespace dealmpm
{
  template <int dim>
  void
  BoundaryFriction<dim>::setup(const EffectSetup<dim> &setup,
                               SceneReader            &reader)
  {
    std::set<types::boundary_id> ids;
    for (const auto &item : coefficients)
      ids.insert(item.first);
    setup.conditions.require(reader,
                             "Coefficients",
                             ids,
                             setup.grid,
                             "slip",
                             "friction acts where a slip wall holds the "
                             "normal velocity");
    grid_changed(setup.grid);
  }

  template <int dim>
  void
  BoundaryFriction<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    std::set<types::boundary_id> ids;
    for (const auto &item : coefficients)
      ids.insert(item.first);
    nodes = boundary_nodes(grid, ids);
  }

  template <int dim>
  void
  BoundaryFriction<dim>::after_grid_update(const EffectContext<dim> &state,
                                           NodalFields<dim>         &fields)
  {
    // Per node, what the slip condition took off the normal velocity (> 0
    // where it pushed, < 0 where it held a node that was leaving the wall).
    pressed.assign(nodes.size(), 0.);
    dissipated.clear();
    std::map<types::boundary_id, std::array<double, 2>> sums; // net, pushes
    for (const auto &item : coefficients)
      sums[item.first] = {{0., 0.}};
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        const unsigned int i = nodes[k].local_index;
        const double       m = fields.mass.local_element(i);
        if (!(m > state.mass_threshold))
          continue;
        const Tensor<1, dim> n = nodes[k].normal();
        for (unsigned int d = 0; d < dim; ++d)
          pressed[k] += n[d] * ((fields.momentum[d].local_element(i) +
                                 state.dt * fields.force[d].local_element(i)) /
                                  m -
                                fields.velocity[d].local_element(i));
        sums[nodes[k].id][0] += m * pressed[k];
        sums[nodes[k].id][1] += m * std::max(0., pressed[k]);
      }
    // The wall's pulls are no Coulomb contact: charge them against its
    // pushes, so that friction acts on the net normal force.
    std::map<types::boundary_id, double> share;
    for (auto &[id, sum] : sums)
      {
        const double net    = Utilities::MPI::sum(sum[0], state.grid.comm);
        const double pushes = Utilities::MPI::sum(sum[1], state.grid.comm);
        share[id] = pushes > 0. ? std::clamp(net / pushes, 0., 1.) : 0.;
      }
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        if (!(pressed[k] > 0.))
          continue;
        const BoundaryNode<dim> &node = nodes[k];
        const unsigned int       i    = node.local_index;
        const double             m    = fields.mass.local_element(i);
        Tensor<1, dim>           v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = fields.velocity[d].local_element(i);
        const Tensor<1, dim> change =
          coulomb_change(v,
                         node.normal(),
                         share[node.id] * pressed[k],
                         coefficients.at(node.id));
        if (change.norm_square() == 0.)
          continue;
        // The impulse's work on the velocity it leaves (as a rigid body's):
        // none on a node it holds at rest. The kinetic energy it takes
        // off, 1/2 m (|v + change|^2 - |v|^2), is larger by 1/2 m
        // |change|^2, and at rest that is the velocity the other forces
        // gave the node within the step and friction took back: counted
        // as work, it grew every step of a block that never moved.
        this->work += m * (change * (v + change));
        dissipated.emplace_back(i, -m * (change * (v + change)));
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields.velocity[d].local_element(i) += change[d];
            fields.velocity_increment[d].local_element(i) += change[d];
          }
      }
    NodalExchange()
      .add(fields.velocity)
      .add(fields.velocity_increment)
      .copy_owners_to_ghosts();
  }

  template class BoundaryFriction<2>;
  template class BoundaryFriction<3>;

  template <int dim>
  void
  add_boundary_friction_effect(Registry<Effect<dim>> &registry)
  {
    registry.add(
      "boundary friction",
      "Coulomb friction on slip walls of the grid (section Boundary "
      "friction: Coefficients).",
      [](ParameterHandler &prm) {
        prm.declare_entry(
          "Coefficients",
          "",
          Patterns::Anything(),
          "Friction coefficient per boundary id, e.g. '2: 0.3, 3: 0.5'; "
          "each id must have 'slip' in 'Grid/Boundary conditions'.");
      },
      [](SceneReader &reader) -> std::unique_ptr<Effect<dim>> {
        const std::map<unsigned int, double> read =
          reader.get_id_nonnegatives("Coefficients");
        const std::map<types::boundary_id, double> coefficients(read.begin(),
                                                                read.end());
        if (coefficients.empty())
          reader.fail("Coefficients",
                      "at least one 'id: friction coefficient' pair");
        return std::make_unique<BoundaryFriction<dim>>(coefficients);
      });
  }

  template void
  add_boundary_friction_effect(Registry<Effect<2>> &);
  template void
  add_boundary_friction_effect(Registry<Effect<3>> &);
} // namespace dealmpm
