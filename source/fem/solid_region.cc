#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/smallest_stretch.h>
#include <dealmpm/fem/solid_region.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>

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
    RegionBoundaryConditions<dim> only_fixed;
    only_fixed.fixed = fixed;
    setup(only_fixed);
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
    }
  } // namespace

  template <int dim>
  void
  SolidRegion<dim>::setup(const RegionBoundaryConditions<dim> &bc)
  {
    conditions = bc;
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    const IndexSet relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);
    for (auto *v : {&displacement, &velocity, &mass, &force, &traction_force})
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

    // The owned nodes: a support point's dofs are owned together. Faces
    // give their nodes the conditions of their ids.
    std::map<types::global_dof_index, Node> found;
    const std::vector<Point<dim>>          &unit = fe.get_unit_support_points();
    std::vector<types::global_dof_index>    face_dofs(fe.n_dofs_per_face());
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
                    apply_conditions<dim>(bc,
                                          cell->face(f)->boundary_id(),
                                          found[face_dofs[j]]);
              }
        }
    nodes.clear();
    for (const auto &item : found)
      nodes.push_back(item.second);

    // Nominal tractions: int N_i t dA over the reference faces.
    if (!bc.traction.empty())
      {
        QGauss<dim - 1>   face_gauss(degree + 1);
        FEFaceValues<dim> face_values(mapping,
                                      fe,
                                      face_gauss,
                                      update_values | update_JxW_values);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  bc.traction.count(cell->face(f)->boundary_id()))
                {
                  const Tensor<1, dim> t =
                    bc.traction.at(cell->face(f)->boundary_id());
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
    work    = 0;
    make_reference_data();
  }

  template <int dim>
  void
  SolidRegion<dim>::make_reference_data()
  {
    ReferenceData &r = reference;
    r                = ReferenceData();
    r.n_dofs         = fe.n_dofs_per_cell();
    r.n_scalar       = r.n_dofs / dim;
    for (unsigned int i = 0; i < r.n_dofs; ++i)
      {
        r.component.push_back(fe.system_to_component_index(i).first);
        r.scalar.push_back(fe.system_to_component_index(i).second);
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
    std::vector<types::global_dof_index> dofs(r.n_dofs);
    unsigned int                         c = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (const types::global_dof_index dof : dofs)
            r.local_dofs.push_back(partitioner.global_to_local(dof));
          r.centre.push_back(cell->center());
          values.reinit(cell);
          for (unsigned int q = 0; q < r.n_q; ++q)
            {
              r.JxW.push_back(values.JxW(q));
              const std::size_t first = r.grad.size();
              r.grad.resize(first + r.n_scalar);
              for (unsigned int i = 0; i < r.n_dofs; ++i)
                r.grad[first + r.scalar[i]] =
                  values.shape_grad_component(i, q, r.component[i]);
            }
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                face_values.reinit(cell, f);
                r.face_cell.push_back(c);
                r.face_id.push_back(cell->face(f)->boundary_id());
                for (unsigned int q = 0; q < r.n_face_q; ++q)
                  {
                    r.face_normal_dA.push_back(face_values.normal_vector(q) *
                                               face_values.JxW(q));
                    const std::size_t first = r.face_grad.size();
                    r.face_grad.resize(first + r.n_scalar);
                    r.face_value.resize(first + r.n_scalar);
                    for (unsigned int i = 0; i < r.n_dofs; ++i)
                      {
                        r.face_grad[first + r.scalar[i]] =
                          face_values.shape_grad_component(i,
                                                           q,
                                                           r.component[i]);
                        r.face_value[first + r.scalar[i]] =
                          face_values.shape_value_component(i,
                                                            q,
                                                            r.component[i]);
                      }
                  }
              }
          ++c;
        }
  }

  template <int dim>
  Tensor<2, dim>
  SolidRegion<dim>::reference_gradient(
    const LinearAlgebra::distributed::Vector<double> &w,
    const unsigned int                                cell,
    const Tensor<1, dim>                             *grad) const
  {
    Tensor<2, dim>      g;
    const unsigned int *dofs = &reference.local_dofs[cell * reference.n_dofs];
    for (unsigned int i = 0; i < reference.n_dofs; ++i)
      {
        const double          value = w.local_element(dofs[i]);
        const Tensor<1, dim> &dN    = grad[reference.scalar[i]];
        const unsigned int    a     = reference.component[i];
        for (unsigned int b = 0; b < dim; ++b)
          g[a][b] += value * dN[b];
      }
    return g;
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
  double
  SolidRegion<dim>::stable_time_step(const double cfl) const
  {
    const double rate = signal_rate();
    return rate > 0 ? cfl / rate : std::numeric_limits<double>::max();
  }

  template <int dim>
  double
  SolidRegion<dim>::signal_rate() const
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
          // for k = 1, 2 is 1), in the current configuration's scale.
          double stretch = 1;
          for (unsigned int q = 0; q < n_q; ++q)
            stretch =
              std::min(stretch, smallest_stretch(deformation[k - n_q + q]));
          rate = std::max(rate,
                          c * fe.degree /
                            (stretch * cell->minimum_vertex_distance()));
        }
    return Utilities::MPI::max(rate, comm);
  }

  template <int dim>
  void
  SolidRegion<dim>::internal_force(const double dt)
  {
    displacement.update_ghost_values();
    velocity.update_ghost_values();
    force                  = 0;
    const ReferenceData &r = reference;
    std::vector<double>  local(r.n_dofs);
    const std::size_t    n_cells = r.centre.size();
    for (std::size_t c = 0, k = 0; c < n_cells; ++c)
      {
        std::fill(local.begin(), local.end(), 0.);
        for (unsigned int q = 0; q < r.n_q; ++q, ++k)
          {
            const Tensor<1, dim> *grad = &r.grad[k * r.n_scalar];
            const Tensor<2, dim>  F    = unit_symmetric_tensor<dim>() +
                                     reference_gradient(displacement, c, grad);
            const double J = determinant(F);
            if (!(J > 0))
              {
                std::ostringstream message;
                message << "an FEM region's cell at reference position ("
                        << r.centre[c] << ") turned inside out (J = " << J
                        << "); a smaller time step or a finer mesh there "
                           "may help";
                throw RunError(message.str());
              }
            // The half step that made F: F - F_old = dt grad_X v.
            if (dt > 0)
              material.update_stress(
                reference_gradient(velocity, c, grad) * invert(F),
                F,
                dt,
                stress[k],
                ArrayView<double>(internal.data() + k * n_internal,
                                  n_internal));
            deformation[k] = F;
            const Tensor<2, dim> P =
              J * Tensor<2, dim>(stress[k]) * transpose(invert(F));
            for (unsigned int i = 0; i < r.n_dofs; ++i)
              local[i] -= (P[r.component[i]] * grad[r.scalar[i]]) * r.JxW[k];
          }
        const unsigned int *dofs = &r.local_dofs[c * r.n_dofs];
        for (unsigned int i = 0; i < r.n_dofs; ++i)
          force.local_element(dofs[i]) += local[i];
      }
    force.compress(VectorOperation::add);
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  SolidRegion<dim>::area_normals(const std::set<types::boundary_id> &ids) const
  {
    LinearAlgebra::distributed::Vector<double> a(force);
    a = 0;
    displacement.update_ghost_values();
    const ReferenceData &r = reference;
    for (std::size_t face = 0; face < r.face_cell.size(); ++face)
      if (ids.count(r.face_id[face]))
        {
          const unsigned int  c    = r.face_cell[face];
          const unsigned int *dofs = &r.local_dofs[c * r.n_dofs];
          for (unsigned int q = 0; q < r.n_face_q; ++q)
            {
              const std::size_t    k = face * r.n_face_q + q;
              const Tensor<2, dim> F =
                unit_symmetric_tensor<dim>() +
                reference_gradient(displacement,
                                   c,
                                   &r.face_grad[k * r.n_scalar]);
              // Nanson: n da = J F^-T N dA.
              const Tensor<1, dim> n_da =
                determinant(F) * transpose(invert(F)) * r.face_normal_dA[k];
              const double *N = &r.face_value[k * r.n_scalar];
              for (unsigned int i = 0; i < r.n_dofs; ++i)
                a.local_element(dofs[i]) +=
                  N[r.scalar[i]] * n_da[r.component[i]];
            }
        }
    a.compress(VectorOperation::add);
    std::vector<Tensor<1, dim>> normals(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      normals[k] = node_vector(a, nodes[k]);
    return normals;
  }

  namespace
  {
    /** Per dof of the locally owned cells: the sorted global indices of
     * the vertices of the mesh object (vertex, line, face, cell) its
     * support point sits on, and its component; the same on any
     * partition (k <= 2: one support point per object). */
    template <int dim>
    std::map<types::global_dof_index, std::string>
    dof_keys(const DoFHandler<dim> &dof_handler)
    {
      const FiniteElement<dim>            &fe   = dof_handler.get_fe();
      const std::vector<Point<dim>>       &unit = fe.get_unit_support_points();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::map<types::global_dof_index, std::string> keys;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                std::vector<unsigned int> vertices;
                for (const unsigned int v : cell->vertex_indices())
                  {
                    bool on = true;
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        const double x     = unit[i][d];
                        const bool   upper = (v >> d) & 1u;
                        if ((x < 1e-12 && upper) || (x > 1 - 1e-12 && !upper))
                          on = false;
                      }
                    if (on)
                      vertices.push_back(cell->vertex_index(v));
                  }
                std::sort(vertices.begin(), vertices.end());
                std::string key =
                  std::to_string(fe.system_to_component_index(i).first);
                for (const unsigned int v : vertices)
                  key += "," + std::to_string(v);
                keys[dofs[i]] = key;
              }
          }
      return keys;
    }

    void
    write_hex(std::ostream &out, const double x)
    {
      out << ' ' << std::hexfloat << x << std::defaultfloat;
    }

    double
    read_hex(std::istream &in)
    {
      std::string word;
      in >> word;
      return std::strtod(word.c_str(), nullptr);
    }
  } // namespace

  template <int dim>
  std::string
  SolidRegion<dim>::save_state() const
  {
    std::ostringstream out;
    out << "step";
    write_hex(out, last_dt);
    write_hex(out, work);
    write_hex(out, row_time);
    for (unsigned int d = 0; d < dim; ++d)
      write_hex(out, row_impulse[d]);
    out << '\n';
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    for (const auto &[dof, key] : dof_keys(dof_handler))
      if (owned.is_element(dof))
        {
          out << "dof " << key;
          write_hex(out, displacement(dof));
          write_hex(out, velocity(dof));
          for (const auto &column : affine)
            write_hex(out, column(dof));
          out << '\n';
        }
    const unsigned int n_q = QGauss<dim>(fe.degree + 1).size();
    std::size_t        k   = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          out << "cell " << cell->id().to_string();
          for (unsigned int q = 0; q < n_q; ++q, ++k)
            {
              for (unsigned int c = 0; c < stress[k].n_independent_components;
                   ++c)
                write_hex(out, stress[k].access_raw_entry(c));
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  write_hex(out, deformation[k][i][j]);
              for (unsigned int j = 0; j < n_internal; ++j)
                write_hex(out, internal[k * n_internal + j]);
            }
          out << '\n';
        }
    return out.str();
  }

  template <int dim>
  void
  SolidRegion<dim>::load_state(const std::vector<std::string> &parts)
  {
    // Per dof: u, v and the affine columns.
    std::map<std::string, std::vector<double>> dofs;
    std::map<std::string, std::string>         cells;
    double                                     total_work = 0;
    Tensor<1, dim>                             total_impulse;
    for (const std::string &part : parts)
      {
        std::istringstream lines(part);
        std::string        line;
        while (std::getline(lines, line))
          {
            std::istringstream in(line);
            std::string        kind, key;
            in >> kind;
            if (kind == "step")
              {
                last_dt = read_hex(in);
                total_work += read_hex(in);
                row_time = read_hex(in);
                for (unsigned int d = 0; d < dim; ++d)
                  total_impulse[d] += read_hex(in);
              }
            else if (kind == "dof")
              {
                in >> key;
                std::vector<double> &values = dofs[key];
                for (in >> std::ws; !in.eof(); in >> std::ws)
                  values.push_back(read_hex(in));
              }
            else if (kind == "cell")
              {
                in >> key;
                std::getline(in, cells[key]);
              }
          }
      }
    const bool first      = Utilities::MPI::this_mpi_process(comm) == 0;
    work                  = first ? total_work : 0.;
    row_impulse           = first ? total_impulse : Tensor<1, dim>();
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    for (const auto &[dof, key] : dof_keys(dof_handler))
      if (owned.is_element(dof))
        {
          const auto found = dofs.find(key);
          AssertThrow(found != dofs.end() &&
                        found->second.size() >= 2 + affine.size(),
                      ExcMessage("the saved FEM region has no node " + key));
          displacement(dof) = found->second[0];
          velocity(dof)     = found->second[1];
          for (unsigned int j = 0; j < affine.size(); ++j)
            affine[j](dof) = found->second[2 + j];
        }
    displacement.update_ghost_values();
    velocity.update_ghost_values();
    const unsigned int n_q = QGauss<dim>(fe.degree + 1).size();
    std::size_t        k   = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto found = cells.find(cell->id().to_string());
          AssertThrow(found != cells.end(),
                      ExcMessage("the saved FEM region has no cell " +
                                 cell->id().to_string()));
          std::istringstream in(found->second);
          for (unsigned int q = 0; q < n_q; ++q, ++k)
            {
              for (unsigned int c = 0; c < stress[k].n_independent_components;
                   ++c)
                stress[k].access_raw_entry(c) = read_hex(in);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  deformation[k][i][j] = read_hex(in);
              for (unsigned int j = 0; j < n_internal; ++j)
                internal[k * n_internal + j] = read_hex(in);
            }
        }
  }

  template <int dim>
  Point<dim>
  SolidRegion<dim>::position(const Node &node) const
  {
    return node.X + node_vector(displacement, node);
  }

  template <int dim>
  Tensor<1, dim>
  SolidRegion<dim>::node_vector(
    const LinearAlgebra::distributed::Vector<double> &v,
    const Node                                       &node) const
  {
    Tensor<1, dim> value;
    for (unsigned int d = 0; d < dim; ++d)
      value[d] = v.local_element(node.dof[d]);
    return value;
  }

  template <int dim>
  void
  SolidRegion<dim>::compute_forces(const double          time,
                                   const double          dt,
                                   const BodyForce<dim> &body_force)
  {
    internal_force(last_dt);
    const double t_mid = time + 0.5 * dt;
    if (!conditions.traction.empty())
      force.add(conditions.traction_curve(t_mid), traction_force);
    if (body_force)
      for (const Node &node : nodes)
        {
          const Tensor<1, dim> b = body_force(node.X,
                                              position(node),
                                              node_vector(velocity, node),
                                              t_mid);
          const double         m = mass.local_element(node.dof[0]);
          for (unsigned int d = 0; d < dim; ++d)
            force.local_element(node.dof[d]) += m * b[d];
        }
  }

  template <int dim>
  void
  SolidRegion<dim>::advance(const double time, const double dt)
  {
    using Kind = typename Node::Kind;
    velocity.zero_out_ghost_values();
    displacement.zero_out_ghost_values();
    const double t_mid = time + 0.5 * dt;
    support_reaction   = Tensor<1, dim>();
    for (const Node &node : nodes)
      {
        Tensor<1, dim> v;
        switch (node.kind)
          {
            case Kind::free:
              for (unsigned int d = 0; d < dim; ++d)
                v[d] = velocity.local_element(node.dof[d]) +
                       dt * force.local_element(node.dof[d]) /
                         mass.local_element(node.dof[d]);
              if (!velocity_correction.empty())
                v += velocity_correction[&node - nodes.data()];
              break;
            case Kind::fixed:
              break;
            case Kind::displacement:
              v = node.value *
                  (conditions.displacement_curve(time + dt) -
                   conditions.displacement_curve(time)) /
                  dt;
              break;
            case Kind::velocity:
              v = node.value * conditions.velocity_curve(t_mid);
              break;
            case Kind::bonded:
              v = node_vector(velocity, node);
              break;
          }
        // The work of what holds a prescribed node: the force beyond what
        // the node's own inertia takes, times its path.
        if (node.kind == Kind::fixed || node.kind == Kind::displacement ||
            node.kind == Kind::velocity)
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double m   = mass.local_element(node.dof[d]);
              const double v0  = velocity.local_element(node.dof[d]);
              const double f   = force.local_element(node.dof[d]);
              const double Rxn = m * (v[d] - v0) / dt - f;
              work += Rxn * dt * 0.5 * (v[d] + v0);
              support_reaction[d] += Rxn;
              row_impulse[d] += dt * Rxn;
            }
        for (unsigned int d = 0; d < dim; ++d)
          {
            velocity.local_element(node.dof[d]) = v[d];
            displacement.local_element(node.dof[d]) += dt * v[d];
          }
      }
    velocity_correction.clear();
    row_time += dt;
    // The tractions' work: f_t . v over the step.
    if (!conditions.traction.empty())
      {
        const double scale = conditions.traction_curve(t_mid);
        for (unsigned int i = 0; i < velocity.locally_owned_size(); ++i)
          work += dt * scale * traction_force.local_element(i) *
                  velocity.local_element(i);
      }
    last_dt = dt;
  }

  template <int dim>
  void
  SolidRegion<dim>::step(const double          dt,
                         const double          time,
                         const BodyForce<dim> &body_force)
  {
    compute_forces(time, dt, body_force);
    advance(time, dt);
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
           !conditions.velocity.empty();
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

  template class SolidRegion<2>;
  template class SolidRegion<3>;
} // namespace dealmpm
