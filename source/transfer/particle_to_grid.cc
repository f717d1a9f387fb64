#include <dealmpm/grid/nodal_exchange.h>
#include <dealmpm/transfer/affine_transfer.h>
#include <dealmpm/transfer/box_q1.h>
#include <dealmpm/transfer/particle_to_grid.h>
#include <dealmpm/transfer/particle_weights.h>
#include <dealmpm/transfer/stencil_order.h>

#include <type_traits>
#include <vector>

#include "p2g_rows.h"
#include "p2g_targets.h"

namespace dealmpm
{
  namespace
  {
    /** -V_p sigma_p (updated Lagrangian), or -V_p0 P_p = -V_p sigma_p
     * F_p^-T (total Lagrangian, whose stencil holds reference gradients):
     * the particle's internal force on a node is this times grad N. */
    template <bool total_lagrangian, int dim>
    DEAL_II_ALWAYS_INLINE inline auto
    force_per_gradient(const ArrayView<const double> &props)
    {
      const Tensor<2, dim> F =
        read_tensor<dim>(&props[FixedCore<dim>::deformation_gradient]);
      const SymmetricTensor<2, dim> minus_V_sigma =
        -determinant(F) * props[FixedCore<dim>::initial_volume] *
        read_symmetric<dim>(&props[FixedCore<dim>::stress]);
      if constexpr (total_lagrangian)
        return Tensor<2, dim>(minus_V_sigma * transpose(invert(F)));
      else
        return minus_V_sigma;
    }

    /** One cell's shares of mass, momentum and internal force in its
     * 2^dim nodes, summed in locals by vertex from any weights (a box
     * cell's: BoxCellSums). */
    template <int dim, bool mass_and_momentum, bool internal_force>
    struct CellSums
    {
      static constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
      double                        mass[n_vertices]          = {};
      double                        momentum[n_vertices][dim] = {};
      double                        force[n_vertices][dim]    = {};

      /** What a particle brings: m, v and -V sigma as a plain array
       * (deal.II's symmetric tensor times a vector goes through accessor
       * objects: 17 instructions a node in 3D). */
      struct Shares
      {
        double         m;
        Tensor<1, dim> v;
        double         minus_V_sigma[dim][dim] = {};

        template <typename Particle>
        DEAL_II_ALWAYS_INLINE
        Shares(const Particle &p)
        {
          const ArrayView<const double> props = p.get_properties();
          m                                   = props[FixedCore<dim>::mass];
          v = read_vector<dim>(&props[FixedCore<dim>::velocity]);
          if (internal_force)
            {
              const SymmetricTensor<2, dim> S =
                force_per_gradient<false, dim>(props);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  minus_V_sigma[i][j] = S[i][j];
            }
        }
      };

      DEAL_II_ALWAYS_INLINE void
      add_mass_and_momentum(const unsigned int vertex,
                            const Shares      &p,
                            const double       N)
      {
        const double mN = p.m * N;
        mass[vertex] += mN;
        for (unsigned int d = 0; d < dim; ++d)
          momentum[vertex][d] += mN * p.v[d];
      }

      /** Add particle @p p's shares; @p weights_at(xi, f) hands out the
       * cell's weights at xi in vertex order. */
      template <typename Particle, typename WeightsAt>
      DEAL_II_ALWAYS_INLINE void
      add(const Particle &p, const WeightsAt &weights_at)
      {
        const Shares shares(p);
        unsigned int vertex = 0;
        weights_at(p.get_reference_location(),
                   [&](const unsigned int,
                       const double          N,
                       const Tensor<1, dim> &grad_N) DEAL_II_ALWAYS_INLINE {
                     if (mass_and_momentum)
                       add_mass_and_momentum(vertex, shares, N);
                     if (internal_force)
                       for (unsigned int d = 0; d < dim; ++d)
                         {
                           double fi = shares.minus_V_sigma[d][0] * grad_N[0];
                           for (unsigned int j = 1; j < dim; ++j)
                             fi += shares.minus_V_sigma[d][j] * grad_N[j];
                           force[vertex][d] += fi;
                         }
                     ++vertex;
                   });
      }

      /** Add the sums into the nodal vectors at the cell's @p nodes. */
      DEAL_II_ALWAYS_INLINE void
      scatter(const unsigned int *nodes, const NodalPointers<dim> &to) const
      {
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            const unsigned int n = nodes[v];
            if (mass_and_momentum)
              to.mass[n] += mass[v];
            for (unsigned int d = 0; d < dim; ++d)
              {
                if (mass_and_momentum)
                  to.momentum[d][n] += momentum[v][d];
                if (internal_force)
                  to.force[d][n] += force[v][d];
              }
          }
      }
    };

