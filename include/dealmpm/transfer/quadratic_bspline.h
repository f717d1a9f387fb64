#pragma once

#include <dealmpm/transfer/lattice_weights.h>
#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stencil_order.h>

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

    /** Whether every direction has two cells or more: then the windows'
     * padded nodes exist and WindowWeights can be used. */
    bool
    windows_fit() const
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (n_cells[d] < 2)
          return false;
      return true;
    }

    /** The 1D windows @p w of a particle at unit-cell point @p xi of owned
     * cell @p i, on the cell's lattice block (block_nodes). From the
     * reference location, not the position: MUSL's re-map and stress
     * update compute them after the particle moved (Stencil::where_used).
     * Needs windows_fit(). */
    DEAL_II_ALWAYS_INLINE void
    windows_at(const unsigned int i, const Point<dim> &xi, NodeWindow *w) const
    {
      for (unsigned int d = 0; d < dim; ++d)
        window_1d(xi[d], lower_index[i][d], n_cells[d] - 1, inverse_h[d], w[d]);
    }

    /** The same weights as windows_at() without the padded nodes, for the
     * stored stencil. */
    void
    weights_at(const unsigned int i,
               const Point<dim>  &xi,
               LatticeWeights1D  *w) const
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          NodeWindow s;
          window_1d(xi[d], lower_index[i][d], n_cells[d] - 1, inverse_h[d], s);
          w[d].first = s.first + (s.padded == 0 ? 1 : 0);
          w[d].count = s.padded == 3 ? 3 : 2;
          for (unsigned int k = 0; k < 3; ++k)
            if (k != s.padded)
              {
                w[d].value[s.first + k] = s.value[k];
                w[d].slope[s.first + k] = s.slope[k];
              }
        }
    }

    Point<dim>                        origin;
    Tensor<1, dim>                    h;
    Tensor<1, dim>                    inverse_h;
    std::array<int, dim>              n_cells;
    std::vector<std::array<int, dim>> lower_index;
    std::vector<unsigned int>         block_nodes; ///< cells x 4^dim

  private:
    /**
     * The window along one direction of a particle at unit-cell coordinate
     * @p s (0 to 1, to round-off) in the cell whose lower node is J, the
     * grid's last cell along it being @p last, on that cell's 4-node block
     * of cell length 1 / @p inverse_h. The half of its cell that the
     * particle is in decides its nearest node and whether it is in a half
     * cell next to a boundary: taken from s itself, not from the grid
     * coordinate J + s, which costs a conversion and, far from the origin,
     * the low bits of s.
     */
    static DEAL_II_ALWAYS_INLINE void
    window_1d(const double s,
              const int    J,
              const int    last,
              const double inverse_h,
              NodeWindow  &w)
    {
      const bool upper_half = s >= 0.5;
      if (upper_half ? J == last : J == 0)
        {
          // The half cell next to a boundary: linear hats on nodes J and
          // J + 1 (positions 1 and 2).
          const bool lower = !upper_half;
          w.first          = lower ? 1 : 0;
          w.padded         = lower ? 2 : 0;
          w.rows           = 3;
          double *v = w.value + (lower ? 0 : 1), *g = w.slope + (lower ? 0 : 1);
          w.value[w.padded] = 0;
          w.slope[w.padded] = 0;
          v[0]              = 1. - s;
          v[1]              = s;
          g[0]              = -inverse_h;
          g[1]              = inverse_h;
          return;
        }
      // The splines of the nearest node (the cell's lower one, or its upper
      // one: r = s - 1 is exact there) and its two neighbours at r in
      // [-1/2, 1/2), written out: the same numbers as by each node's
      // distance, without a branch per node.
      const double r     = upper_half ? s - 1. : s;
      const double below = 0.5 - r, above = 0.5 + r;
      w.first    = upper_half ? 1 : 0;
      w.padded   = 3;
      w.rows     = 3;
      w.value[0] = 0.5 * below * below;
      w.value[1] = 0.75 - r * r;
      w.value[2] = 0.5 * above * above;
      w.slope[0] = -below * inverse_h;
      w.slope[1] = -2. * r * inverse_h;
      w.slope[2] = above * inverse_h;
    }
  };

  template <int dim>
  void
  compute_bspline_stencil(const BackgroundGrid<dim>       &grid,
                          const QuadraticBSplineGrid<dim> &spline,
                          const ParticleSet<dim>          &particles,
                          Stencil<dim>                    &stencil);
} // namespace dealmpm
