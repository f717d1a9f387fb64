#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_exchange.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/affine_transfer.h>
#include <dealmpm/transfer/box_q1.h>

#include <type_traits>

namespace dealmpm
{
  namespace g2p_sweep
  {
    /** The weights of a box cell's sweep (grid_to_particle.h). */
    template <int dim>
    struct BoxWeights;
  } // namespace g2p_sweep

  /** A G2P sweep without a re-map (all but MUSL's motion). */
  struct NoRemap
  {
    struct Sums
    {};

    template <typename... Args>
    void
    add(const Args &...) const
    {}

    template <typename... Args>
    void
    end_box_cell(const Args &...) const
    {}
  };

  /**
   * MUSL's re-map of mass and momentum made in its G2P motion sweep, from
   * each particle's updated velocity and the weights at the step's start
   * that the sweep holds anyway: the sums particle_to_grid() (mass and
   * momentum only) makes after the sweep, without that second pass over
   * the particles. A box cell's particles are summed in BoxCellSums (the
   * sweep's local Sums) and added once at the cell's end, as P2G does (the
   * same numbers); the particles of other cells add into the nodal vectors
   * directly (P2G sums a non-box cell in locals first: equal to
   * round-off). With APIC (@p affine: the particles carry B) each node gets
   * m N_i (v + C (x_i - x_p)), C = B D^-1 at the step's start (the
   * particle's position before the sweep moves it; in a box cell
   * BoxCellSums::add_affine()). Not for per-body fields (contact).
   *
   * Zeroes the fields' mass and momentum when made; finish() sums them
   * over the ranks. The sweep must not read them (G2P reads only the
   * velocity and its increment).
   *
   * With @p keep_mass the fields' mass stays P2G's, the re-map's own mass
   * of the same particles with the same weights: in box cells the same
   * numbers (the same BoxCellSums in the same order), elsewhere equal to
   * round-off. Only where nothing else put mass into the nodes (a bonded
   * FE region does). The 2D column under MUSL: 494 -> 483 instructions
   * per particle-step, 3D 1,028 -> 1,011; chosen at run time (the sums
   * kept, the mass not added) it saved a third of that.
   */
  template <int dim, bool affine = false, bool keep_mass = false>
  struct RemapInSweep
  {
    using Sums = BoxCellSums<dim, true, false, !keep_mass>;
    NodalFields<dim>          &fields;
    const BackgroundGrid<dim> &grid;
    /** The mass the re-map adds into; nullptr with keep_mass. */
    double *mass;
    double *momentum[dim];

    RemapInSweep(NodalFields<dim> &to, const BackgroundGrid<dim> &grid)
      : fields(to)
      , grid(grid)
      , mass(keep_mass ? nullptr : to.mass.begin())
    {
      if (!keep_mass)
        fields.mass = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          fields.momentum[d] = 0.;
          momentum[d]        = fields.momentum[d].begin();
        }
    }

    /** Add particle @p p with its updated velocity @p v and (APIC) affine
     * moment @p B with @p weights (before the sweep moves it): into
     * @p sums with BoxWeights. */
    template <typename Weights, typename Particle>
    DEAL_II_ALWAYS_INLINE void
    add(const Weights        &weights,
        const std::size_t     k,
        const Particle       &p,
        const GridCell<dim>  &c,
        const Tensor<1, dim> &v,
        const Tensor<2, dim> &B,
        Sums                 &sums) const
    {
      const double m = p.get_properties()[FixedCore<dim>::mass];
      if constexpr (std::is_same_v<Weights, g2p_sweep::BoxWeights<dim>>)
        {
          const double      no_stress[dim][dim] = {};
          const Point<dim> &xi                  = p.get_reference_location();
          if constexpr (affine)
            {
              double g[dim][dim];
              box_affine_unit_gradient(B, xi, c.inverse_jacobian, g);
              sums.add_affine(m, v, g, no_stress, xi);
            }
          else
            sums.add(m, v, no_stress, xi);
          return;
        }
      const Point<dim> x_p = p.get_location();
      Tensor<2, dim>   C;
      if constexpr (affine)
        C = affine_velocity_gradient(grid, weights, k, p, c, x_p, B);
      weights(k,
              p,
              c,
              [&](const unsigned int n, const double N, const Tensor<1, dim> &)
                DEAL_II_ALWAYS_INLINE {
                  const double         mN = m * N;
                  const Tensor<1, dim> v_n =
                    affine ? v + C * (grid.node_positions[n] - x_p) : v;
                  if (!keep_mass)
                    mass[n] += mN;
                  for (unsigned int d = 0; d < dim; ++d)
                    momentum[d][n] += mN * v_n[d];
                });
    }

    /** Add a box cell's @p sums at its @p nodes. */
    DEAL_II_ALWAYS_INLINE void
    end_box_cell(const GridCell<dim>      &c,
                 const unsigned int *const nodes,
                 const Sums               &sums) const
    {
      sums.scatter(c.inverse_jacobian, nodes, *this);
    }

    /** Sum the re-mapped momentum (and mass) over the ranks. */
    void
    finish()
    {
      NodalExchange sums;
      if (!keep_mass)
        sums.add(fields.mass);
      sums.add(fields.momentum).sum_ghosts_into_owners();
    }
  };
} // namespace dealmpm
