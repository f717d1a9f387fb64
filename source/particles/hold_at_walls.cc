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
  bool
  hold_at_walls(const GridCell<dim>                                &c,
                const std::set<types::boundary_id>                 &walls,
                const CoreFields                                   &f,
                Particles::PropertyPool<dim>                       &pool,
                const typename Particles::PropertyPool<dim>::Handle handle,
                const Point<dim>                                   &xi)
  {
    Point<dim> on_wall = xi;
    const auto normals = clamp_to_walls(on_wall, c.cell, walls);
    if (normals.empty())
      return false;
    const Point<dim>        x     = c.real_point(on_wall);
    const ArrayView<double> props = pool.get_properties(handle);
    write_vector<dim>(&props[f.displacement],
                      read_vector<dim>(&props[f.displacement]) +
                        (x - pool.get_location(handle)));
    Tensor<1, dim> v = read_vector<dim>(&props[f.velocity]);
    for (const Tensor<1, dim> &n : normals)
      v -= std::max(0., v * n) * n;
    write_vector<dim>(&props[f.velocity], v);
    pool.set_location(handle, x);
    pool.set_reference_location(handle, on_wall);
    return true;
  }

#define DEALMPM_INSTANTIATE(dim)                                          \
  template bool hold_at_walls(const GridCell<dim> &,                      \
                              const std::set<types::boundary_id> &,       \
                              const CoreFields &,                         \
                              Particles::PropertyPool<dim> &,             \
                              const Particles::PropertyPool<dim>::Handle, \
                              const Point<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
