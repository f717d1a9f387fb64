#include <dealmpm/particles/surface_area.h>

namespace dealmpm
{
  template <int dim>
  SurfaceFaces<dim>
  surface_faces(const GridCell<dim> &c,
                const Point<dim>    &xi,
                const unsigned int   n,
                const Shape<dim>    &shape,
                const double         volume)
  {
    const Tensor<2, dim> inverse_jacobian = c.inverse_jacobian_at(xi);
    const Point<dim>     x                = c.real_point(xi);
    SurfaceFaces<dim>    faces;
    double               total_area = 0;
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
          Point<dim> centre = xi;
          centre[d] += 0.5 * side / n;
          faces.area += area;
          faces.offset += area.norm() * (c.real_point(centre) - x);
          total_area += area.norm();
        }
    if (total_area > 0)
      faces.offset /= total_area;
    return faces;
  }

  template SurfaceFaces<2>
  surface_faces(const GridCell<2> &,
                const Point<2> &,
                const unsigned int,
                const Shape<2> &,
                const double);
  template SurfaceFaces<3>
  surface_faces(const GridCell<3> &,
                const Point<3> &,
                const unsigned int,
                const Shape<3> &,
                const double);
} // namespace dealmpm
