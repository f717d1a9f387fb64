#include <dealmpm/transfer/kernel.h>
#include <dealmpm/transfer/lattice_blocks.h>
#include <dealmpm/transfer/quadratic_bspline.h>

#include <set>
#include <stdexcept>

namespace dealmpm
{
  namespace
  {
    template <int dim>
    class Linear : public ShapeFunction<dim>
    {
    public:
      std::string
      setup(BackgroundGrid<dim> &) override
      {
        return "";
      }

      void
      compute_stencil(const BackgroundGrid<dim> &grid,
                      const ParticleSet<dim>    &particles,
                      Stencil<dim>              &stencil) const override
      {
        compute_linear_stencil(grid, particles, stencil);
      }

      bool
      gradient_shrinks_with_weight() const override
      {
        return false;
      }
      /** Its weights exist wherever the particle is in the grid. */
      bool
      stencil_can_fail() const override
      {
        return false;
      }
    };

    /** GIMP and CPDI keep each particle's initial domain half-lengths. */
    template <int dim>
    class WithParticleDomain : public ShapeFunction<dim>
    {
    public:
      std::vector<FieldDescription>
      particle_fields() const override
      {
        return {{"domain_half_length", dim}};
      }
    };

    template <int dim>
    class GIMP : public WithParticleDomain<dim>
    {
    public:
      explicit GIMP(const bool follow_deformation)
        : follow_deformation(follow_deformation)
      {}

      std::string
      setup(BackgroundGrid<dim> &grid) override
      {
        if (!grid.cartesian)
          return "'linear' or 'CPDI' on this grid: GIMP needs cells that "
                 "are axis-aligned boxes (a rectangle grid, or such a mesh)";
        grid.find_neighbors();
        lattice.setup(grid);
        windows_fit =
          Utilities::MPI::min(lattice.windows_fit() ? 1 : 0, grid.comm) == 1;
        return "";
      }

      /** Its lattice where the sweeps can compute GIMP's weights on
       * three-node windows (GimpWindows), else nullptr. Whether the
       * domains fit them (cpGIMP's stretch) is domains_fit_windows(). */
      const LatticeBlocks<dim> *
      window_lattice() const
      {
        return windows_fit ? &lattice : nullptr;
      }

      void
      compute_stencil(const BackgroundGrid<dim> &grid,
                      const ParticleSet<dim>    &particles,
                      Stencil<dim>              &stencil) const override
      {
        compute_gimp_stencil(
          grid, particles, follow_deformation, stencil, &lattice);
      }

      /** Its weights exist wherever the particle is in the grid. */
      bool
      stencil_can_fail() const override
      {
        return false;
      }

      /** uGIMP's fixed domain keeps a node's gradient in proportion to its
       * weight; cpGIMP's shrinks with F's diagonal (to 1e-3 of a spacing),
       * and a squashed domain that has just crossed a row of nodes has
       * linear's full gradient 1/h on a sliver of weight: the fine granular
       * collapse's front grains turned inside out so at CFL 0.3. */
      bool
      gradient_shrinks_with_weight() const override
      {
        return !follow_deformation;
      }

    private:
      bool               follow_deformation;
      LatticeBlocks<dim> lattice;
      bool               windows_fit = false;
    };

    template <int dim>
    class CPDI : public WithParticleDomain<dim>
    {
    public:
      std::string
      setup(BackgroundGrid<dim> &grid) override
      {
        grid.find_neighbors();
        // Uniform patches sum the corners' values on their lattice, by
        // rows (cpdi_stencil.cc); other cells take the general path.
        lattice.setup(grid);
        return "";
      }

      void
      compute_stencil(const BackgroundGrid<dim> &grid,
                      const ParticleSet<dim>    &particles,
                      Stencil<dim>              &stencil) const override
      {
        compute_cpdi_stencil(grid, particles, stencil, &lattice);
      }

    private:
      LatticeBlocks<dim> lattice;
    };

    template <int dim>
    class QuadraticBSpline : public ShapeFunction<dim>
    {
    public:
      /** Its node pattern spans three equal cells: no hanging nodes. */
      bool
      needs_uniform_grid() const override
      {
        return true;
      }

