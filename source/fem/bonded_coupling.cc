#include <deal.II/base/mpi.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/fem/bonded_coupling.h>

namespace dealmpm
{
  template <int dim>
  BondedCoupling<dim>::BondedCoupling(SolidRegion<dim>  &region,
                                      const unsigned int body)
    : region(region)
    , body(body)
  {
    for (unsigned int k = 0; k < region.nodes.size(); ++k)
      if (region.nodes[k].kind == SolidRegion<dim>::Node::Kind::bonded)
        local.push_back(k);
    n_global = Utilities::MPI::sum(local.size(), region.comm);
  }

  template <int dim>
  void
  BondedCoupling<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    points.grid_changed(grid);
  }

  template <int dim>
  void
  BondedCoupling<dim>::deposit(const BackgroundGrid<dim> &grid,
                               NodalFieldSet<dim>        &set)
  {
    // x, m, m v, f per node.
    constexpr unsigned int n_values = 3 * dim + 1;
    std::vector<double>    mine;
    mine.reserve(local.size() * n_values);
    for (const unsigned int k : local)
      {
        const auto          &node = region.nodes[k];
        const Point<dim>     x    = region.position(node);
        const double         m    = region.mass.local_element(node.dof[0]);
        const Tensor<1, dim> v    = region.node_vector(region.velocity, node);
        const Tensor<1, dim> f    = region.node_vector(region.force, node);
        append_components<dim>(mine, x);
        mine.push_back(m);
        append_components<dim>(mine, m * v);
        append_components<dim>(mine, f);
      }
    points.gather_and_place(grid, mine, n_values);

    std::vector<NodalFields<dim> *> targets{&set.core};
    if (set.has_body_fields())
      targets.push_back(&set.body[body]);
    for (NodalFields<dim> *fields : targets)
      {
        fields->mass.zero_out_ghost_values();
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields->momentum[d].zero_out_ghost_values();
            fields->force[d].zero_out_ghost_values();
          }
        for (const auto &p : points.placed())
          for (unsigned int n = 0; n < p.nodes.size(); ++n)
            {
              const double w = p.weights[n];
              fields->mass.local_element(p.nodes[n]) +=
                w * points.value(p.point, dim);
              for (unsigned int d = 0; d < dim; ++d)
                {
                  fields->momentum[d].local_element(p.nodes[n]) +=
                    w * points.value(p.point, dim + 1 + d);
                  fields->force[d].local_element(p.nodes[n]) +=
                    w * points.value(p.point, 2 * dim + 1 + d);
                }
            }
        fields->mass.compress(VectorOperation::add);
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields->momentum[d].compress(VectorOperation::add);
            fields->force[d].compress(VectorOperation::add);
          }
      }
  }

  template <int dim>
  void
  BondedCoupling<dim>::read_back(const BackgroundGrid<dim> &grid,
                                 const NodalFieldSet<dim>  &set)
  {
    const NodalFields<dim> &fields =
      set.has_body_fields() ? set.body[body] : set.core;
    std::vector<double> v(dim * points.n_points(), 0.);
    for (const auto &p : points.placed())
      for (unsigned int n = 0; n < p.nodes.size(); ++n)
        for (unsigned int d = 0; d < dim; ++d)
          v[dim * p.point + d] +=
            p.weights[n] * fields.velocity[d].local_element(p.nodes[n]);
    const std::vector<double> mine = points.sum_to_owners(v, dim, grid.comm);
    region.velocity.zero_out_ghost_values();
    for (std::size_t j = 0; j < local.size(); ++j)
      for (unsigned int d = 0; d < dim; ++d)
        region.velocity.local_element(region.nodes[local[j]].dof[d]) =
          mine[dim * j + d];
  }

  template class BondedCoupling<2>;
  template class BondedCoupling<3>;
} // namespace dealmpm
