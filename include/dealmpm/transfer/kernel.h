#pragma once

#include <dealmpm/base/registry.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/stencil.h>

#include <memory>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * A particle-node weight function ('MPM/Shape function'): it prepares
   * the per-mesh data only it needs and computes every particle's stencil
   * (nodes, weights, gradients). The built-in ones (linear, uGIMP, cpGIMP,
   * CPDI, quadratic B-spline) are registered in shape_function_registry();
   * a user registers another from C++ before the scene is read.
   */
  template <int dim>
  class ShapeFunction
  {
  public:
    virtual ~ShapeFunction() = default;

    /** Prepare for @p grid; returns what the grid lacks for this shape
     * function (empty when it suits), as "<what to use instead>: <why>".
     * Collective; called again after the grid changes. */
    virtual std::string
    setup(BackgroundGrid<dim> &grid) = 0;

    virtual void
    compute_stencil(const BackgroundGrid<dim> &grid,
                    const ParticleSet<dim>    &particles,
                    Stencil<dim>              &stencil) const = 0;

    /** Whether it needs a grid of equal cells (then adaptivity, whose
     * refined cells make hanging nodes, cannot run with it). */
    virtual bool
    needs_uniform_grid() const
    {
      return false;
    }

    /** Whether a node's gradient at a particle shrinks with its weight
     * there, as it does for every shape function smoother than linear: if
     * not, a node a particle has just reached has a full gradient on a
     * sliver of mass, and USL weights that node's increment
     * (stable_nodal_mass()). */
    virtual bool
    gradient_shrinks_with_weight() const
    {
      return true;
    }

    /** Whether compute_stencil() can fail for a particle (Stencil::failed):
     * then each step's stencil costs a reduction, so that all ranks stop
     * together. A shape function that never fails says so and saves it. */
    virtual bool
    stencil_can_fail() const
    {
      return true;
    }

    /** Per-particle fields it stores (GIMP and CPDI: the particle domain's
     * initial half-lengths, "domain_half_length"). */
    virtual std::vector<FieldDescription>
    particle_fields() const
    {
      return {};
    }
  };

  template <int dim>
  using ShapeFunctionRegistry =
    Registry<ShapeFunction<dim>, std::unique_ptr<ShapeFunction<dim>>()>;

  /** The shape functions a scene can name, built-in ones first. */
  template <int dim>
  ShapeFunctionRegistry<dim> &
  shape_function_registry();

  /** "a|b|c": the names registered in 2D or 3D, for the parameter's
   * pattern. */
  std::string
  shape_function_pattern();

  /** What each registered shape function does, for the documentation. */
  std::string
  shape_function_documentation();

  /** The scene's shape function, set up for the grid. */
  template <int dim>
  class Kernel
  {
  public:
    /** Choose the shape function registered as @p name and prepare it for
     * @p grid; returns what the grid lacks for it (empty when it suits).
     * Collective. */
    std::string
    setup(const std::string &name, BackgroundGrid<dim> &grid);

    /** Prepare again after the grid changed (collective). */
    std::string
    rebuild(BackgroundGrid<dim> &grid)
    {
      return shape_function->setup(grid);
    }

    void
    compute_stencil(const BackgroundGrid<dim> &grid,
                    const ParticleSet<dim>    &particles,
                    Stencil<dim>              &stencil) const
    {
      stencil.failed = false;
      // The sweeps compute the weights themselves (LinearWeights,
      // WindowWeights).
      if (stencil.where_used)
        return;
      shape_function->compute_stencil(grid, particles, stencil);
    }

    const std::string &
    name() const
    {
      return chosen;
    }

    /** The quadratic B-spline's lattice if that is the shape function and
     * the sweeps can compute its weights where they use them
     * (WindowWeights, as they do linear ones: every direction has two
     * cells or more), else nullptr. */
    const QuadraticBSplineGrid<dim> *
    spline_grid() const;

    /** GIMP's lattice if that is the shape function (uGIMP or cpGIMP) and the
     * sweeps can compute its weights where they use them on this grid
     * (GimpWindows: LatticeBlocks::windows_fit() on every rank), else nullptr.
     * Whether the particles' domains fit too is domains_fit_windows(). */
    const LatticeBlocks<dim> *
    gimp_lattice() const;

    std::vector<FieldDescription>
    particle_fields() const
    {
      return shape_function->particle_fields();
    }

    bool
    gradient_shrinks_with_weight() const
    {
      return shape_function->gradient_shrinks_with_weight();
    }

    bool
    stencil_can_fail() const
    {
      return shape_function->stencil_can_fail();
    }

  private:
    std::string                         chosen;
    std::unique_ptr<ShapeFunction<dim>> shape_function;
  };
} // namespace dealmpm
