#pragma once

#include <dealmpm/transfer/stencil.h>

#include <array>
#include <string>
#include <vector>

namespace dealmpm
{
  /**
   * What the quadratic B-spline kernel needs of a uniform box grid: per
   * locally owned cell the 4^dim nodes of the 3^dim block of cells around it
   * (each particle uses 3 of the 4 per direction), and the structured index
   * of its lower vertex. Built once per mesh.
   *
   * The 1D functions are the uniform quadratic B-splines centred on the
   * nodes, except in the half cell next to each boundary, where the two
   * nearest nodes' linear hats take over (Steffen, Kirby and Berzins 2008):
   * they still sum to one, reproduce linear fields and are C1 across x = h/2.
   */
  template <int dim>
  struct QuadraticBSplineGrid
  {
    static constexpr unsigned int block_size = Utilities::pow(4, dim);

    /** Empty when the grid is one box of equal axis-aligned cells without
     * hanging nodes, else what is wrong with it. Collective. */
    static std::string
    check(const BackgroundGrid<dim> &grid);

    /** Needs check() to have passed and grid.find_neighbors(). */
    void
    setup(const BackgroundGrid<dim> &grid);

    Point<dim>                        origin;
    Tensor<1, dim>                    h;
    std::array<int, dim>              n_cells;
    std::vector<std::array<int, dim>> lower_index;
    std::vector<unsigned int>         block_nodes; ///< cells x 4^dim
  };

  template <int dim>
  void
  compute_bspline_stencil(const BackgroundGrid<dim>       &grid,
                          const QuadraticBSplineGrid<dim> &spline,
                          const ParticleSet<dim>          &particles,
                          Stencil<dim>                    &stencil);
} // namespace dealmpm