      std::string
      setup(BackgroundGrid<dim> &grid) override
      {
        const std::string problem = QuadraticBSplineGrid<dim>::check(grid);
        if (!problem.empty())
          return "another shape function on this grid: the quadratic "
                 "B-spline needs " +
                 problem;
        grid.find_neighbors();
        spline = QuadraticBSplineGrid<dim>();
        spline.setup(grid);
        return "";
      }

      void
      compute_stencil(const BackgroundGrid<dim> &grid,
                      const ParticleSet<dim>    &particles,
                      Stencil<dim>              &stencil) const override
      {
        compute_bspline_stencil(grid, spline, particles, stencil);
      }

      /** Its weights exist wherever the particle is in the grid. */
      bool
      stencil_can_fail() const override
      {
        return false;
      }

      const QuadraticBSplineGrid<dim> &
      lattice() const
      {
        return spline;
      }

    private:
      QuadraticBSplineGrid<dim> spline;
    };

    template <int dim>
    ShapeFunctionRegistry<dim>
    built_in_shape_functions()
    {
      ShapeFunctionRegistry<dim> registry;
      registry.add("linear",
                   "the grid's Q1 functions at the particle; cheapest, but "
                   "noisy when particles cross cells.",
                   [] { return std::make_unique<Linear<dim>>(); });
      registry.add("uGIMP",
                   "the Q1 functions averaged over a fixed particle domain "
                   "of one particle spacing; needs axis-aligned box cells.",
                   [] { return std::make_unique<GIMP<dim>>(false); });
      registry.add("cpGIMP",
                   "as uGIMP, the domain stretching with F's diagonal.",
                   [] { return std::make_unique<GIMP<dim>>(true); });
      registry.add("CPDI",
                   "the domain is the parallelogram F maps it to; for large "
                   "shear and rotation, any quadrilateral grid.",
                   [] { return std::make_unique<CPDI<dim>>(); });
      registry.add("quadratic B-spline",
                   "smooth, 3^dim nodes per particle; a uniform box grid "
                   "without local refinement.",
                   [] { return std::make_unique<QuadraticBSpline<dim>>(); });
      return registry;
    }
  } // namespace

  template <int dim>
  ShapeFunctionRegistry<dim> &
  shape_function_registry()
  {
    static ShapeFunctionRegistry<dim> registry =
      built_in_shape_functions<dim>();
    return registry;
  }

  std::string
  shape_function_pattern()
  {
    std::set<std::string> names;
    for (const auto &n : shape_function_registry<2>().names())
      names.insert(n);
    for (const auto &n : shape_function_registry<3>().names())
      names.insert(n);
    std::string pattern;
    for (const auto &n : names)
      pattern += (pattern.empty() ? "" : "|") + n;
    return pattern;
  }

  std::string
  shape_function_documentation()
  {
    return "Particle-node weights: " + shape_function_registry<3>().describe() +
           "GIMP and CPDI add dim doubles per particle.";
  }

  template <int dim>
  std::string
  Kernel<dim>::setup(const std::string &name, BackgroundGrid<dim> &grid)
  {
    const ShapeFunctionRegistry<dim> &registry = shape_function_registry<dim>();
    if (!registry.has(name))
      return "one of " + registry.pattern() + " (no '" + name +
             "' is registered in " + std::to_string(dim) + "D)";
    chosen         = name;
    shape_function = registry.get(name).create();
    return shape_function->setup(grid);
  }

  template <int dim>
  const QuadraticBSplineGrid<dim> *
  Kernel<dim>::spline_grid() const
  {
    const auto *spline =
      dynamic_cast<const QuadraticBSpline<dim> *>(shape_function.get());
    return spline && spline->lattice().windows_fit() ? &spline->lattice() :
                                                       nullptr;
  }

  template <int dim>
  const LatticeBlocks<dim> *
  Kernel<dim>::gimp_lattice() const
  {
    const auto *gimp = dynamic_cast<const GIMP<dim> *>(shape_function.get());
    return gimp ? gimp->window_lattice() : nullptr;
  }

  template class Kernel<2>;
  template class Kernel<3>;
#define DEALMPM_INSTANTIATE(dim) \
  template ShapeFunctionRegistry<dim> &shape_function_registry();
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
