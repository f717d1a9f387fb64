#include <deal.II/base/geometry_info.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/grid/boundary_conditions.h>
#include <dealmpm/grid/face_normal.h>

#include <algorithm>
#include <cmath>
#include <map>

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
      Patterns::Map(
        Patterns::Integer(0, numbers::internal_face_boundary_id - 1),
        Patterns::Selection(boundary_condition_registry<dim>().pattern())),
      "Velocity condition per boundary id, e.g. '0: slip, 2: no-slip': " +
        boundary_condition_registry<dim>().describe() +
        "Ids not listed are free.");
    prm.leave_subsection();
  }

  namespace
  {
    template <int dim>
    class NoSlip : public BoundaryCondition<dim>
    {
    public:
      bool
      fixes_nodes() const override
      {
        return true;
      }
      std::vector<Tensor<1, dim>>
      removed_directions(const Tensor<1, dim> &) const override
      {
        return {};
      }
    };

    template <int dim>
    class Slip : public BoundaryCondition<dim>
    {
    public:
      std::vector<Tensor<1, dim>>
      removed_directions(const Tensor<1, dim> &normal) const override
      {
        return {normal};
      }
    };

    template <int dim>
    class Free : public BoundaryCondition<dim>
    {
    public:
      std::vector<Tensor<1, dim>>
      removed_directions(const Tensor<1, dim> &) const override
      {
        return {};
      }
    };
  } // namespace

  template <int dim>
  BoundaryConditionRegistry<dim> &
  boundary_condition_registry()
  {
    static BoundaryConditionRegistry<dim> registry = [] {
      BoundaryConditionRegistry<dim> r;
      r.add("no-slip", "fixes the nodes.", [] {
        return std::make_unique<NoSlip<dim>>();
      });
      r.add("slip", "removes the normal velocity.", [] {
        return std::make_unique<Slip<dim>>();
      });
      r.add("free", "does nothing.", [] {
        return std::make_unique<Free<dim>>();
      });
      return r;
    }();
    return registry;
  }

  void
  check_grid_has_ids(const SceneReader                         &reader,
                     const std::string                         &entry,
                     const std::map<unsigned int, std::string> &ids,
                     const std::vector<types::boundary_id>     &grid_ids,
                     const std::string                         &whose)
  {
    for (const auto &item : ids)
      if (std::find(grid_ids.begin(), grid_ids.end(), item.first) ==
          grid_ids.end())
        {
          std::string known;
          for (const auto g : grid_ids)
            known += (known.empty() ? "" : ", ") + std::to_string(g);
          reader.fail(entry,
                      "boundary ids " + whose + " (" + known + "), not " +
                        std::to_string(item.first));
        }
  }

  template <int dim>
  std::map<types::boundary_id, std::string>
  BoundaryConditions<dim>::read(SceneReader                           &reader,
                                const std::vector<types::boundary_id> &grid_ids)
  {
    SectionScope grid(reader, "Grid");
    const auto  &registry = boundary_condition_registry<dim>();
    const std::map<unsigned int, std::string> items =
      reader.get_id_map("Boundary conditions", "a kind " + registry.pattern());
    check_grid_has_ids(reader, "Boundary conditions", items, grid_ids);
    std::map<types::boundary_id, std::string> names;
    for (const auto &[id, kind] : items)
      {
        if (!registry.has(kind))
          reader.fail("Boundary conditions",
                      "kind " + registry.pattern() + ", not '" + kind + "'");
        names[id] = kind;
      }
    return names;
  }

  template <int dim>
  void
  BoundaryConditions<dim>::setup(
    const BackgroundGrid<dim>                       &grid,
    const std::map<types::boundary_id, std::string> &names)
  {
    conditions.clear();
    condition_names = names;
    for (const auto &[id, name] : names)
      conditions[id] = boundary_condition_registry<dim>().get(name).create();
    rebuild(grid);
  }

  template <int dim>
  std::set<types::boundary_id>
  BoundaryConditions<dim>::walls() const
  {
    std::set<types::boundary_id> ids;
    const Tensor<1, dim>         any_normal = Point<dim>::unit_vector(0);
    for (const auto &[id, condition] : conditions)
      if (condition->fixes_nodes() ||
          !condition->removed_directions(any_normal).empty())
        ids.insert(id);
    return ids;
  }

  namespace
  {
    /** Add @p n to @p directions: faces that meet at less than 30 degrees
     * (a curved or slightly kinked boundary) share one averaged normal;
     * only a real corner gets a second one, so slip stays slip on curved
     * walls. */
    template <int dim>
    void
    merge_direction(std::vector<Tensor<1, dim>> &directions,
                    const Tensor<1, dim>        &n)
    {
      const double same_direction = std::cos(M_PI / 6);
      for (auto &direction : directions)
        {
          const double cosine = direction * n / direction.norm();
          if (std::abs(cosine) > same_direction)
            {
              direction += (cosine > 0 ? 1. : -1.) * n;
              return;
            }
        }
      directions.push_back(n);
    }
  } // namespace

  template <int dim>
  std::map<unsigned int, typename BoundaryConditions<dim>::Collected>
  BoundaryConditions<dim>::collect_nodes(const BackgroundGrid<dim> &grid) const
  {
    std::map<unsigned int, Collected> collected;
    for (const auto &cell : grid.dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || !cell->at_boundary())
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary())
              continue;
            const auto found = conditions.find(face->boundary_id());
            if (found == conditions.end())
              continue;
            const BoundaryCondition<dim>     &condition = *found->second;
            const std::vector<Tensor<1, dim>> removed =
              condition.removed_directions(face_normal(face));
            if (!condition.fixes_nodes() && removed.empty())
              continue;
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              {
                const types::global_dof_index dof =
                  face->vertex_dof_index(v, 0);
                if (!grid.partitioner->in_local_range(dof) ||
                    grid.hanging_node_constraints.is_constrained(dof))
                  continue;
                Collected &node =
                  collected[grid.partitioner->global_to_local(dof)];
                if (condition.fixes_nodes())
                  node.fixed = true;
                for (const Tensor<1, dim> &n : removed)
                  merge_direction(node.directions, n);
              }
          }
      }
    return collected;
  }

  template <int dim>
  void
  BoundaryConditions<dim>::rebuild(const BackgroundGrid<dim> &grid)
  {
    nodes.clear();
    for (const auto &[local_index, c] : collect_nodes(grid))
      {
        Node node{local_index, 0, {}};
        if (c.fixed)
          for (unsigned int d = 0; d < dim; ++d)
            {
              node.normals[d]    = Tensor<1, dim>();
              node.normals[d][d] = 1.;
              node.n_normals     = dim;
            }
        else
          for (Tensor<1, dim> n : c.directions)
            {
              // Gram-Schmidt against the normals the node already has.
              for (unsigned int k = 0; k < node.n_normals; ++k)
                n -= (n * node.normals[k]) * node.normals[k];
              if (node.n_normals < dim && n.norm() > 1e-6)
                node.normals[node.n_normals++] = n / n.norm();
            }
        nodes.push_back(node);
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

  template <int dim>
  void
  BoundaryConditions<dim>::project_with_increment(
    std::array<NodalVector, dim> &velocity,
    std::array<NodalVector, dim> &increment) const
  {
    for (const Node &node : nodes)
      {
        Tensor<1, dim> v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = velocity[d].local_element(node.local_index);
        Tensor<1, dim> removed;
        for (unsigned int k = 0; k < node.n_normals; ++k)
          removed += (v * node.normals[k]) * node.normals[k];
        for (unsigned int d = 0; d < dim; ++d)
          {
            velocity[d].local_element(node.local_index) -= removed[d];
            increment[d].local_element(node.local_index) -= removed[d];
          }
      }
  }

  template <int dim>
  std::set<types::boundary_id>
  BoundaryConditions<dim>::walls_without_mass(const BackgroundGrid<dim> &grid,
                                              const NodalVector         &mass,
                                              const double threshold) const
  {
    const std::set<types::boundary_id> ids = walls();
    std::set<types::boundary_id>       touched;
    for (const auto &cell : grid.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (face->at_boundary() && ids.count(face->boundary_id()) > 0)
              for (unsigned int v = 0; v < face->n_vertices(); ++v)
                {
                  const types::global_dof_index dof =
                    face->vertex_dof_index(v, 0);
                  if (grid.partitioner->in_local_range(dof) &&
                      mass.local_element(
                        grid.partitioner->global_to_local(dof)) > threshold)
                    touched.insert(face->boundary_id());
                }
          }
    std::set<types::boundary_id> without;
    for (const types::boundary_id id : ids)
      if (Utilities::MPI::logical_or(touched.count(id) > 0, grid.comm) == false)
        without.insert(id);
    return without;
  }

  template <int dim>
  void
  BoundaryConditions<dim>::require(const SceneReader                  &reader,
                                   const std::string                  &entry,
                                   const std::set<types::boundary_id> &ids,
                                   const BackgroundGrid<dim>          &grid,
                                   const std::string &condition,
                                   const std::string &why) const
  {
    std::map<unsigned int, std::string> listed;
    for (const types::boundary_id id : ids)
      listed[id] = "";
    check_grid_has_ids(reader,
                       entry,
                       listed,
                       grid.triangulation.get_boundary_ids());
    for (const types::boundary_id id : ids)
      {
        const auto        named = condition_names.find(id);
        const std::string kind =
          named == condition_names.end() ? "free" : named->second;
        if (kind == condition)
          continue;
        const std::string found =
          "(id " + std::to_string(id) + " is '" + kind + "'";
        reader.fail(entry,
                    condition == "free" ?
                      "ids without a velocity condition " + found +
                        " in 'Grid/Boundary conditions'): " + why :
                      "ids whose 'Grid/Boundary conditions' is '" + condition +
                        "' " + found + "): " + why);
      }
  }

  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace dealmpm
