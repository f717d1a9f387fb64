#include <deal.II/base/mpi.h>

#include <dealmpm/adaptivity/split_particles.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace dealmpm
{
  namespace
  {
    template <int dim>
    using ParticleIterator =
      typename Particles::ParticleHandler<dim>::particle_iterator;

    /** Whether each of the 2^dim parts of a particle of current volume
     * @p volume would still fill at least half of a particle's share of
     * a cell of measure @p cell_measure. */
    template <int dim>
    bool
    too_large(const double       volume,
              const double       cell_measure,
              const unsigned int particles_per_direction)
    {
      const double per_cell = std::pow(double(particles_per_direction), dim);
      return volume / (1u << dim) >= 0.5 * cell_measure / per_cell;
    }

    /** How many particles are too_large() for their cells, walked in the
     * step's order (deal.II's lists may lag behind it). */
    template <int dim>
    std::size_t
    n_to_split(const BackgroundGrid<dim> &grid,
               const ParticleSet<dim>    &particles,
               const unsigned int         particles_per_direction)
    {
      const ParticlesByCell<dim, const ParticleSet<dim>> by_cell(grid,
                                                                 particles);
      std::size_t                                        n = 0;
      for (std::size_t i = 0; i < grid.cells.size(); ++i)
        by_cell.for_each(i, [&](const auto &p) {
          n += too_large<dim>(current_volume<dim>(p.get_properties().data(),
                                                  particles.fields),
                              grid.cells[i].measure,
                              particles_per_direction);
        });
      return n;
    }

    /** The particles each of whose 2^dim parts would still fill at least
     * half of a particle's share of the cell (too_large()). */
    template <int dim>
    std::vector<ParticleIterator<dim>>
    particles_to_split(const BackgroundGrid<dim> &grid,
                       ParticleSet<dim>          &particles,
                       const unsigned int         particles_per_direction)
    {
      const CoreFields                  &f = particles.fields;
      std::vector<ParticleIterator<dim>> parents;
      for (const GridCell<dim> &c : grid.cells)
        for (auto p = particles.handler.particles_in_cell(c.cell).begin();
             p != particles.handler.particles_in_cell(c.cell).end();
             ++p)
          if (too_large<dim>(current_volume<dim>(p->get_properties().data(), f),
                             c.measure,
                             particles_per_direction))
            parents.push_back(p);
      return parents;
    }

    /** A part of a split particle, to be inserted once all are made. */
    template <int dim>
    struct Part
    {
      Point<dim>                                        location;
      typename Triangulation<dim>::active_cell_iterator cell;
      std::vector<double>                               properties;
    };

    /** Splits particle @p p: it becomes part 0, and its parts 1 to
     * 2^dim - 1 are appended to @p parts, their ids to @p ids (in a range
     * of its own above @p first_id, so that they are the same on any
     * number of ranks). */
    template <int dim>
    void
    split_parent(ParticleIterator<dim>              &p,
                 const CoreFields                   &f,
                 const types::particle_index         first_id,
                 std::vector<Part<dim>>             &parts,
                 std::vector<types::particle_index> &ids)
    {
      constexpr unsigned int n_parts = 1u << dim;
      const auto             props   = p->get_properties();
      const Tensor<2, dim> F = read_tensor<dim>(&props[f.deformation_gradient]);
      Tensor<1, dim>       size; // the initial size l0 per axis
      for (unsigned int d = 0; d < dim; ++d)
        size[d] = f.domain_half_length != numbers::invalid_unsigned_int ?
                    2 * props[f.domain_half_length + d] :
                    std::pow(props[f.initial_volume], 1. / dim);
      props[f.mass] /= n_parts;
      props[f.initial_volume] /= n_parts;
      if (f.domain_half_length != numbers::invalid_unsigned_int)
        for (unsigned int d = 0; d < dim; ++d)
          props[f.domain_half_length + d] /= 2;
      const Point<dim>     centre = p->get_location();
      const Tensor<1, dim> displacement =
        read_vector<dim>(&props[f.displacement]);
      const Tensor<2, dim> strain = F - unit_symmetric_tensor<dim>();
      // Part k's offset: -l0/4 or +l0/4 along axis d by bit d of k.
      const auto offset = [&](const unsigned int k) {
        Tensor<1, dim> o;
        for (unsigned int d = 0; d < dim; ++d)
          o[d] = ((k >> d) & 1 ? 0.25 : -0.25) * size[d];
        return o;
      };
      for (unsigned int k = 1; k < n_parts; ++k)
        {
          const Tensor<1, dim> o = offset(k);
          Part<dim>            part{centre + F * o,
                         p->get_surrounding_cell(),
                         std::vector<double>(props.begin(), props.end())};
          write_vector<dim>(&part.properties[f.displacement],
                            displacement + strain * o);
          parts.push_back(std::move(part));
          ids.push_back(first_id + p->get_id() * (n_parts - 1) + k - 1);
        }
      // The parent becomes part 0.
      const Tensor<1, dim> o = offset(0);
      write_vector<dim>(&props[f.displacement], displacement + strain * o);
      p->set_location(centre + F * o);
    }
  } // namespace

  template <int dim>
  double
  split_particles(const BackgroundGrid<dim> &grid,
                  ParticleSet<dim>          &particles,
                  const unsigned int         particles_per_direction)
  {
    constexpr unsigned int n_parts = 1u << dim;
    // Nothing to split anywhere (the usual case between refinements): no
    // sort either.
    const double n_split = Utilities::MPI::sum(
      double(n_to_split(grid, particles, particles_per_direction)), grid.comm);
    if (n_split == 0)
      return 0;
    particles.update_handler(grid); // walked cell by cell below

    // The parents first: inserting would invalidate the iterators.
    std::vector<ParticleIterator<dim>> parents =
      particles_to_split(grid, particles, particles_per_direction);

    // Ids above every id in use, each parent's parts in a range of its
    // own: the same ids on any number of ranks.
    const types::particle_index n_new = parents.size() * (n_parts - 1);
    const types::particle_index first_id =
      particles.handler.get_next_free_particle_index();

    std::vector<Part<dim>> parts;
    parts.reserve(n_new);
    std::vector<types::particle_index> ids;
    ids.reserve(n_new);
    for (auto &p : parents)
      split_parent(p, particles.fields, first_id, parts, ids);
    for (std::size_t i = 0; i < parts.size(); ++i)
      particles.handler.insert_particle(parts[i].location,
                                        Point<dim>(),
                                        ids[i],
                                        parts[i].cell,
                                        make_array_view(parts[i].properties));
    // The parts may lie in a neighbouring cell (or rank).
    particles.sort();
    return n_split;
  }

  namespace
  {
    /** The sub-cell, of a cell's n^dim, that reference point @p xi lies in
     * (points just outside the cell count to the nearest). */
    template <int dim>
    unsigned int
    sub_cell(const Point<dim> &xi, const unsigned int n)
    {
      unsigned int sub = 0;
      for (int d = dim - 1; d >= 0; --d)
        sub = sub * n + std::min(n - 1,
                                 static_cast<unsigned int>(
                                   std::max(0., std::floor(xi[d] * n))));
      return sub;
    }

    /** The particles of cell @p c grouped by (sub-cell, body; a body has
     * one material): the parts of one split particle share a group. */
    template <int dim>
    std::map<std::array<unsigned int, 2>, std::vector<ParticleIterator<dim>>>
    groups_in_cell(const GridCell<dim> &c,
                   ParticleSet<dim>    &particles,
                   const unsigned int   n)
    {
      std::map<std::array<unsigned int, 2>, std::vector<ParticleIterator<dim>>>
           groups;
      auto range = particles.handler.particles_in_cell(c.cell);
      for (auto p = range.begin(); p != range.end(); ++p)
        {
          const unsigned int sub =
            sub_cell(c.reference_point(p->get_location()), n);
          const auto props = p->get_properties();
          groups[{{sub, particles.body_of(props)}}].push_back(p);
        }
      return groups;
    }

    /** A group's sums: mass, current volume, first moment of mass, and
     * every property weighted by mass and by volume. */
    template <int dim>
    struct GroupSums
    {
      double              mass = 0, volume = 0;
      Point<dim>          centre;
      std::vector<double> by_mass, by_volume;

      GroupSums(const std::vector<ParticleIterator<dim>> &group,
                const CoreFields                         &f,
                const unsigned int                        n_properties)
        : by_mass(n_properties, 0.)
        , by_volume(n_properties, 0.)
      {
        for (const ParticleIterator<dim> &p : group)
          {
            const auto   props = p->get_properties();
            const double m     = props[f.mass];
            const double v     = current_volume<dim>(props.data(), f);
            mass += m;
            volume += v;
            centre += m * p->get_location();
            for (unsigned int i = 0; i < n_properties; ++i)
              {
                by_mass[i] += m * props[i];
                by_volume[i] += v * props[i];
              }
          }
      }
    };

    /** Merges @p group into its particle of the smallest id, which comes
     * first in it (the others are to be removed). */
    template <int dim>
    void
    merge_group(std::vector<ParticleIterator<dim>> &group,
                const CoreFields                   &f,
                const unsigned int                  n_properties)
    {
      std::sort(group.begin(),
                group.end(),
                [](const ParticleIterator<dim> &a,
                   const ParticleIterator<dim> &b) {
                  return a->get_id() < b->get_id();
                });
      const GroupSums<dim> sums(group, f, n_properties);
      const double         mass = sums.mass, volume = sums.volume;
      auto                 props = group[0]->get_properties();
      for (unsigned int i = 0; i < n_properties; ++i)
        props[i] = sums.by_mass[i] / mass;
      // Volume-weighted: F and stress (mass-weighted: velocity, so
      // that momentum is kept; everything else).
      for (unsigned int i = 0; i < dim * dim; ++i)
        props[f.deformation_gradient + i] =
          sums.by_volume[f.deformation_gradient + i] / volume;
      for (unsigned int i = 0;
           i < SymmetricTensor<2, dim>::n_independent_components;
           ++i)
        props[f.stress + i] = sums.by_volume[f.stress + i] / volume;
      props[f.mass]          = mass;
      const Tensor<2, dim> F = read_tensor<dim>(&props[f.deformation_gradient]);
      // The current volume is kept: V0 det F = sum of the volumes;
      // the domain grows with V0 from the group's mean.
      props[f.initial_volume] = volume / determinant(F);
      if (f.domain_half_length != numbers::invalid_unsigned_int)
        for (unsigned int d = 0; d < dim; ++d)
          props[f.domain_half_length + d] *=
            std::pow(props[f.initial_volume] /
                       (sums.by_mass[f.initial_volume] / mass),
                     1. / dim);
      group[0]->set_location(sums.centre / mass);
    }
  } // namespace

  template <int dim>
  double
  merge_particles(const BackgroundGrid<dim> &grid,
                  ParticleSet<dim>          &particles,
                  const unsigned int         particles_per_direction)
  {
    // A sub-cell holding this many particles of one body and material
    // (the parts of one split particle) is crowded.
    const unsigned int crowded      = 1u << dim;
    const unsigned int n_properties = particles.layout.size();
    particles.update_handler(grid); // walked cell by cell below
    std::vector<ParticleIterator<dim>> removed;
    for (const GridCell<dim> &c : grid.cells)
      {
        if (particles.handler.n_particles_in_cell(c.cell) < crowded)
          continue;
        auto groups = groups_in_cell(c, particles, particles_per_direction);
        for (auto &[key, group] : groups)
          {
            if (group.size() < crowded)
              continue;
            merge_group<dim>(group, particles.fields, n_properties);
            removed.insert(removed.end(), group.begin() + 1, group.end());
          }
      }
    const double n_removed =
      Utilities::MPI::sum(double(removed.size()), grid.comm);
    if (n_removed == 0)
      return 0;
    particles.handler.remove_particles(removed);
    // The merged particle may sit in a neighbouring cell (a concave cell).
    particles.sort();
    return n_removed;
  }

#define DEALMPM_INSTANTIATE(dim)                               \
  template double split_particles(const BackgroundGrid<dim> &, \
                                  ParticleSet<dim> &,          \
                                  const unsigned int);         \
  template double merge_particles(const BackgroundGrid<dim> &, \
                                  ParticleSet<dim> &,          \
                                  const unsigned int);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
