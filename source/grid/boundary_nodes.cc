#include <dealmpm/grid/boundary_nodes.h>
#include <dealmpm/grid/face_normal.h>

#include <cmath>
#include <map>
#include <utility>

namespace dealmpm
{
  template <int dim>
  std::vector<BoundaryNode<dim>>
  boundary_nodes(const BackgroundGrid<dim>          &grid,
                 const std::set<types::boundary_id> &ids)
  {
    // (local index, id) -> area vectors, one per direction.
    std::map<std::pair<unsigned int, types::boundary_id>,
             std::vector<Tensor<1, dim>>>
                 found;
    const double same_direction = std::cos(M_PI / 6);
    for (const auto &cell : grid.dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial() || !cell->at_boundary())
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() || ids.count(face->boundary_id()) == 0)
              continue;
            Tensor<1, dim> normal = face_normal(face);
            if (normal * (face->center() - cell->center()) < 0)
              normal = -normal;
            const Tensor<1, dim> share =
              face->measure() / face->n_vertices() * normal;
            for (unsigned int v = 0; v < face->n_vertices(); ++v)
              {
                const types::global_dof_index dof =
                  face->vertex_dof_index(v, 0);
                if (!grid.partitioner->in_local_range(dof) ||
                    grid.hanging_node_constraints.is_constrained(dof))
                  continue;
                auto &areas  = found[{grid.partitioner->global_to_local(dof),
                                      face->boundary_id()}];
                bool  merged = false;
                for (Tensor<1, dim> &area : areas)
                  if (area * normal > same_direction * area.norm())
                    {
                      area += share;
                      merged = true;
                      break;
                    }
                if (!merged)
                  areas.push_back(share);
              }
          }
      }
    std::vector<BoundaryNode<dim>> nodes;
    for (const auto &[key, areas] : found)
      for (const Tensor<1, dim> &area : areas)
        nodes.push_back({key.first, key.second, area});
    return nodes;
  }

#define DEALMPM_INSTANTIATE(dim)                          \
  template std::vector<BoundaryNode<dim>> boundary_nodes( \
    const BackgroundGrid<dim> &, const std::set<types::boundary_id> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
