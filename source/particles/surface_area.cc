#include <dealmpm/particles/surface_area.h>

namespace dealmpm
{
  template <int dim>
  SurfaceFaces<dim>
  surface_faces(const GridCell<dim>  &c,
                const Point<dim>     &xi,
                const unsigned int    n,
                const Shape<dim>     &shape,
                const double          volume,
                const Tensor<1, dim> &face_normal)
  {
    const Tensor<2, dim> inverse_jacobian = c.inverse_jacobian_at(xi);
    const Point<dim>     x                = c.real_point(xi);
    const bool           all_faces        = face_normal.norm() == 0.;
    const Tensor<1, dim> normal =
      all_faces ? face_normal : face_normal / face_normal.norm();
    SurfaceFaces<dim> faces;
    for (unsigned int d = 0; d < dim; ++d)
      for (const double side : {-1., 1.})
        {
          Point<dim> neighbour = xi;
          neighbour[d] += side / n;
          if (shape.contains(c.real_point(neighbour)))
            continue;
          Tensor<1, dim> area;
          for (unsigned int i = 0; i < dim; ++i)
            area[i] = side * volume * n * inverse_jacobian[d][i];
          faces.by_direction[2 * d + (side > 0 ? 1 : 0)] = area.norm();
          const double size = all_faces ? area.norm() : area * normal;
          if (!(size > 1e-12 * area.norm()))
            continue;
          Point<dim> centre = xi;
          centre[d] += 0.5 * side / n;
          faces.area += all_faces ? area : size * normal;
          faces.size += size;
          faces.offset += size * (c.real_point(centre) - x);
        }
    if (faces.size > 0)
      faces.offset /= faces.size;
    return faces;
  }

  template SurfaceFaces<2>
  surface_faces(const GridCell<2> &,
                const Point<2> &,
                const unsigned int,
                const Shape<2> &,
                const double,
                const Tensor<1, 2> &);
  template SurfaceFaces<3>
  surface_faces(const GridCell<3> &,
                const Point<3> &,
                const unsigned int,
                const Shape<3> &,
                const double,
                const Tensor<1, 3> &);
} // namespace dealmpm