    /** P2G with linear weights computed where used (updated Lagrangian,
     * one set of nodal fields) in a cell without hanging nodes: its
     * particles add into its 2^dim nodes held in locals (CellSums),
     * added into the nodal vectors once. With APIC (@p affine: the
     * particles' B at @p affine_velocity) only in box cells, by the
     * closed forms of affine_transfer.h. */
    template <int dim, bool mass_and_momentum, bool internal_force, bool affine>
    DEAL_II_ALWAYS_INLINE inline void
    transfer_one_cell(
      const BackgroundGrid<dim>                          &grid,
      const ParticlesByCell<dim, const ParticleSet<dim>> &by_cell,
      const LinearWeights<dim>                           &weights,
      const std::size_t                                   cell_index,
      const NodalPointers<dim>                           &to,
      const unsigned int                                  affine_velocity)
    {
      const GridCell<dim> &c = grid.cells[cell_index];
      if (by_cell.empty(cell_index))
        return;
      const unsigned int *const nodes = &grid.cell_nodes[c.first_node];
      if (LinearWeights<dim>::is_box(c))
        {
          BoxCellSums<dim, mass_and_momentum, internal_force> box;
          by_cell.for_each(
            cell_index, [&](const auto &p) DEAL_II_ALWAYS_INLINE {
              const typename CellSums<dim, mass_and_momentum, internal_force>::
                Shares shares(p);
              // A reference: a copy cost the 3D column 7 instructions a
              // particle.
              const Point<dim> &xi = p.get_reference_location();
              if constexpr (affine)
                {
                  double g[dim][dim];
                  box_affine_unit_gradient(
                    read_tensor<dim>(&p.get_properties()[affine_velocity]),
                    xi,
                    c.inverse_jacobian,
                    g);
                  box.add_affine(
                    shares.m, shares.v, g, shares.minus_V_sigma, xi);
                }
              else
                box.add(shares.m, shares.v, shares.minus_V_sigma, xi);
            });
          box.scatter(c.inverse_jacobian, nodes, to);
          return;
        }
      CellSums<dim, mass_and_momentum, internal_force> sums;
      by_cell.for_each(cell_index, [&](const auto &p) DEAL_II_ALWAYS_INLINE {
        sums.add(p,
                 [&](const Point<dim> &xi, auto &&g) { weights.at(xi, c, g); });
      });
      sums.scatter(nodes, to);
    }

    /** P2G a cell at a time, for linear weights computed here: a cell
     * without hanging nodes keeps its nodes' sums in locals and adds them
     * once (transfer_one_cell(); a value added straight into the nodal
     * vectors cost 7 to 10 instructions; with APIC a box cell only), the
     * others add each particle's shares with @p per_particle(k, particle,
     * cell). */
    template <int  dim,
              bool mass_and_momentum,
              bool internal_force,
              bool affine,
              typename PerParticle>
    void
    transfer_by_cell(const BackgroundGrid<dim> &grid,
                     const ParticleSet<dim>    &particles,
                     const LinearWeights<dim>  &weights,
                     const NodalPointers<dim>  &to,
                     const PerParticle         &per_particle)
    {
      const ParticlesByCell<dim, const ParticleSet<dim>> by_cell(grid,
                                                                 particles);
      for (std::size_t i = 0; i < grid.cells.size(); ++i)
        {
          // Asked first, as G2P does: the cell's data would be read for
          // nothing where it has no particles (the air above a body). The
          // tall grid of the flowing column, two thirds air, spent a fifth
          // of its P2G waiting for those reads (perf).
          if (by_cell.empty(i))
            continue;
          const GridCell<dim> &c = grid.cells[i];
          if (c.first_weight == numbers::invalid_unsigned_int &&
              (!affine || LinearWeights<dim>::is_box(c)))
            transfer_one_cell<dim, mass_and_momentum, internal_force, affine>(
              grid, by_cell, weights, i, to, particles.fields.affine_velocity);
          else
            by_cell.for_each(i, [&](const auto &p) DEAL_II_ALWAYS_INLINE {
              per_particle(0, p, c); // LinearWeights needs no k
            });
        }
    }

