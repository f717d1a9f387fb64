#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

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
    const auto &nodes = region.get_nodes();
    for (unsigned int k = 0; k < nodes.size(); ++k)
      if (nodes[k].kind == SolidRegion<dim>::Node::Kind::bonded)
        local.push_back(k);
    n_global = Utilities::MPI::sum(local.size(), region.get_communicator());
  }

  template <int dim>
  void
  BondedCoupling<dim>::use_affine()
  {
    affine = true;
    region.use_affine();
  }

  namespace
  {
    /** C = B D^+ with D's pseudo-inverse: a node on a grid line has no
     * spread across it (the grid cannot hold an affine part there). */
    template <int dim>
    Tensor<2, dim>
    affine_matrix(const Tensor<2, dim> &B, const SymmetricTensor<2, dim> &D)
    {
      Tensor<2, dim> D_plus;
      const double   scale = trace(D);
      if (!(scale > 0))
        return D_plus;
      for (const auto &[lambda, e] : eigenvectors(D))
        if (lambda > 1e-12 * scale)
          D_plus += outer_product(e, e) / lambda;
      return B * D_plus;
    }
  } // namespace

  template <int dim>
  void
  BondedCoupling<dim>::grid_changed(const BackgroundGrid<dim> &grid)
  {
    points.grid_changed(grid);
  }

  template <int dim>
  std::vector<double>
  BondedCoupling<dim>::node_values() const
  {
    // x, m, m v, f (and B, and the heat) per node.
    std::vector<double> mine;
    mine.reserve(local.size() * n_values());
    for (const unsigned int k : local)
      {
        const auto          &node = region.get_nodes()[k];
        const Point<dim>     x    = region.position(node);
        const double         m    = region.mass_of(node);
        const Tensor<1, dim> v    = region.velocity_of(node);
        const Tensor<1, dim> f    = region.force_of(node);
        append_components<dim>(mine, x);
        mine.push_back(m);
        append_components<dim>(mine, m * v);
        append_components<dim>(mine, f);
        if (affine)
          {
            const Tensor<2, dim> B = region.affine_of(node);
            for (unsigned int j = 0; j < dim; ++j)
              for (unsigned int c = 0; c < dim; ++c)
                mine.push_back(B[c][j]);
          }
        if (heat)
          {
            const double C = region.heat_capacity_of(node);
            mine.push_back(C);
            mine.push_back(C * region.temperature_of(node));
            mine.push_back(region.conducted_heat_of(node));
          }
      }
    return mine;
  }

  template <int dim>
  void
  BondedCoupling<dim>::deposit(const BackgroundGrid<dim> &grid,
                               NodalFieldSet<dim>        &set)
  {
    points.gather_and_place(grid, node_values(), n_values());
    add_to(set.core, grid);
    if (set.has_body_fields())
      add_to(set.body[body], grid);
  }

  template <int dim>
  Tensor<2, dim>
  BondedCoupling<dim>::affine_momentum(
    const typename NodesOnGrid<dim>::Placed &p,
    const Point<dim>                        &x,
    const BackgroundGrid<dim>               &grid) const
  {
    Tensor<2, dim>          B;
    SymmetricTensor<2, dim> D;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int j = 0; j < dim; ++j)
        B[c][j] = points.value(p.point, 3 * dim + 1 + j * dim + c);
    for (unsigned int n = 0; n < p.nodes.size(); ++n)
      {
        const Tensor<1, dim> r = grid.node_positions[p.nodes[n]] - x;
        D += p.weights[n] * symmetrize(outer_product(r, r));
      }
    return points.value(p.point, dim) * affine_matrix(B, D);
  }

  template <int dim>
  void
  BondedCoupling<dim>::add_to(NodalFields<dim>          &fields,
                              const BackgroundGrid<dim> &grid) const
  {
    fields.mass.zero_out_ghost_values();
    for (unsigned int d = 0; d < dim; ++d)
      {
        fields.momentum[d].zero_out_ghost_values();
        fields.force[d].zero_out_ghost_values();
      }
    for (const auto &p : points.placed())
      {
        Point<dim>     x;
        Tensor<1, dim> mv;
        Tensor<2, dim> mC; // the affine part times m
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d]  = points.value(p.point, d);
            mv[d] = points.value(p.point, dim + 1 + d);
          }
        if (affine)
          mC = affine_momentum(p, x, grid);
        for (unsigned int n = 0; n < p.nodes.size(); ++n)
          {
            const double         w = p.weights[n];
            const Tensor<1, dim> p_n =
              affine ? mv + mC * (grid.node_positions[p.nodes[n]] - x) : mv;
            fields.mass.local_element(p.nodes[n]) +=
              w * points.value(p.point, dim);
            for (unsigned int d = 0; d < dim; ++d)
              {
                fields.momentum[d].local_element(p.nodes[n]) += w * p_n[d];
                fields.force[d].local_element(p.nodes[n]) +=
                  w * points.value(p.point, 2 * dim + 1 + d);
              }
          }
      }
    fields.mass.compress(VectorOperation::add);
    for (unsigned int d = 0; d < dim; ++d)
      {
        fields.momentum[d].compress(VectorOperation::add);
        fields.force[d].compress(VectorOperation::add);
      }
  }

  template <int dim>
  std::vector<double>
  BondedCoupling<dim>::grid_velocities(const BackgroundGrid<dim> &grid,
                                       const NodalFields<dim>    &fields)
  {
    // v (and B, column by column) per node.
    const unsigned int  width = dim + (affine ? dim * dim : 0);
    std::vector<double> v(width * points.n_points(), 0.);
    for (const auto &p : points.placed())
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = points.value(p.point, d);
        for (unsigned int n = 0; n < p.nodes.size(); ++n)
          {
            const double w  = p.weights[n];
            double      *to = &v[width * p.point];
            for (unsigned int d = 0; d < dim; ++d)
              to[d] += w * fields.velocity[d].local_element(p.nodes[n]);
            if (!affine)
              continue;
            const Tensor<1, dim> r = grid.node_positions[p.nodes[n]] - x;
            for (unsigned int j = 0; j < dim; ++j)
              for (unsigned int c = 0; c < dim; ++c)
                to[dim + j * dim + c] +=
                  w * fields.velocity[c].local_element(p.nodes[n]) * r[j];
          }
      }
    return points.sum_to_owners(v, width, grid.comm);
  }

  template <int dim>
  void
  BondedCoupling<dim>::read_back(const BackgroundGrid<dim> &grid,
                                 const NodalFieldSet<dim>  &set)
  {
    const NodalFields<dim> &fields =
      set.has_body_fields() ? set.body[body] : set.core;
    const unsigned int          width = dim + (affine ? dim * dim : 0);
    const std::vector<double>   mine  = grid_velocities(grid, fields);
    std::vector<Tensor<1, dim>> v(local.size());
    std::vector<Tensor<2, dim>> B(affine ? local.size() : 0);
    for (std::size_t k = 0; k < local.size(); ++k)
      for (unsigned int c = 0; c < dim; ++c)
        {
          v[k][c] = mine[width * k + c];
          if (affine)
            for (unsigned int j = 0; j < dim; ++j)
              B[k][c][j] = mine[width * k + dim + j * dim + c];
        }
    region.set_bonded_velocities(local, v, B);
  }

  template class BondedCoupling<2>;
  template class BondedCoupling<3>;
} // namespace dealmpm
