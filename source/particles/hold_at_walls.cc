#include <deal.II/base/geometry_info.h>

#include <dealmpm/grid/face_normal.h>
#include <dealmpm/particles/hold_at_walls.h>

namespace dealmpm
{
  namespace
  {
    /** Beyond a face by more than this (in reference coordinates): the
     * slack move() allows before it asks for a sort, so that round-off on a
     * face is neither moved nor counted. */
    constexpr double beyond = 1e-12;

    /** Clamp @p xi onto the faces of @p cell that are walls and that it
     * lies beyond; their outward normals. */
    template <int dim, typename Cell>
    std::vector<Tensor<1, dim>>
    clamp_to_walls(Point<dim>                         &xi,
                   const Cell                         &cell,
                   const std::set<types::boundary_id> &walls)
    {
      std::vector<Tensor<1, dim>> normals;
      for (unsigned int d = 0; d < dim; ++d)
        {
          // Faces 2d (xi_d = 0) and 2d + 1 (xi_d = 1) of the unit cell.
          const int side = xi[d] < -beyond ? 0 : (xi[d] > 1 + beyond ? 1 : -1);
          if (side < 0)
            continue;
          const auto face = cell->face(2 * d + side);
          if (face->at_boundary() && walls.count(face->boundary_id()) > 0)
            {
              xi[d]                  = side;
              const Tensor<1, dim> n = face_normal(face);
              normals.push_back(n * (face->center() - cell->center()) > 0 ? n :
                                                                            -n);
            }
        }
      return normals;
    }
  } // namespace

  template <int dim>
  unsigned int
  hold_particles_at_walls(const BackgroundGrid<dim>          &grid,
                          ParticleSet<dim>                   &particles,
                          const std::set<types::boundary_id> &walls)
  {
    if (walls.empty())
      return 0;
    const CoreFields         &f     = particles.fields;
    const ParticleOrder<dim> &order = particles.order_over(grid);
    auto                     &pool  = particles.handler.get_property_pool();
    unsigned int              moved = 0;
    for (std::size_t i = 0; i < grid.cells.size(); ++i)
      for (unsigned int k = order.cell_begin[i]; k < order.cell_begin[i + 1];
           ++k)
        {
          const PooledParticle<dim, false> p(pool, order.handles[k]);
          Point<dim>                       xi = p.get_reference_location();
          if (GeometryInfo<dim>::is_inside_unit_cell(xi, beyond))
            continue;
          const auto normals = clamp_to_walls(xi, grid.cells[i].cell, walls);
          if (normals.empty())
            continue;
          const Point<dim>        x     = grid.cells[i].real_point(xi);
          const ArrayView<double> props = p.get_properties();
          write_vector<dim>(&props[f.displacement],
                            read_vector<dim>(&props[f.displacement]) +
                              (x - p.get_location()));
          Tensor<1, dim> v = read_vector<dim>(&props[f.velocity]);
          for (const Tensor<1, dim> &n : normals)
            v -= std::max(0., v * n) * n;
          write_vector<dim>(&props[f.velocity], v);
          p.set_location(x);
          p.set_reference_location(xi);
          ++moved;
        }
    return moved;
  }

#define DEALMPM_INSTANTIATE(dim)                 \
  template unsigned int hold_particles_at_walls( \
    const BackgroundGrid<dim> &,                 \
    ParticleSet<dim> &,                          \
    const std::set<types::boundary_id> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
