#pragma once

#include <dealmpm/grid/nodal_field_set.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/particles/particle_set.h>

#include <vector>

namespace dealmpm
{
  /* Where P2G adds (private to particle_to_grid.cc): each target says
   * whether it holds one set of fields per body and whether it is an
   * interleaved block, and gives a particle's fields by of(). */

  /** The raw arrays P2G adds into. */
  template <int dim>
  struct NodalPointers
  {
    static constexpr bool interleaved = false;
    double               *mass;
    double               *momentum[dim];
    double               *force[dim];
    double               *mass_gradient[dim] = {}; ///< body targets only

    DEAL_II_ALWAYS_INLINE void
    add_mass_and_momentum(const unsigned int    n,
                          const double          mN,
                          const Tensor<1, dim> &v) const
    {
      mass[n] += mN;
      for (unsigned int d = 0; d < dim; ++d)
        momentum[d][n] += mN * v[d];
    }

    DEAL_II_ALWAYS_INLINE void
    add_force(const unsigned int n, const double (&f)[dim]) const
    {
      for (unsigned int d = 0; d < dim; ++d)
        force[d][n] += f[d];
    }

    explicit NodalPointers(NodalFields<dim> &f)
      : mass(f.mass.begin())
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          momentum[d] = f.momentum[d].begin();
          force[d]    = f.force[d].begin();
        }
    }
  };

  /** Where P2G adds through stored or B-spline weights into one set of
   * nodal fields: a block of 1 + 2 dim numbers per node (mass, momentum,
   * force; 3D pads them to eight, so that mass and momentum are one vector
   * of four and force another), copied into the nodal vectors after the
   * sweep.
   * A stored stencil adds into 3^dim nodes a particle (quadratic
   * B-spline, GIMP); each entry then touches one cache line instead of 1
   * + 2 dim, from one address, and the pairs of momentum and force are
   * added as pairs. */
  template <int dim>
  struct InterleavedNodes
  {
    static constexpr bool         interleaved = true;
    static constexpr unsigned int stride      = dim == 3 ? 8 : 1 + 2 * dim;
    double                       *block;

    DEAL_II_ALWAYS_INLINE void
    add_mass_and_momentum(const unsigned int    n,
                          const double          mN,
                          const Tensor<1, dim> &v) const
    {
      double *const x = block + std::size_t(n) * stride;
      x[0] += mN;
      for (unsigned int d = 0; d < dim; ++d)
        x[1 + d] += mN * v[d];
    }

    DEAL_II_ALWAYS_INLINE void
    add_force(const unsigned int n, const double (&f)[dim]) const
    {
      double *const x = block + std::size_t(n) * stride + 1 + dim;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] += f[d];
    }
  };

  /** Where P2G adds: one set of nodal fields, as the vectors'
   * NodalPointers or an InterleavedNodes block (stored or B-spline
   * weights). */
  template <typename Fields>
  struct SingleTarget
  {
    static constexpr bool per_body    = false;
    static constexpr bool interleaved = Fields::interleaved;
    Fields                fields;

    DEAL_II_ALWAYS_INLINE const Fields &
    of(const ArrayView<const double> &) const
    {
      return fields;
    }
  };

  /** Where P2G adds: the fields of the particle's body, whose mass
   * gradient sum_p m_p grad N it adds too (contact's normals). */
  template <int dim>
  struct BodyTargets
  {
    static constexpr bool           per_body    = true;
    static constexpr bool           interleaved = false;
    std::vector<NodalPointers<dim>> bodies;
    const ParticleSet<dim>         &particles;

    BodyTargets(NodalFieldSet<dim> &set, const ParticleSet<dim> &particles)
      : particles(particles)
    {
      for (unsigned int b = 0; b < set.body.size(); ++b)
        {
          bodies.emplace_back(set.body[b]);
          for (unsigned int d = 0; d < dim; ++d)
            bodies.back().mass_gradient[d] = set.mass_gradient[b][d].begin();
        }
    }

    DEAL_II_ALWAYS_INLINE const NodalPointers<dim>                             &
    of(const ArrayView<const double> &props) const
    {
      return bodies[particles.body_of(props)];
    }
  };
} // namespace dealmpm
