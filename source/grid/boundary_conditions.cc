#include <deal.II/base/geometry_info.h>

#include <dealmpm/core/errors.h>
#include <dealmpm/grid/boundary_conditions.h>

#include <unordered_map>

namespace dealmpm
{
  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Grid");
    prm.declare_entry(
      "Boundary conditions",
      "",
      Patterns::Anything(),
      "Velocity condition per boundary id, e.g. '0: slip, 2: no-slip'. "
      "'no-slip' fixes the nodes, 'slip' removes the normal velocity, "
      "'free' (the default for ids not listed) does nothing.");
    prm.leave_subsection();
  }

  template <int dim>
  std::map<types::boundary_id, BoundaryKind>
  BoundaryConditions<dim>::read(SceneReader &reader)
  {
    SectionScope                               grid(reader, "Grid");
    std::map<types::boundary_id, BoundaryKind> kinds;
    for (const auto &item :
         Utilities::split_string_list(reader.get("Boundary conditions"), ','))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        int        id    = -1;
        try
          {
            if (parts.size() == 2)
              id = Utilities::string_to_int(parts[0]);
          }
        catch (...)
          {}
        if (parts.size() != 2 || id < 0 || id > 255)
          reader.fail("Boundary conditions",
                      "a list of 'id: kind' pairs (id 0-255, kind no-slip, "
                      "slip or free)");
        if (parts[1] == "no-slip")
          kinds[id] = BoundaryKind::no_slip;
        else if (parts[1] == "slip")
          kinds[id] = BoundaryKind::slip;
        else if (parts[1] == "free")
          kinds[id] = BoundaryKind::free;
        else
          reader.fail("Boundary conditions",
                      "kind 'no-slip', 'slip' or 'free', not '" + parts[1] +
                        "'");
      }
    return kinds;
  }

  template <int dim>
  void
  BoundaryConditions<dim>::setup(
    const BackgroundGrid<dim>                        &grid,
    const std::map<types::boundary_id, BoundaryKind> &kinds)
  {
    nodes.clear();
    std::unordered_map<unsigned int, std::size_t> node_of_index;
    const auto add_normal = [&](const types::global_dof_index dof,
                                const Tensor<1, dim>         &normal,
                                const bool                    fixed) {
      if (!grid.partitioner->in_local_range(dof) ||
          grid.hanging_node_constraints.is_constrained(dof))
        return;
      const unsigned int local = grid.partitioner->global_to_local(dof);
      auto               it    = node_of_index.find(local);
      if (it == node_of_index.end())
        {
          it = node_of_index.emplace(local, nodes.size()).first;
          nodes.push_back(Node{local, 0, {}});
        }
      Node &node = nodes[it->second];
      if (fixed)
        {
          node.n_normals = dim;
          for (unsigned int d = 0; d < dim; ++d)
            {
              node.normals[d]    = Tensor<1, dim>();
              node.normals[d][d] = 1.;
            }
          return;
        }
      // Gram-Schmidt against the normals the node already has.
      Tensor<1, dim> n = normal;
      for (unsigned int k = 0; k < node.n_normals; ++k)
        n -= (n * node.normals[k]) * node.normals[k];
      if (node.n_normals < dim && n.norm() > 1e-6)
        node.normals[node.n_normals++] = n / n.norm();
    };

    for (const auto &cell : grid.dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || !cell->at_boundary())
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const auto kind = kinds.find(cell->face(f)->boundary_id());
            if (kind == kinds.end() || kind->second == BoundaryKind::free)
              continue;
            const auto     face = cell->face(f);
            Tensor<1, dim> normal;
            if constexpr (dim == 2)
              {
                const Tensor<1, dim> edge = face->vertex(1) - face->vertex(0);
                normal[0]                 = edge[1];
                normal[1]                 = -edge[0];
              }
            else
              normal = cross_product_3d(face->vertex(1) - face->vertex(0),
                                        face->vertex(2) - face->vertex(0));
            normal /= normal.norm();
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              add_normal(face->vertex_dof_index(v, 0),
                         normal,
                         kind->second == BoundaryKind::no_slip);
          }
      }
  }

  template <int dim>
  void
  BoundaryConditions<dim>::project(std::array<NodalVector, dim> &vector) const
  {
    for (const Node &node : nodes)
      {
        Tensor<1, dim> v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = vector[d].local_element(node.local_index);
        for (unsigned int k = 0; k < node.n_normals; ++k)
          v -= (v * node.normals[k]) * node.normals[k];
        for (unsigned int d = 0; d < dim; ++d)
          vector[d].local_element(node.local_index) = v[d];
      }
  }

  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace dealmpm
