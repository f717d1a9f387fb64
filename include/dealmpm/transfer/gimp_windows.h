#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/lattice_blocks.h>
#include <dealmpm/transfer/lattice_weights.h>

#include <algorithm>

namespace dealmpm
{
  /** A cpGIMP domain's half-length along @p d: the particle's
   * domain_half_length (at @p half_length in @p props) stretched by F_dd,
   * to 1e-3 of it at least, as compute_gimp_stencil() stretches it. */
  template <int dim, typename Properties>
  DEAL_II_ALWAYS_INLINE inline double
  stretched_half_length(const Properties  &props,
                        const unsigned int half_length,
                        const unsigned int d)
  {
    return props[half_length + d] *
           std::max(props[FixedCore<dim>::deformation_gradient + d * dim + d],
                    1e-3);
  }

  /**
   * GIMP's weights on fixed windows of three nodes a direction (NodeWindow,
   * read by WindowWeights as the quadratic B-spline's are), computed where
   * the sweeps use them instead of stored (Stencil::where_used). They are
   * the stored stencil's numbers (compute_gimp_stencil()) to round-off:
   * the integrals of the hats over the particle domain, over the covered
   * length where the domain reaches past the grid. uGIMP's domain keeps
   * its half-lengths; cpGIMP's (@p follows_deformation) are stretched by
   * F's diagonal as the stored stencil stretches them.
   *
   * Needs a lattice block in every owned cell whose missing cells are whole
   * rows (LatticeBlocks::windows_fit(): the covered part of a domain is
   * then a box, and its weights products of 1D ones) and every domain's
   * half-length at most half its cell's edge (domains_fit_windows(): a
   * domain then touches three nodes a direction at most; cpGIMP's
   * stretching domains are checked again every step, Stencil::
   * gimp_follows_deformation).
   */
  template <int dim>
  struct GimpWindows
  {
    const LatticeBlocks<dim> *lattice = nullptr;
    /** The particles' domain_half_length (CoreFields). */
    unsigned int half_length = numbers::invalid_unsigned_int;
    /** cpGIMP: the half-lengths stretch with F's diagonal. */
    bool follows_deformation = false;

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
      const Point<dim>   &xi      = p.get_reference_location();
      const auto          props   = p.get_properties();
      const std::uint32_t present = lattice->cells_present(i);
      // One test a particle, not one a direction.
      double lambda[dim];
      if (follows_deformation)
        for (unsigned int d = 0; d < dim; ++d)
          lambda[d] = stretched_half_length<dim>(props, half_length, d) *
                      c.inverse_jacobian[d][d];
      else
        for (unsigned int d = 0; d < dim; ++d)
          lambda[d] = props[half_length + d] * c.inverse_jacobian[d][d];
      // The directions written out: the neighbours' bits at constant
      // shifts (a loop kept them at run time, a sixth of the windows'
      // cost).
      const auto along = [&](const auto direction) DEAL_II_ALWAYS_INLINE {
        constexpr unsigned int level = dim == 2 ? 4 : 13; // sides 1, 1 (, 1)
        constexpr unsigned int n     = decltype(direction)::value;
        constexpr unsigned int step  = n == 0 ? 1 : n == 1 ? 3 : 9; // 3^d
        window_1d(xi[n],
                  lambda[n],
                  (present >> (level - step)) & 1u,
                  (present >> (level + step)) & 1u,
                  c.inverse_jacobian[n][n],
                  w[n]);
      };
      along(std::integral_constant<unsigned int, 0>());
      along(std::integral_constant<unsigned int, 1>());
      if constexpr (dim == 3)
        along(std::integral_constant<unsigned int, 2>());
      return lattice->of(i);
    }

    /**
     * The window along one direction of a domain of half-length @p lambda
     * (in cell lengths, at most 1/2) about unit-cell coordinate @p s, in a
     * cell with (@p below, @p above) or without a neighbour on each side.
     * The domain [a, b] = [s - lambda, s + lambda] lies in the cell, or
     * reaches into one neighbour: then it weights that neighbour's node
     * too. A domain inside its cell, or clipped at the grid's edge to the
     * part inside it, averages the cell's two hats: linear weights at its
     * centre, on a window of two nodes (the cell's).
     */
    static DEAL_II_ALWAYS_INLINE void
    window_1d(const double s,
              const double lambda,
              const bool   below,
              const bool   above,
              const double inverse_h,
              NodeWindow  &w)
    {
      // A domain that reaches a trillionth of a cell past its cell's face
      // (a particle a quarter cell from it, by round-off) would weight the
      // node beyond by 1e-24: left out, so that the particle keeps two
      // nodes.
      constexpr double past = 1e-12;
      const double     a = s - lambda, b = s + lambda;
      double           centre = s;
      if (a < -past && below)
        {
          // Nodes below, at and above the cell's lower node (hats -y, 1 - |y|
          // and y about it) share the domain [a, b] of length 2 lambda.
          const double to_value = 0.25 / lambda,
                       to_slope = 2. * to_value * inverse_h;
          three_nodes(w, 0, a, b, to_value, to_slope);
          return;
        }
      if (b > 1. + past && above)
        {
          const double to_value = 0.25 / lambda,
                       to_slope = 2. * to_value * inverse_h;
          three_nodes(w, 1, a - 1., b - 1., to_value, to_slope);
          return;
        }
      if (a < 0. && !below)
        centre = 0.5 * b; // [0, b]: clipped at the grid's lower edge
      else if (b > 1. && !above)
        centre = 0.5 * (a + 1.);
      // The window's third entries are not read (rows = 2).
      w.first    = 1;
      w.rows     = 2;
      w.value[0] = 1. - centre;
      w.value[1] = centre;
      w.slope[0] = -inverse_h;
      w.slope[1] = inverse_h;
    }

    /** Particle @p props' domain half-length along @p d (cpGIMP's
     * stretched: stretched_half_length()). */
    template <typename Properties>
    DEAL_II_ALWAYS_INLINE double
    half_length_of(const Properties &props, const unsigned int d) const
    {
      return follows_deformation ?
               stretched_half_length<dim>(props, half_length, d) :
               props[half_length + d];
    }

  private:
    /** The window of nodes first .. first + 2 of a domain [lo, hi] about
     * the middle one, which splits at it into a part under the lower
     * node's hat (-y) and one under the upper's (y). */
    static DEAL_II_ALWAYS_INLINE void
    three_nodes(NodeWindow        &w,
                const unsigned int first,
                const double       lo,
                const double       hi,
                const double       to_value,
                const double       to_slope)
    {
      const double v0 = lo * lo * to_value, v2 = hi * hi * to_value;
      const double g0 = lo * to_slope, g2 = hi * to_slope;
      w.first = first;
      w.rows  = 3;
      set(w, v0, 1. - v0 - v2, v2, g0, -(g0 + g2), g2);
    }

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

  /** Whether every locally owned particle's domain half-length (stretched
   * by F's diagonal if @p follows_deformation: cpGIMP) is at most half its
   * cell's edge in every direction, on all ranks (GimpWindows).
   * Collective. */
  template <int dim>
  bool
  domains_fit_windows(const BackgroundGrid<dim> &grid,
                      const ParticleSet<dim>    &particles,
                      const bool                 follows_deformation = false);

  /** The largest domain half-length along each direction that fits the
   * windows in every cell of the grid: half its shortest edge along that
   * direction, over all ranks (Stencil::gimp_stretch_limit). Collective. */
  template <int dim>
  Tensor<1, dim>
  gimp_stretch_limit(const BackgroundGrid<dim> &grid);
} // namespace dealmpm
