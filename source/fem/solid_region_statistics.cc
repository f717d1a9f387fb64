#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <dealmpm/fem/solid_region.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dealmpm
{
  template <int dim>
  double
  SolidRegion<dim>::kinetic_energy() const
  {
    double e = 0;
    for (unsigned int i = 0; i < velocity.locally_owned_size(); ++i)
      e += 0.5 * mass.local_element(i) * std::pow(velocity.local_element(i), 2);
    return Utilities::MPI::sum(e, comm);
  }

  template <int dim>
  template <typename Density>
  double
  SolidRegion<dim>::integral(const Density &density) const
  {
    QGauss<dim>   gauss(fe.degree + 1);
    FEValues<dim> values(mapping, fe, gauss, update_JxW_values);
    double        e = 0;
    std::size_t   k = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          for (unsigned int q = 0; q < gauss.size(); ++q, ++k)
            e +=
              density(k,
                      ArrayView<const double>(internal.data() + k * n_internal,
                                              n_internal)) *
              values.JxW(q);
        }
    return Utilities::MPI::sum(e, comm);
  }

  template <int dim>
  double
  SolidRegion<dim>::strain_energy() const
  {
    return integral(
      [this](const std::size_t k, const ArrayView<const double> state) {
        return material.strain_energy_density(deformation[k], stress[k], state);
      });
  }

  template <int dim>
  double
  SolidRegion<dim>::dissipated_work() const
  {
    if (!material.dissipates())
      return 0;
    return integral(
      [this](const std::size_t, const ArrayView<const double> state) {
        return material.dissipated_energy_density(state);
      });
  }

  template <int dim>
  double
  SolidRegion<dim>::potential_energy(
    const std::function<double(const Point<dim> &)> &potential) const
  {
    return Utilities::MPI::sum(local_potential_energy(potential), comm);
  }

  template <int dim>
  double
  SolidRegion<dim>::local_potential_energy(
    const std::function<double(const Point<dim> &)> &potential) const
  {
    double e = 0;
    for (const Node &node : nodes)
      e += mass.local_element(node.dof[0]) * potential(position(node));
    return e;
  }

  template <int dim>
  void
  SolidRegion<dim>::track_potential(
    const std::function<double(const Point<dim> &)> &potential,
    const bool                                       before_step)
  {
    const double e = local_potential_energy(potential);
    if (before_step)
      work += e - last_potential;
    last_potential = e;
  }

  template <int dim>
  Tensor<1, dim>
  SolidRegion<dim>::momentum() const
  {
    Tensor<1, dim> p;
    for (const Node &node : nodes)
      p += mass.local_element(node.dof[0]) * node_vector(velocity, node);
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = Utilities::MPI::sum(p[d], comm);
    return p;
  }

  template <int dim>
  Tensor<1, 3>
  SolidRegion<dim>::angular_momentum() const
  {
    Tensor<1, 3> h;
    for (const Node &node : nodes)
      {
        Tensor<1, 3>         x, mv;
        const Point<dim>     p = position(node);
        const Tensor<1, dim> v = node_vector(velocity, node);
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d]  = p[d];
            mv[d] = mass.local_element(node.dof[0]) * v[d];
          }
        h += cross_product_3d(x, mv);
      }
    for (unsigned int d = 0; d < 3; ++d)
      h[d] = Utilities::MPI::sum(h[d], comm);
    return h;
  }

  template <int dim>
  Tensor<1, dim>
  SolidRegion<dim>::support_force() const
  {
    return Utilities::MPI::sum(support_reaction, comm);
  }

  template <int dim>
  Tensor<1, dim>
  SolidRegion<dim>::mean_support_force() const
  {
    return row_time > 0 ? Utilities::MPI::sum(row_impulse, comm) / row_time :
                          Tensor<1, dim>();
  }

  template <int dim>
  void
  SolidRegion<dim>::start_statistics_row()
  {
    row_impulse = Tensor<1, dim>();
    row_time    = 0;
  }

  template <int dim>
  bool
  SolidRegion<dim>::has_supports() const
  {
    return !conditions.fixed.empty() || !conditions.displacement.empty() ||
           !conditions.velocity.empty() || !conditions.shaken.empty();
  }

  template <int dim>
  double
  SolidRegion<dim>::total_mass() const
  {
    double m = 0;
    for (const Node &node : nodes)
      m += mass.local_element(node.dof[0]);
    return Utilities::MPI::sum(m, comm);
  }

  template <int dim>
  double
  SolidRegion<dim>::node_velocity(const Point<dim>  &x,
                                  const unsigned int component) const
  {
    const double tolerance = 1e-10 * GridTools::diameter(triangulation);
    double       found     = -std::numeric_limits<double>::max();
    for (const Node &node : nodes)
      if (node.X.distance(x) < tolerance)
        found = velocity.local_element(node.dof[component]);
    found = Utilities::MPI::max(found, comm);
    return found > -std::numeric_limits<double>::max() ?
             found :
             std::numeric_limits<double>::quiet_NaN();
  }

  template <int dim>
  void
  SolidRegion<dim>::cell_means(
    std::vector<SymmetricTensor<2, 3>> &cell_stress,
    std::vector<double>                &cell_von_mises,
    std::vector<std::vector<double>>   &cell_internal) const
  {
    const unsigned int n_q     = QGauss<dim>(fe.degree + 1).size();
    const std::size_t  n_cells = stress.size() / n_q;
    cell_stress.assign(n_cells, SymmetricTensor<2, 3>());
    cell_von_mises.assign(n_cells, 0.);
    cell_internal.assign(n_cells, std::vector<double>(n_internal, 0.));
    for (std::size_t c = 0; c < n_cells; ++c)
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const std::size_t           k = c * n_q + q;
          const SymmetricTensor<2, 3> full =
            full_stress(material,
                        deformation[k],
                        stress[k],
                        ArrayView<const double>(internal.data() +
                                                  k * n_internal,
                                                n_internal));
          cell_stress[c] += full / n_q;
          cell_von_mises[c] +=
            std::sqrt(1.5 * deviator(full) * deviator(full)) / n_q;
          for (unsigned int j = 0; j < n_internal; ++j)
            cell_internal[c][j] += internal[k * n_internal + j] / n_q;
        }
  }

  template <int dim>
  double
  SolidRegion<dim>::largest_node_spacing_on(
    const std::set<types::boundary_id> &ids) const
  {
    double spacing = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              ids.count(cell->face(f)->boundary_id()))
            {
              if (dim == 2)
                spacing = std::max(spacing, cell->face(f)->diameter());
              else
                for (unsigned int l = 0; l < cell->face(f)->n_lines(); ++l)
                  spacing =
                    std::max(spacing, cell->face(f)->line(l)->diameter());
            }
    spacing /= fe.degree;
    return Utilities::MPI::max(spacing, comm);
  }

