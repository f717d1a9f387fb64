#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <dealmpm/fem/solid_region.h>

#include <cmath>
#include <limits>

namespace dealmpm
{
  template <int dim>
  SolidRegion<dim>::SolidRegion(const MPI_Comm       comm,
                                const Material<dim> &material,
                                const unsigned int   degree)
    : comm(comm)
    , triangulation(comm)
    , fe(FE_Q<dim>(degree), dim)
    , dof_handler(triangulation)
    , material(material)
  {}

  template <int dim>
  void
  SolidRegion<dim>::setup(const std::set<types::boundary_id> &fixed)
  {
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    const IndexSet relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);
    for (auto *v : {&displacement, &velocity, &mass, &force})
      v->reinit(owned, relevant, comm);

    // Gauss-Lobatto points are the support points: the mass is diagonal.
    const unsigned int                   degree = fe.degree;
    QGaussLobatto<dim>                   lobatto(degree + 1);
    FEValues<dim>                        values(mapping,
                         fe,
                         lobatto,
                         update_values | update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            for (unsigned int q = 0; q < lobatto.size(); ++q)
              mass(dofs[i]) += material.density *
                               std::pow(values.shape_value(i, q), 2) *
                               values.JxW(q);
        }
    mass.compress(VectorOperation::add);
    mass.update_ghost_values();

    fixed_dofs.clear();
    if (!fixed.empty())
      {
        const IndexSet boundary =
          DoFTools::extract_boundary_dofs(dof_handler, ComponentMask(), fixed);
        for (const types::global_dof_index d : boundary)
          if (owned.is_element(d))
            fixed_dofs.push_back(d);
      }

    const unsigned int n_q = QGauss<dim>(degree + 1).size();
    const std::size_t  n   = triangulation.n_locally_owned_active_cells() * n_q;
    stress.assign(n, SymmetricTensor<2, dim>());
    deformation.assign(n, unit_symmetric_tensor<dim>());
    n_internal = 0;
    for (const FieldDescription &f : material.internal_variables())
      n_internal += f.n_components;
    internal.assign(n * n_internal, 0.);
    for (std::size_t k = 0; k < n; ++k)
      material.initialize_internal_variables(
        ArrayView<double>(internal.data() + k * n_internal, n_internal));
    last_dt = 0;
  }

  template <int dim>
  void
  SolidRegion<dim>::set_velocity(const Function<dim> &f)
  {
    const std::vector<Point<dim>>       &unit = fe.get_unit_support_points();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (dof_handler.locally_owned_dofs().is_element(dofs[i]))
              velocity(dofs[i]) =
                f.value(mapping.transform_unit_to_real_cell(cell, unit[i]),
                        fe.system_to_component_index(i).first);
        }
    velocity.update_ghost_values();
  }

  template <int dim>
  double
  SolidRegion<dim>::stable_time_step(const double cfl) const
  {
    double             rate = 0;
    const unsigned int n_q  = QGauss<dim>(fe.degree + 1).size();
    std::size_t        k    = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double c = 0;
          for (unsigned int q = 0; q < n_q; ++q, ++k)
            c = std::max(c, material.wave_speed(deformation[k]));
          // The smallest node spacing of the cell (Gauss-Lobatto points of
          // degree k are closer than h / k near the vertices; the factor
          // for k = 1, 2 is 1).
          rate =
            std::max(rate, c * fe.degree / cell->minimum_vertex_distance());
        }
    rate = Utilities::MPI::max(rate, comm);
    return rate > 0 ? cfl / rate : std::numeric_limits<double>::max();
  }

  template <int dim>
  void
  SolidRegion<dim>::internal_force(const double dt)
  {
    displacement.update_ghost_values();
    velocity.update_ghost_values();
    force = 0;
    QGauss<dim>                      gauss(fe.degree + 1);
    FEValues<dim>                    values(mapping,
                         fe,
                         gauss,
                         update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector u(0);
    std::vector<Tensor<2, dim>>      grad_u(gauss.size()), grad_v(gauss.size());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    Vector<double>                       local(fe.n_dofs_per_cell());
    std::size_t                          k = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          values[u].get_function_gradients(displacement, grad_u);
          values[u].get_function_gradients(velocity, grad_v);
          local = 0;
          for (unsigned int q = 0; q < gauss.size(); ++q, ++k)
            {
              const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + grad_u[q];
              // The half step that made F: F - F_old = dt grad_X v.
              if (dt > 0)
                material.update_stress(grad_v[q] * invert(F),
                                       F,
                                       dt,
                                       stress[k],
                                       ArrayView<double>(internal.data() +
                                                           k * n_internal,
                                                         n_internal));
              deformation[k]         = F;
              const Tensor<2, dim> P = determinant(F) *
                                       Tensor<2, dim>(stress[k]) *
                                       transpose(invert(F));
              for (unsigned int i = 0; i < dofs.size(); ++i)
                local(i) -=
                  scalar_product(values[u].gradient(i, q), P) * values.JxW(q);
            }
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            force(dofs[i]) += local(i);
        }
    force.compress(VectorOperation::add);
  }

  template <int dim>
  void
  SolidRegion<dim>::step(const double dt)
  {
    // The stress of u^n (over the last step's size), then
    // v^{n+1/2} = v^{n-1/2} + dt f / m and u^{n+1} = u^n + dt v^{n+1/2}.
    internal_force(last_dt);
    velocity.zero_out_ghost_values();
    displacement.zero_out_ghost_values();
    for (unsigned int i = 0; i < velocity.locally_owned_size(); ++i)
      velocity.local_element(i) +=
        dt * force.local_element(i) / mass.local_element(i);
    for (const types::global_dof_index d : fixed_dofs)
      velocity(d) = 0;
    displacement.add(dt, velocity);
    last_dt = dt;
  }

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
  double
  SolidRegion<dim>::strain_energy() const
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
            e += material.strain_energy_density(
                   deformation[k],
                   stress[k],
                   ArrayView<const double>(internal.data() + k * n_internal,
                                           n_internal)) *
                 values.JxW(q);
        }
    return Utilities::MPI::sum(e, comm);
  }

  template <int dim>
  Tensor<1, dim>
  SolidRegion<dim>::momentum() const
  {
    Tensor<1, dim>                       p;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<bool> counted(velocity.locally_owned_size(), false);
    const IndexSet   &owned = dof_handler.locally_owned_dofs();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]))
              {
                const auto local = owned.index_within_set(dofs[i]);
                if (counted[local])
                  continue;
                counted[local] = true;
                p[fe.system_to_component_index(i).first] +=
                  mass.local_element(local) * velocity.local_element(local);
              }
        }
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = Utilities::MPI::sum(p[d], comm);
    return p;
  }

  template <int dim>
  double
  SolidRegion<dim>::node_velocity(const Point<dim>  &x,
                                  const unsigned int component) const
  {
    const std::vector<Point<dim>>       &unit = fe.get_unit_support_points();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    const double tolerance = 1e-10 * GridTools::diameter(triangulation);
    double       found     = -std::numeric_limits<double>::max();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (fe.system_to_component_index(i).first == component &&
                mapping.transform_unit_to_real_cell(cell, unit[i]).distance(x) <
                  tolerance)
              found = velocity(dofs[i]);
        }
    found = Utilities::MPI::max(found, comm);
    return found > -std::numeric_limits<double>::max() ?
             found :
             std::numeric_limits<double>::quiet_NaN();
  }

  template class SolidRegion<2>;
  template class SolidRegion<3>;
} // namespace dealmpm
