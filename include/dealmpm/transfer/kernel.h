#pragma once

#include <dealmpm/transfer/quadratic_bspline.h>
#include <dealmpm/transfer/stencil.h>

#include <memory>
#include <string>

namespace dealmpm
{
  /** The particle-node weight functions a scene can choose. */
  enum class ShapeFunction
  {
    linear,
    uGIMP,
    cpGIMP,
    CPDI,
    quadratic_bspline
  };

  /** "linear|uGIMP|cpGIMP|CPDI|quadratic B-spline" */
  std::string
  shape_function_pattern();

  ShapeFunction
  parse_shape_function(const std::string &name);

  std::string
  to_string(ShapeFunction kind);

  /** GIMP and CPDI store each particle's initial domain half-lengths. */
  bool
  has_particle_domain(ShapeFunction kind);

  /**
   * The chosen shape function with the per-mesh data only it needs (cell
   * neighbours for GIMP and CPDI, the node blocks of the B-spline): no
   * kernel pays for another's.
   */
  template <int dim>
  class Kernel
  {
  public:
    /** Prepare for @p grid; returns what the grid lacks for this kernel
     * (empty when it suits). Collective; call again after mesh changes. */
    std::string
    setup(const ShapeFunction kind, BackgroundGrid<dim> &grid);

    void
    compute_stencil(const BackgroundGrid<dim> &grid,
                    const ParticleSet<dim>    &particles,
                    Stencil<dim>              &stencil) const;

    ShapeFunction
    kind() const
    {
      return shape_function;
    }

  private:
    ShapeFunction shape_function = ShapeFunction::linear;
    std::unique_ptr<QuadraticBSplineGrid<dim>> spline;
  };
} // namespace dealmpm
