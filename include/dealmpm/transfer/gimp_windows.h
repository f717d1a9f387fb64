#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/lattice_blocks.h>
#include <dealmpm/transfer/lattice_weights.h>

#include <algorithm>

namespace dealmpm
{
  /**
   * uGIMP's weights on fixed windows of three nodes a direction (NodeWindow,
   * read by WindowWeights as the quadratic B-spline's are), computed where
   * the sweeps use them instead of stored (Stencil::where_used). They are
   * the stored stencil's numbers (compute_gimp_stencil()) to round-off:
   * the integrals of the hats over the particle domain, over the covered
   * length where the domain reaches past the grid.
   *
   * Needs a lattice block in every owned cell whose missing cells are whole
   * rows (LatticeBlocks::windows_fit(): the covered part of a domain is
   * then a box, and its weights products of 1D ones) and every domain's
   * half-length at most half its cell's edge (domains_fit_windows(): a
   * domain then touches three nodes a direction at most).
   */
  template <int dim>
  struct GimpWindows
  {
    const LatticeBlocks<dim> *lattice = nullptr;
    /** The particles' domain_half_length (CoreFields). */
    unsigned int half_length = numbers::invalid_unsigned_int;

    /** The 1D windows @p w of particle @p p in owned cell @p c (index @p i
     * in grid.cells), from its reference location (MUSL's re-map and stress
     * update compute them after the particle moved); returns the cell's
     * lattice block. */
    template <typename Particle>
    DEAL_II_ALWAYS_INLINE const unsigned int *
    windows_at(const unsigned int   i,
               const Particle      &p,
               const GridCell<dim> &c,
               NodeWindow          *w) const
    {
      const Point<dim>      &xi      = p.get_reference_location();
      const auto             props   = p.get_properties();
      const std::uint32_t    present = lattice->cells_present(i);
      constexpr unsigned int level   = dim == 2 ? 4 : 13; // sides 1, 1 (, 1)
      unsigned int           step    = 1;                 // 3^d
      for (unsigned int d = 0; d < dim; ++d, step *= 3)
        window_1d(xi[d],
                  props[half_length + d] * c.inverse_jacobian[d][d],
                  (present >> (level - step)) & 1u,
                  (present >> (level + step)) & 1u,
                  c.inverse_jacobian[d][d],
                  d == 0,
                  w[d]);
      return lattice->of(i);
    }

    /**
     * The window along one direction of a domain of half-length @p lambda
     * (in cell lengths) about unit-cell coordinate @p s, in a cell with
     * (@p below, @p above) or without a neighbour on each side. The three
     * nodes are the nearest one and its neighbours; with lambda <= 1/2 the
     * domain lies between them. Relative to the nearest node, it is [lo,
     * hi], clipped at the grid's edge, and splits at the node (p) into a
     * part under the lower neighbour's hat (-y) and one under the upper's
     * (y). A domain inside its cell weights the cell's two nodes only: the
     * window's third node is padding, visited only @p along_x.
     */
    static DEAL_II_ALWAYS_INLINE void
    window_1d(const double s,
              const double lambda,
              const bool   below,
              const bool   above,
              const double inverse_h,
              const bool   along_x,
              NodeWindow  &w)
    {
      const bool   upper = s >= 0.5; // the nearest node is the cell's upper
      const double r     = upper ? s - 1. : s;
      double       lo = r - lambda, hi = r + lambda;
      if (!upper && !below)
        lo = std::max(lo, 0.);
      if (upper && !above)
        hi = std::min(hi, 0.);
      const double p         = std::min(std::max(lo, 0.), hi);
      const double to_length = 1. / (hi - lo);
      const double to_slope  = to_length * inverse_h;
      const double v0        = 0.5 * (lo * lo - p * p) * to_length,
                   v2        = 0.5 * (hi * hi - p * p) * to_length;
      const double g0 = (lo - p) * to_slope, g2 = (hi - p) * to_slope;
      const double v1 = 1. - v0 - v2, g1 = -(g0 + g2);
      // A domain that reaches a trillionth of a cell past its cell's face
      // (a particle a quarter cell from it, by round-off) has a weight of
      // 1e-24 there: left out, so that the particle keeps two nodes.
      constexpr double past = 1e-12;
      if (upper ? hi > past : lo < -past)
        {
          w.first  = upper ? 1 : 0;
          w.padded = 3;
          w.rows   = 3;
          set(w, v0, v1, v2, g0, g1, g2);
          return;
        }
      const double lower_value = upper ? v0 : v1, upper_value = upper ? v1 : v2;
      const double lower_slope = upper ? g0 : g1, upper_slope = upper ? g1 : g2;
      if (along_x && !above)
        {
          // Padded below: the node above the cell's does not exist.
          w.first  = 0;
          w.padded = 0;
          w.rows   = 3;
          set(w, 0., lower_value, upper_value, 0., lower_slope, upper_slope);
        }
      else
        {
          w.first  = 1;
          w.padded = 2;
          w.rows   = 2;
          set(w, lower_value, upper_value, 0., lower_slope, upper_slope, 0.);
        }
    }

  private:
    static DEAL_II_ALWAYS_INLINE void
    set(NodeWindow  &w,
        const double v0,
        const double v1,
        const double v2,
        const double g0,
        const double g1,
        const double g2)
    {
      w.value[0] = v0;
      w.value[1] = v1;
      w.value[2] = v2;
      w.slope[0] = g0;
      w.slope[1] = g1;
      w.slope[2] = g2;
    }
  };

  /** Whether every locally owned particle's domain half-length is at most
   * half its cell's edge in every direction, on all ranks (GimpWindows).
   * Collective. */
  template <int dim>
  bool
  domains_fit_windows(const BackgroundGrid<dim> &grid,
                      const ParticleSet<dim>    &particles);
} // namespace dealmpm