    /** APIC's x_p, and C = B D^-1 about it into @p C. x_p is the
     * stencil's recorded position, or, for weights computed where used,
     * the point they are computed at (MUSL re-maps after the particles
     * moved). */
    template <int dim, typename Weights, typename Particle>
    DEAL_II_ALWAYS_INLINE inline Point<dim>
    affine_origin(const BackgroundGrid<dim> &grid,
                  const Stencil<dim>        &stencil,
                  const Weights             &weights,
                  const std::size_t          k,
                  const Particle            &p,
                  const GridCell<dim>       &c,
                  const CoreFields          &f,
                  Tensor<2, dim>            &C)
    {
      Point<dim> x_p;
      if constexpr (computed_where_used<dim, Weights>)
        x_p = weights_centroid(grid, weights, k, p, c);
      else
        x_p = stencil.position[k];
      C = affine_velocity_gradient(grid,
                                   weights,
                                   k,
                                   p,
                                   c,
                                   x_p,
                                   read_tensor<dim>(
                                     &p.get_properties()[f.affine_velocity]));
      return x_p;
    }

    /** Particle @p k into @p to as vectors, through windowed weights by
     * rows or stored ones into an interleaved block; false (nothing
     * added) for other weights and targets, which go node by node. */
    template <int  dim,
              bool mass_and_momentum,
              bool internal_force,
              typename Weights,
              typename Particle,
              typename To>
    DEAL_II_ALWAYS_INLINE inline bool
    add_as_vectors(const Weights        &weights,
                   const Stencil<dim>   &stencil,
                   const std::size_t     k,
                   const Particle       &p,
                   const GridCell<dim>  &c,
                   const double          m,
                   const Tensor<1, dim> &v,
                   const double (&P)[dim][dim],
                   const To &to)
    {
      if constexpr (std::is_same_v<Weights, WindowWeights<dim>>)
        {
          p2g_rows::add_by_rows<dim, mass_and_momentum, internal_force>(
            weights, k, p, c, m, v, P, to);
          return true;
        }
      else if constexpr (std::is_same_v<Weights, StoredWeights<dim>> &&
                         To::interleaved)
        {
          p2g_rows::
            add_entries_to_block<dim, mass_and_momentum, internal_force>(
              stencil, k, m, v, P, to.block);
          return true;
        }
      else
        return false;
    }

