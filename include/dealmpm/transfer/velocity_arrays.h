#pragma once

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_field_set.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>

#include <vector>

namespace dealmpm
{
  /** The nodal velocity and increment arrays a G2P sweep reads: one set
   * for every particle (single-velocity MPM). With @p light, also USL's
   * light-node weights (update_nodal_velocity()), if the fields have any:
   * a sweep compiled without them pays nothing for them. */
  template <int dim, bool light = false>
  struct VelocityArrays
  {
    static constexpr bool may_be_light = light;
    const double         *velocity[dim];
    const double         *increment[dim];
    /** NodalFields::increment_weight when some node is light, or
     * nullptr. */
    const double *weight = nullptr;
    /** The velocity and then its increment interleaved by node
     * (block_stride doubles a node), where G2P through windowed weights
     * reads them (fill_velocity_block()); else nullptr. */
    const double                 *block        = nullptr;
    static constexpr unsigned int block_stride = 1 + 2 * dim;

    explicit VelocityArrays(const NodalFields<dim> &fields)
    {
      if (light && fields.has_light_nodes)
        weight = fields.increment_weight.begin();
      for (unsigned int d = 0; d < dim; ++d)
        {
          velocity[d]  = fields.velocity[d].begin();
          increment[d] = fields.velocity_increment[d].begin();
        }
    }

    template <typename Properties>
    DEAL_II_ALWAYS_INLINE const VelocityArrays &
    of(const Properties &) const
    {
      return *this;
    }

    /** Whether a node of @p cell weighs less than 1 (asked only when
     * weight is set). */
    DEAL_II_ALWAYS_INLINE bool
    has_light_node(const BackgroundGrid<dim> &grid,
                   const GridCell<dim>       &cell) const
    {
      for (unsigned int j = 0; j < cell.n_nodes; ++j)
        if (weight[grid.cell_nodes[cell.first_node + j]] < 1)
          return true;
      return false;
    }
  };

  /**
   * Copies the velocity (and with @p increment its increment) of every
   * owned and ghost node of @p fields into their p2g_block, interleaved by
   * node, and returns @p arrays pointing at it. A sweep through windowed
   * weights then loads a node's values from one address, and sums them
   * in one vector operation: 3^dim nodes a particle, against one copy
   * per node.
   */
  template <int dim>
  VelocityArrays<dim>
  fill_velocity_block(const NodalFields<dim> &fields,
                      VelocityArrays<dim>     arrays,
                      const bool              increment)
  {
    constexpr unsigned int stride = VelocityArrays<dim>::block_stride;
    const NodalVector     &v0     = fields.velocity[0];
    const std::size_t      n =
      v0.locally_owned_size() + v0.get_partitioner()->n_ghost_indices();
    std::vector<double> &block = fields.p2g_block;
    block.resize(n * stride);
    for (unsigned int d = 0; d < dim; ++d)
      for (std::size_t i = 0; i < n; ++i)
        block[i * stride + d] = arrays.velocity[d][i];
    if (increment)
      for (unsigned int d = 0; d < dim; ++d)
        for (std::size_t i = 0; i < n; ++i)
          block[i * stride + dim + d] = arrays.increment[d][i];
    arrays.block = block.data();
    return arrays;
  }

  /** The core fields with USL's light-node weights (a sweep's Fields). */
  template <int dim>
  struct WithLightNodes
  {
    const NodalFields<dim> &fields;
  };

  /** Each particle reads its own body's nodal velocity (contact: the
   * field set's body fields), light-node weights included. */
  template <int dim>
  struct BodyVelocities
  {
    std::vector<VelocityArrays<dim, true>> bodies;
    const ParticleSet<dim>                &particles;

    BodyVelocities(const NodalFieldSet<dim> &set,
                   const ParticleSet<dim>   &particles)
      : particles(particles)
    {
      for (const NodalFields<dim> &fields : set.body)
        bodies.emplace_back(fields);
    }

    template <typename Properties>
    DEAL_II_ALWAYS_INLINE const VelocityArrays<dim, true>                             &
    of(const Properties &props) const
    {
      return bodies[particles.body_of(props)];
    }
  };

  /** What a sweep reads for @p fields: their arrays. */
  template <int dim>
  VelocityArrays<dim>
  velocity_arrays(const NodalFields<dim> &fields)
  {
    return VelocityArrays<dim>(fields);
  }

  template <int dim>
  VelocityArrays<dim, true>
  velocity_arrays(const WithLightNodes<dim> &with)
  {
    return VelocityArrays<dim, true>(with.fields);
  }

  template <int dim>
  const BodyVelocities<dim> &
  velocity_arrays(const BodyVelocities<dim> &bodies)
  {
    return bodies;
  }
} // namespace dealmpm
