#include <deal.II/base/exceptions.h>

#include <dealmpm/transfer/kernel.h>

namespace dealmpm
{
  namespace
  {
    const std::pair<ShapeFunction, const char *> names[] = {
      {ShapeFunction::linear, "linear"},
      {ShapeFunction::uGIMP, "uGIMP"},
      {ShapeFunction::cpGIMP, "cpGIMP"},
      {ShapeFunction::CPDI, "CPDI"},
      {ShapeFunction::quadratic_bspline, "quadratic B-spline"}};
  } // namespace

  std::string
  shape_function_pattern()
  {
    std::string pattern;
    for (const auto &[kind, name] : names)
      pattern += (pattern.empty() ? "" : "|") + std::string(name);
    return pattern;
  }

  ShapeFunction
  parse_shape_function(const std::string &name)
  {
    for (const auto &[kind, n] : names)
      if (name == n)
        return kind;
    AssertThrow(false, ExcMessage("unknown shape function '" + name + "'"));
    return ShapeFunction::linear;
  }

  std::string
  to_string(const ShapeFunction kind)
  {
    for (const auto &[k, name] : names)
      if (k == kind)
        return name;
    return "?";
  }

  bool
  has_particle_domain(const ShapeFunction kind)
  {
    return kind == ShapeFunction::uGIMP || kind == ShapeFunction::cpGIMP ||
           kind == ShapeFunction::CPDI;
  }

  template <int dim>
  std::string
  Kernel<dim>::setup(const ShapeFunction kind, BackgroundGrid<dim> &grid)
  {
    shape_function = kind;
    spline.reset();
    switch (kind)
      {
        case ShapeFunction::linear:
          return "";
        case ShapeFunction::uGIMP:
        case ShapeFunction::cpGIMP:
          if (!grid.cartesian)
            return "'linear' or 'CPDI' on this grid: GIMP needs cells that "
                   "are axis-aligned boxes (a rectangle grid, or such a mesh)";
          grid.find_neighbors();
          return "";
        case ShapeFunction::CPDI:
          grid.find_neighbors();
          return "";
          case ShapeFunction::quadratic_bspline: {
            const std::string problem = QuadraticBSplineGrid<dim>::check(grid);
            if (!problem.empty())
              return "another shape function on this grid: the quadratic "
                     "B-spline needs " +
                     problem;
            grid.find_neighbors();
            spline = std::make_unique<QuadraticBSplineGrid<dim>>();
            spline->setup(grid);
            return "";
          }
      }
    return "";
  }

  template <int dim>
  void
  Kernel<dim>::compute_stencil(const BackgroundGrid<dim> &grid,
                               const ParticleSet<dim>    &particles,
                               Stencil<dim>              &stencil) const
  {
    stencil.failed = false;
    switch (shape_function)
      {
        case ShapeFunction::linear:
          compute_linear_stencil(grid, particles, stencil);
          break;
        case ShapeFunction::uGIMP:
        case ShapeFunction::cpGIMP:
          compute_gimp_stencil(grid,
                               particles,
                               shape_function == ShapeFunction::cpGIMP,
                               stencil);
          break;
        case ShapeFunction::CPDI:
          compute_cpdi_stencil(grid, particles, stencil);
          break;
        case ShapeFunction::quadratic_bspline:
          compute_bspline_stencil(grid, *spline, particles, stencil);
          break;
      }
  }

  template class Kernel<2>;
  template class Kernel<3>;
} // namespace dealmpm