    /** The kernel, compiled once per choice of quantities so that the usual
     * all-in-one P2G has no branch in its loop. */
    template <int  dim,
              bool mass_and_momentum,
              bool internal_force,
              bool affine,
              bool total_lagrangian = false,
              bool predictor        = false,
              typename Targets,
              typename Weights>
    void
    transfer(const BackgroundGrid<dim> &grid,
             const ParticleSet<dim>    &particles,
             const Stencil<dim>        &stencil,
             const Weights             &weights,
             const Targets             &targets,
             const double               predictor_offset = 0)
    {
      const CoreFields &f       = particles.fields;
      constexpr bool    by_cell = std::is_same_v<Weights, LinearWeights<dim>> &&
                               !Targets::per_body && !total_lagrangian &&
                               !predictor;
      const auto per_particle =
        [&](const std::size_t    k,
            const auto          &p,
            const GridCell<dim> &c) DEAL_II_ALWAYS_INLINE {
          const ArrayView<const double> props = p.get_properties();
          const double                  m     = props[FixedCore<dim>::mass];
          const auto                   &to    = targets.of(props);
          Tensor<1, dim> v = read_vector<dim>(&props[FixedCore<dim>::velocity]);
          // Newmark: the grid carries the predicted velocity.
          if constexpr (predictor)
            v -= predictor_offset * read_vector<dim>(&props[f.acceleration]);
          Tensor<2, dim> C;
          Point<dim>     x_p;
          if (affine)
            x_p = affine_origin(grid, stencil, weights, k, p, c, f, C);
          // Once per particle, as a plain array (deal.II's symmetric
          // tensor times a vector goes through accessor objects).
          double force_per_grad[dim][dim] = {};
          if (internal_force)
            {
              const auto P = force_per_gradient<total_lagrangian, dim>(props);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  force_per_grad[i][j] = P[i][j];
            }
          if constexpr (!Targets::per_body && !affine)
            if (add_as_vectors<dim, mass_and_momentum, internal_force>(
                  weights, stencil, k, p, c, m, v, force_per_grad, to))
              return;
          weights(k,
                  p,
                  c,
                  [&](const unsigned int    n,
                      const double          N,
                      const Tensor<1, dim> &grad_N) DEAL_II_ALWAYS_INLINE {
                    if (mass_and_momentum)
                      {
                        to.add_mass_and_momentum(
                          n,
                          m * N,
                          affine ? v + C * (grid.node_positions[n] - x_p) : v);
                        if constexpr (Targets::per_body)
                          for (unsigned int d = 0; d < dim; ++d)
                            to.mass_gradient[d][n] += m * grad_N[d];
                      }
                    if (internal_force)
                      {
                        double fi[dim];
                        for (unsigned int d = 0; d < dim; ++d)
                          {
                            const double *P = force_per_grad[d];
                            fi[d]           = P[0] * grad_N[0];
                            for (unsigned int j = 1; j < dim; ++j)
                              fi[d] += P[j] * grad_N[j];
                          }
                        to.add_force(n, fi);
                      }
                  });
        };
      if constexpr (by_cell)
        transfer_by_cell<dim, mass_and_momentum, internal_force, affine>(
          grid, particles, weights, targets.fields, per_particle);
      else
        for_each_particle_in_stencil_order(grid, particles, per_particle);
    }
  } // namespace

  namespace
  {
    /** Zero what P2G will add into. */
    template <int dim>
    void
    zero(NodalFields<dim> &fields,
         const bool        mass_and_momentum,
         const bool        internal_force)
    {
      if (mass_and_momentum)
        {
          fields.mass = 0.;
          for (unsigned int d = 0; d < dim; ++d)
            fields.momentum[d] = 0.;
        }
      if (internal_force)
        for (unsigned int d = 0; d < dim; ++d)
          fields.force[d] = 0.;
    }

    /** The InterleavedNodes @p block into the nodal vectors of @p fields
     * (owned and ghost entries) it stands for, which leaves them in the
     * state zero() and the additions would have (not ghosted: the ghost
     * entries hold this rank's sums for their owners). */
    template <int dim>
    void
    copy_block(const std::vector<double> &block,
               NodalFields<dim>          &fields,
               const bool                 mass_and_momentum,
               const bool                 internal_force)
    {
      constexpr unsigned int stride = InterleavedNodes<dim>::stride;
      const std::size_t      n      = block.size() / stride;
      if (mass_and_momentum)
        {
          fields.mass.zero_out_ghost_values();
          double *const mass = fields.mass.begin();
          for (std::size_t i = 0; i < n; ++i)
            mass[i] = block[i * stride];
          for (unsigned int d = 0; d < dim; ++d)
            {
              fields.momentum[d].zero_out_ghost_values();
              double *const momentum = fields.momentum[d].begin();
              for (std::size_t i = 0; i < n; ++i)
                momentum[i] = block[i * stride + 1 + d];
            }
        }
      if (internal_force)
        for (unsigned int d = 0; d < dim; ++d)
          {
            fields.force[d].zero_out_ghost_values();
            double *const force = fields.force[d].begin();
            for (std::size_t i = 0; i < n; ++i)
              force[i] = block[i * stride + 1 + dim + d];
          }
    }

    /** Add to @p exchange what P2G added into @p fields. */
    template <int dim>
    void
    add_sums(NodalExchange    &exchange,
             NodalFields<dim> &fields,
             const bool        mass_and_momentum,
             const bool        internal_force)
    {
      if (mass_and_momentum)
        {
          exchange.add(fields.mass);
          exchange.add(fields.momentum);
        }
      if (internal_force)
        exchange.add(fields.force);
    }

    /** The kernel for the quantities asked for, into @p targets. */
    template <int dim, typename Targets>
    void
    dispatch(const BackgroundGrid<dim> &grid,
             const ParticleSet<dim>    &particles,
             const Stencil<dim>        &stencil,
             const Targets             &targets,
             const bool                 mass_and_momentum,
             const bool                 internal_force,
             const Formulation          formulation,
             const double               predictor_offset)
    {
      const bool affine =
        particles.fields.affine_velocity != numbers::invalid_unsigned_int;
      const bool reference = formulation == Formulation::total_lagrangian;
      const auto run       = [&](auto... choices) {
        const auto sweep = [&](const auto &weights) {
          transfer<dim, decltype(choices)::value...>(
            grid, particles, stencil, weights, targets, predictor_offset);
        };
        // The interleaved block is for 3^dim or more nodes a particle:
        // stored weights and windowed ones (particle_to_grid).
        if constexpr (Targets::interleaved)
          {
            if (stencil.where_used)
              sweep(WindowWeights<dim>::of(grid, stencil));
            else
              sweep(StoredWeights<dim>{stencil});
          }
        else
          with_weights(grid, stencil, sweep);
      };
      using Yes = std::true_type;
      using No  = std::false_type;
      if (predictor_offset != 0.)
        {
          // Newmark's first P2G (FLIP only: no affine part).
          AssertThrow(mass_and_momentum && internal_force && !affine &&
                        particles.fields.acceleration !=
                          numbers::invalid_unsigned_int,
                      ExcInternalError());
          if (reference)
            run(Yes(), Yes(), No(), Yes(), Yes());
          else
            run(Yes(), Yes(), No(), No(), Yes());
        }
      else if (internal_force && reference)
        {
          if (mass_and_momentum && affine)
            run(Yes(), Yes(), Yes(), Yes());
          else if (mass_and_momentum)
            run(Yes(), Yes(), No(), Yes());
          else
            run(No(), Yes(), No(), Yes());
        }
      else if (mass_and_momentum && internal_force && affine)
        run(Yes(), Yes(), Yes());
      else if (mass_and_momentum && internal_force)
        run(Yes(), Yes(), No());
      else if (mass_and_momentum && affine)
        run(Yes(), No(), Yes());
      else if (mass_and_momentum)
        run(Yes(), No(), No());
      else if (internal_force)
        run(No(), Yes(), No());
    }
  } // namespace

  template <int dim>
  void
  particle_to_grid(const BackgroundGrid<dim> &grid,
                   const ParticleSet<dim>    &particles,
                   const Stencil<dim>        &stencil,
                   NodalFields<dim>          &fields,
                   const bool                 mass_and_momentum,
                   const bool                 internal_force,
                   const Formulation          formulation,
                   const double               predictor_offset)
  {
    if (stencil.where_used && !stencil.on_windows())
      {
        zero(fields, mass_and_momentum, internal_force);
        dispatch(grid,
                 particles,
                 stencil,
                 SingleTarget<NodalPointers<dim>>{NodalPointers<dim>(fields)},
                 mass_and_momentum,
                 internal_force,
                 formulation,
                 predictor_offset);
      }
    else
      {
        // Stored or windowed weights (3^dim or more nodes a particle): one
        // block entry a node instead of 1 + 2 dim vectors
        // (InterleavedNodes).
        std::vector<double>               &block = fields.p2g_block;
        const Utilities::MPI::Partitioner &nodes =
          *fields.mass.get_partitioner();
        block.assign((nodes.locally_owned_size() + nodes.n_ghost_indices()) *
                       InterleavedNodes<dim>::stride,
                     0.);
        dispatch(grid,
                 particles,
                 stencil,
                 SingleTarget<InterleavedNodes<dim>>{{block.data()}},
                 mass_and_momentum,
                 internal_force,
                 formulation,
                 predictor_offset);
        copy_block(block, fields, mass_and_momentum, internal_force);
      }
    NodalExchange sums;
    add_sums(sums, fields, mass_and_momentum, internal_force);
    sums.sum_ghosts_into_owners();
  }

  template <int dim>
  void
  particle_to_body_grids(const BackgroundGrid<dim> &grid,
                         const ParticleSet<dim>    &particles,
                         const Stencil<dim>        &stencil,
                         NodalFieldSet<dim>        &set,
                         const bool                 mass_and_momentum,
                         const bool                 internal_force,
                         const Formulation          formulation,
                         const double               predictor_offset)
  {
    for (unsigned int b = 0; b < set.body.size(); ++b)
      {
        zero(set.body[b], mass_and_momentum, internal_force);
        if (mass_and_momentum)
          for (NodalVector &v : set.mass_gradient[b])
            v = 0.;
      }
    dispatch(grid,
             particles,
             stencil,
             BodyTargets<dim>(set, particles),
             mass_and_momentum,
             internal_force,
             formulation,
             predictor_offset);
    NodalExchange sums;
    for (unsigned int b = 0; b < set.body.size(); ++b)
      {
        add_sums(sums, set.body[b], mass_and_momentum, internal_force);
        if (mass_and_momentum)
          sums.add(set.mass_gradient[b]);
      }
    sums.sum_ghosts_into_owners();
    zero(set.core, mass_and_momentum, internal_force);
    for (const NodalFields<dim> &body : set.body)
      {
        if (mass_and_momentum)
          set.core.mass += body.mass;
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (mass_and_momentum)
              set.core.momentum[d] += body.momentum[d];
            if (internal_force)
              set.core.force[d] += body.force[d];
          }
      }
  }

#define DEALMPM_INSTANTIATE(dim)                                    \
  template void particle_to_grid(const BackgroundGrid<dim> &,       \
                                 const ParticleSet<dim> &,          \
                                 const Stencil<dim> &,              \
                                 NodalFields<dim> &,                \
                                 bool,                              \
                                 bool,                              \
                                 Formulation,                       \
                                 double);                           \
  template void particle_to_body_grids(const BackgroundGrid<dim> &, \
                                       const ParticleSet<dim> &,    \
                                       const Stencil<dim> &,        \
                                       NodalFieldSet<dim> &,        \
                                       bool,                        \
                                       bool,                        \
                                       Formulation,                 \
                                       double);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