#define DEALMPM_INSTANTIATE(dim)                                                     \
  template double SolidRegion<dim>::kinetic_energy() const;                          \
  template double SolidRegion<dim>::strain_energy() const;                           \
  template double SolidRegion<dim>::dissipated_work() const;                         \
  template double SolidRegion<dim>::potential_energy(                                \
    const std::function<double(const Point<dim> &)> &) const;                        \
  template void SolidRegion<dim>::track_potential(                                   \
    const std::function<double(const Point<dim> &)> &, const bool);                  \
  template Tensor<1, dim> SolidRegion<dim>::momentum() const;                        \
  template Tensor<1, 3>   SolidRegion<dim>::angular_momentum() const;                \
  template Tensor<1, dim> SolidRegion<dim>::support_force() const;                   \
  template Tensor<1, dim> SolidRegion<dim>::mean_support_force() const;              \
  template void           SolidRegion<dim>::start_statistics_row();                  \
  template bool           SolidRegion<dim>::has_supports() const;                    \
  template double         SolidRegion<dim>::total_mass() const;                      \
  template double         SolidRegion<dim>::node_velocity(const Point<dim> &,        \
                                                  const unsigned int) const; \
  template void           SolidRegion<dim>::cell_means(                              \
    std::vector<SymmetricTensor<2, 3>> &,                                  \
    std::vector<double> &,                                                 \
    std::vector<std::vector<double>> &) const;                             \
  template double SolidRegion<dim>::largest_node_spacing_on(                         \
    const std::set<types::boundary_id> &) const;
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
