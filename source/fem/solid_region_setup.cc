#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

#include <dealmpm/fem/solid_region.h>

#include <cmath>
#include <cstring>
#include <map>
#include <string_view>

namespace dealmpm
{
  template <int dim>
  void
  SolidRegion<dim>::setup(const std::set<types::boundary_id> &fixed)
  {
    RegionBoundaryConditions<dim> only_fixed;
    only_fixed.fixed = fixed;
    setup(only_fixed);
  }

  template <int dim>
  void
  SolidRegion<dim>::setup(const RegionBoundaryConditions<dim> &bc)
  {
    conditions = bc;
    distribute_dofs();
    make_lumped_mass();
    make_nodes();
    if (!conditions.traction.empty())
      make_traction_force();
    make_quadrature_state();
    make_reference_data();
    update_signal_rate();
  }

  template <int dim>
  void
  SolidRegion<dim>::distribute_dofs()
  {
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    const IndexSet relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);
    // One partitioner for all: each of its own would cost a consensus
    // among the ranks to set up.
    const auto partitioner =
      std::make_shared<Utilities::MPI::Partitioner>(owned, relevant, comm);
    for (auto *v : {&displacement, &velocity, &mass, &force, &traction_force})
      v->reinit(partitioner);
  }

  template <int dim>
  void
  SolidRegion<dim>::make_lumped_mass()
  {
    // Gauss-Lobatto points are the support points: the mass is diagonal.
    QGaussLobatto<dim>                   lobatto(fe.degree + 1);
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
  }

  template <int dim>
  void
  SolidRegion<dim>::make_nodes()
  {
    std::map<types::global_dof_index, Node> found = find_owned_nodes();
    apply_face_conditions(found);
    nodes.clear();
    for (const auto &item : found)
      nodes.push_back(item.second);
    if (!conditions.shaken.empty() && !conditions.base->rigid)
      set_base_areas();
  }

  template <int dim>
  void
  SolidRegion<dim>::set_base_areas()
  {
    // A compliant base's dashpots act on each node's share of the base:
    // int N_i n dA with Gauss-Lobatto points (lumped, as the mass).
    LinearAlgebra::distributed::Vector<double> area(mass.get_partitioner());
    QGaussLobatto<dim - 1>                     lobatto(fe.degree + 1);
    FEFaceValues<dim>                          face_values(mapping,
                                  fe,
                                  lobatto,
                                  update_values | update_normal_vectors |
                                    update_JxW_values);
    std::vector<types::global_dof_index>       dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              conditions.shaken.count(cell->face(f)->boundary_id()))
            {
              face_values.reinit(cell, f);
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                for (unsigned int q = 0; q < lobatto.size(); ++q)
                  area(dofs[i]) += face_values.shape_value(i, q) *
                                   face_values.normal_vector(
                                     q)[fe.system_to_component_index(i).first] *
                                   face_values.JxW(q);
            }
    area.compress(VectorOperation::add);
    for (Node &node : nodes)
      if (node.kind == Node::Kind::shaken)
        for (unsigned int d = 0; d < dim; ++d)
          node.value[d] = area.local_element(node.dof[d]);
  }

  template <int dim>
  std::map<types::global_dof_index, typename SolidRegion<dim>::Node>
  SolidRegion<dim>::find_owned_nodes() const
  {
    // A support point's dofs are owned together.
    const IndexSet owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, Node> found;
    const std::vector<Point<dim>>          &unit = fe.get_unit_support_points();
    std::vector<types::global_dof_index>    dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const auto [component, base] = fe.system_to_component_index(i);
              if (!owned.is_element(dofs[i]))
                continue;
              // Keyed by the x dof: the node's other dofs follow it.
              unsigned int i0   = fe.component_to_system_index(0, base);
              Node        &node = found[dofs[i0]];
              node.dof[component] =
                static_cast<unsigned int>(owned.index_within_set(dofs[i]));
              node.X = mapping.transform_unit_to_real_cell(cell, unit[i]);
            }
        }
    return found;
  }

  namespace
  {
    /** The strongest condition of a node on faces with ids @p ids. */
    template <int dim>
    void
    apply_conditions(const RegionBoundaryConditions<dim> &bc,
                     const types::boundary_id             id,
                     typename SolidRegion<dim>::Node     &node)
    {
      using Kind       = typename SolidRegion<dim>::Node::Kind;
      const auto raise = [&](const Kind kind, const Tensor<1, dim> &value) {
        if (static_cast<int>(kind) < static_cast<int>(node.kind) ||
            node.kind == Kind::free)
          {
            node.kind  = kind;
            node.value = value;
          }
      };
      if (bc.fixed.count(id))
        raise(Kind::fixed, Tensor<1, dim>());
      if (bc.displacement.count(id))
        raise(Kind::displacement, bc.displacement.at(id));
      if (bc.velocity.count(id))
        raise(Kind::velocity, bc.velocity.at(id));
      if (bc.bonded.count(id))
        raise(Kind::bonded, Tensor<1, dim>());
      if (bc.shaken.count(id))
        raise(Kind::shaken, Tensor<1, dim>());
    }
  } // namespace

  template <int dim>
  void
  SolidRegion<dim>::apply_face_conditions(
    std::map<types::global_dof_index, Node> &found) const
  {
    const IndexSet owned = dof_handler.locally_owned_dofs();
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    // Every cell at an owned node is owned or a ghost.
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                cell->face(f)->get_dof_indices(face_dofs);
                for (unsigned int j = 0; j < face_dofs.size(); ++j)
                  if (fe.face_system_to_component_index(j).first == 0 &&
                      owned.is_element(face_dofs[j]))
                    apply_conditions<dim>(conditions,
                                          cell->face(f)->boundary_id(),
                                          found[face_dofs[j]]);
              }
        }
  }

  template <int dim>
  void
  SolidRegion<dim>::make_traction_force()
  {
    const std::map<types::boundary_id, Tensor<1, dim>> &traction =
      conditions.traction;
    QGauss<dim - 1>                      face_gauss(fe.degree + 1);
    FEFaceValues<dim>                    face_values(mapping,
                                  fe,
                                  face_gauss,
                                  update_values | update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              traction.count(cell->face(f)->boundary_id()))
            {
              const Tensor<1, dim> t =
                traction.at(cell->face(f)->boundary_id());
              face_values.reinit(cell, f);
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                for (unsigned int q = 0; q < face_gauss.size(); ++q)
                  traction_force(dofs[i]) +=
                    face_values.shape_value(i, q) *
                    t[fe.system_to_component_index(i).first] *
                    face_values.JxW(q);
            }
    traction_force.compress(VectorOperation::add);
  }

  template <int dim>
  void
  SolidRegion<dim>::make_quadrature_state()
  {
    const unsigned int n_q = QGauss<dim>(fe.degree + 1).size();
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
    work    = 0;
  }

  template <int dim>
  void
  SolidRegion<dim>::make_reference_data()
  {
    ReferenceData &r = reference;
    r                = ReferenceData();
    r.n_dofs         = fe.n_dofs_per_cell();
    r.n_scalar       = r.n_dofs / dim;
    // A cell's dofs node by node (scalar shape function s, then its
    // components): the force loop reads a node's dim values together.
    for (unsigned int s = 0; s < r.n_scalar; ++s)
      for (unsigned int a = 0; a < dim; ++a)
        {
          r.component.push_back(a);
          r.scalar.push_back(s);
          r.fe_index.push_back(fe.component_to_system_index(a, s));
        }
    QGauss<dim>       gauss(fe.degree + 1);
    QGauss<dim - 1>   face_gauss(fe.degree + 1);
    FEValues<dim>     values(mapping,
                         fe,
                         gauss,
                         update_gradients | update_JxW_values);
    FEFaceValues<dim> face_values(mapping,
                                  fe,
                                  face_gauss,
                                  update_values | update_gradients |
                                    update_normal_vectors | update_JxW_values);
    r.n_q                   = gauss.size();
    r.n_face_q              = face_gauss.size();
    const auto &partitioner = *displacement.get_partitioner();
    std::vector<types::global_dof_index>               dofs(r.n_dofs);
    std::unordered_multimap<std::size_t, unsigned int> known_gradients;
    unsigned int                                       c = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (const unsigned int i : r.fe_index)
            r.local_dofs.push_back(partitioner.global_to_local(dofs[i]));
          r.centre.push_back(cell->center());
          r.min_vertex_distance.push_back(cell->minimum_vertex_distance());
          values.reinit(cell);
          add_cell_reference(values, known_gradients);
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                face_values.reinit(cell, f);
                add_face_reference(face_values,
                                   c,
                                   cell->face(f)->boundary_id());
              }
          ++c;
        }
  }

  template <int dim>
  void
  SolidRegion<dim>::add_cell_reference(
    const FEValues<dim, dim>                           &values,
    std::unordered_multimap<std::size_t, unsigned int> &known)
  {
    ReferenceData &r = reference;
    for (unsigned int q = 0; q < r.n_q; ++q)
      r.JxW.push_back(values.JxW(q));
    const unsigned int  n = r.n_scalar;
    std::vector<double> set(dim * n * r.n_q);
    for (unsigned int s = 0; s < n; ++s)
      for (unsigned int q = 0; q < r.n_q; ++q)
        {
          // The x component's dof of node s (i = s * dim).
          const Tensor<1, dim> dN =
            values.shape_grad_component(r.fe_index[s * dim], q, 0);
          for (unsigned int b = 0; b < dim; ++b)
            set[(b * n + s) * r.n_q + q] = dN[b];
        }
    // The same bits, the same set: the force loop's numbers are those of
    // the cell's own copy.
    const std::size_t bytes = set.size() * sizeof(double);
    const std::size_t hash  = std::hash<std::string_view>()(
      std::string_view(reinterpret_cast<const char *>(set.data()), bytes));
    const auto [first, last] = known.equal_range(hash);
    for (auto it = first; it != last; ++it)
      if (std::memcmp(&r.grad[std::size_t(it->second) * set.size()],
                      set.data(),
                      bytes) == 0)
        {
          r.gradient_set.push_back(it->second);
          return;
        }
    const unsigned int index = r.grad.size() / set.size();
    known.emplace(hash, index);
    r.gradient_set.push_back(index);
    r.grad.insert(r.grad.end(), set.begin(), set.end());
  }

  template <int dim>
  void
  SolidRegion<dim>::add_face_reference(
    const FEFaceValues<dim, dim> &face_values,
    const unsigned int            cell,
    const types::boundary_id      id)
  {
    ReferenceData &r = reference;
    r.face_cell.push_back(cell);
    r.face_id.push_back(id);
    for (unsigned int q = 0; q < r.n_face_q; ++q)
      {
        r.face_normal_dA.push_back(face_values.normal_vector(q) *
                                   face_values.JxW(q));
        const std::size_t first = r.face_grad.size();
        r.face_grad.resize(first + r.n_scalar);
        r.face_value.resize(first + r.n_scalar);
        for (unsigned int i = 0; i < r.n_dofs; ++i)
          {
            const unsigned int j = r.fe_index[i];
            r.face_grad[first + r.scalar[i]] =
              face_values.shape_grad_component(j, q, r.component[i]);
            r.face_value[first + r.scalar[i]] =
              face_values.shape_value_component(j, q, r.component[i]);
          }
      }
  }

  template <int dim>
  void
  SolidRegion<dim>::set_velocity(const Function<dim> &f)
  {
    for (const Node &node : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        velocity.local_element(node.dof[d]) = f.value(node.X, d);
    velocity.update_ghost_values();
  }

  template <int dim>
  void
  SolidRegion<dim>::set_displacement(const Function<dim> &f)
  {
    for (const Node &node : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        displacement.local_element(node.dof[d]) = f.value(node.X, d);
    displacement.update_ghost_values();
  }

#define DEALMPM_INSTANTIATE(dim)                                               \
  template void SolidRegion<dim>::setup(const std::set<types::boundary_id> &); \
  template void SolidRegion<dim>::setup(                                       \
    const RegionBoundaryConditions<dim> &);                                    \
  template void SolidRegion<dim>::set_velocity(const Function<dim> &);         \
  template void SolidRegion<dim>::set_displacement(const Function<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
