#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>
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
   * round-off). Not for APIC (its re-map adds the affine part) nor
   * per-body fields (contact).
   *
   * Zeroes the fields' mass and momentum when made; finish() sums them
   * over the ranks. The sweep must not read them (G2P reads only the
   * velocity and its increment).
   */
  template <int dim>
  struct RemapInSweep
  {
    using Sums = BoxCellSums<dim, true, false>;
    NodalFields<dim> &fields;
    double           *mass;
    double           *momentum[dim];

    explicit RemapInSweep(NodalFields<dim> &to)
      : fields(to)
      , mass(to.mass.begin())
    {
      fields.mass = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          fields.momentum[d] = 0.;
          momentum[d]        = fields.momentum[d].begin();
        }
    }

    /** Add particle @p p of mass @p m and updated velocity @p v with
     * @p weights (before the sweep moves it): into @p sums with
     * BoxWeights. */
    template <typename Weights, typename Particle>
    DEAL_II_ALWAYS_INLINE void
    add(const Weights        &weights,
        const std::size_t     k,
        const Particle       &p,
        const GridCell<dim>  &c,
        const double          m,
        const Tensor<1, dim> &v,
        Sums                 &sums) const
    {
      if constexpr (std::is_same_v<Weights, g2p_sweep::BoxWeights<dim>>)
        {
          const double no_stress[dim][dim] = {};
          sums.add(m, v, no_stress, p.get_reference_location());
        }
      else
        weights(k,
                p,
                c,
                [&](const unsigned int n,
                    const double       N,
                    const Tensor<1, dim> &) DEAL_II_ALWAYS_INLINE {
                  const double mN = m * N;
                  mass[n] += mN;
                  for (unsigned int d = 0; d < dim; ++d)
                    momentum[d][n] += mN * v[d];
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

    /** Sum the re-mapped mass and momentum over the ranks. */
    void
    finish()
    {
      fields.mass.compress(VectorOperation::add);
      for (unsigned int d = 0; d < dim; ++d)
        fields.momentum[d].compress(VectorOperation::add);
    }
  };
} // namespace dealmpm
