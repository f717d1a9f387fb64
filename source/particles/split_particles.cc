#include <deal.II/base/mpi.h>

#include <dealmpm/particles/split_particles.h>

#include <cmath>
#include <vector>

namespace dealmpm
{
  template <int dim>
  double
  split_particles(const BackgroundGrid<dim> &grid,
                  ParticleSet<dim>          &particles,
                  const unsigned int         particles_per_direction)
  {
    constexpr unsigned int n_parts = 1u << dim;
    const CoreFields      &f       = particles.fields;
    const double per_cell = std::pow(double(particles_per_direction), dim);

    // The parents first: inserting would invalidate the iterators.
    std::vector<typename Particles::ParticleHandler<dim>::particle_iterator>
      parents;
    for (const GridCell<dim> &c : grid.cells)
      for (auto p = particles.handler.particles_in_cell(c.cell).begin();
           p != particles.handler.particles_in_cell(c.cell).end();
           ++p)
        if (current_volume<dim>(p->get_properties().data(), f) / n_parts >=
            0.5 * c.measure / per_cell)
          parents.push_back(p);

    // Nothing to split anywhere: no sort either (the usual case between
    // refinements).
    const double n_split =
      Utilities::MPI::sum(double(parents.size()), grid.comm);
    if (n_split == 0)
      return 0;

    // Ids above every id in use, each parent's parts in a range of its
    // own: the same ids on any number of ranks.
    const types::particle_index n_new = parents.size() * (n_parts - 1);
    const types::particle_index first_id =
      particles.handler.get_next_free_particle_index();

    struct Part
    {
      Point<dim>                                        location;
      typename Triangulation<dim>::active_cell_iterator cell;
      std::vector<double>                               properties;
    };
    std::vector<Part> parts;
    parts.reserve(n_new);
    std::vector<types::particle_index> ids;
    ids.reserve(n_new);
    for (auto &p : parents)
      {
        const auto           props = p->get_properties();
        const Tensor<2, dim> F =
          read_tensor<dim>(&props[f.deformation_gradient]);
        Tensor<1, dim> size; // the initial size l0 per axis
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
            Part                 part{centre + F * o,
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
    for (std::size_t i = 0; i < parts.size(); ++i)
      particles.handler.insert_particle(parts[i].location,
                                        Point<dim>(),
                                        ids[i],
                                        parts[i].cell,
                                        make_array_view(parts[i].properties));
    // The parts may lie in a neighbouring cell (or rank).
    particles.handler.sort_particles_into_subdomains_and_cells();
    return n_split;
  }

  template double
  split_particles(const BackgroundGrid<2> &,
                  ParticleSet<2> &,
                  const unsigned int);
  template double
  split_particles(const BackgroundGrid<3> &,
                  ParticleSet<3> &,
                  const unsigned int);
} // namespace dealmpm
