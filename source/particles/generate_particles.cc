#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/particles/body.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dealmpm
{
  namespace
  {
    /** Ids are (body, global cell index, place in the cell's pattern)
     * packed into one number: refuse grids where they would not fit. */
    template <int dim>
    void
    check_id_range(const BackgroundGrid<dim> &grid,
                   const unsigned int         body_index,
                   const unsigned int         id_stride)
    {
      const double n_cells = grid.triangulation.n_global_active_cells();
      if ((body_index + 1.) * n_cells * id_stride >
          double(std::numeric_limits<types::particle_index>::max()))
        throw InputError("too many particles for 32-bit particle ids: use "
                         "fewer cells, particles per cell or bodies");
    }

    /**
     * Fills cells with the particles of body number body_index (see
     * generate_particles): n per direction at the centres of the cell's
     * sub-cells, where the body's shape is and no later body that replaces
     * it is.
     */
    template <int dim>
    class BodyFiller
    {
    public:
      BodyFiller(const std::vector<Body<dim>> &bodies,
                 const unsigned int            body_index,
                 const double                  density,
                 const BackgroundGrid<dim>    &grid,
                 ParticleSet<dim>             &particles,
                 const std::vector<double>    &initial_internal_variables,
                 const unsigned int            id_stride)
        : bodies(bodies)
        , body_index(body_index)
        , body(bodies[body_index])
        , density(density)
        , grid(grid)
        , particles(particles)
        , initial_internal_variables(initial_internal_variables)
        , id_stride(id_stride)
        , n(body.particles_per_direction)
        , per_cell(Utilities::fixed_power<dim>(n))
        , shape_box(body.shape->bounding_box())
        , properties(particles.layout.size(), 0.)
      {
        AssertThrow(per_cell <= id_stride, ExcInternalError());
      }

      /** The body's particles in cell @p c. */
      void
      fill(const GridCell<dim> &c)
      {
        // Most cells are nowhere near the body: skip them by its box.
        const auto             vertices = c.vertices();
        const BoundingBox<dim> cell_box(
          std::vector<Point<dim>>(vertices.begin(), vertices.end()));
        if (cell_box.get_neighbor_type(shape_box) ==
            NeighborType::not_neighbors)
          return;
        for (unsigned int k = 0; k < per_cell; ++k)
          {
            const Point<dim> xi = pattern_point(k);
            const Point<dim> x  = c.real_point(xi);
            if (!body.shape->contains(x) ||
                first_body_containing(x, body_index + 1, bodies.size(), true) !=
                  numbers::invalid_unsigned_int)
              continue;
            if (!body.allow_overlap &&
                result.overlapped_body == numbers::invalid_unsigned_int)
              result.overlapped_body =
                first_body_containing(x, 0, body_index, false);
            if (counting)
              ++result.n_created;
            else
              insert(c, k, xi, x);
          }
      }

      /** fill() only counts the particles it would make. */
      bool counting = false;

      GeneratedParticles result;

    private:
      /** The first of bodies [begin, end) that contains @p x (with
       * @p replacing_only, only those whose particles replace earlier
       * bodies'), or numbers::invalid_unsigned_int. */
      unsigned int
      first_body_containing(const Point<dim>  &x,
                            const unsigned int begin,
                            const unsigned int end,
                            const bool         replacing_only) const
      {
        for (unsigned int b = begin; b < end; ++b)
          if ((!replacing_only || bodies[b].allow_overlap) &&
              bodies[b].shape->bounding_box().point_inside(x) &&
              bodies[b].shape->contains(x))
            return b;
        return numbers::invalid_unsigned_int;
      }

      /** Unit-cell point of place @p k of the pattern: the centre of its
       * sub-cell. */
      Point<dim>
      pattern_point(const unsigned int k) const
      {
        Point<dim>   xi;
        unsigned int rest = k;
        for (unsigned int d = 0; d < dim; ++d, rest /= n)
          xi[d] = (rest % n + 0.5) / n;
        return xi;
      }

      /** The particle at place @p k of cell @p c, unit-cell point @p xi,
       * position @p x, with the body's initial state. */
      void
      insert(const GridCell<dim> &c,
             const unsigned int   k,
             const Point<dim>    &xi,
             const Point<dim>    &x)
      {
        const CoreFields &f = particles.fields;
        // |det J| at the centre of the particle's sub-cell: exact for
        // bilinear cells, so the particle volumes of a cell sum to it.
        const double volume =
          (c.affine ? c.measure :
                      1. / std::abs(determinant(c.inverse_jacobian_at(xi)))) /
          per_cell;
        std::fill(properties.begin(), properties.end(), 0.);
        properties[f.mass]           = density * volume;
        properties[f.initial_volume] = volume;
        write_vector<dim>(&properties[f.velocity], body.velocity);
        write_tensor<dim>(&properties[f.deformation_gradient],
                          unit_symmetric_tensor<dim>());
        if (f.domain_half_length != numbers::invalid_unsigned_int)
          for (unsigned int d = 0; d < dim; ++d)
            properties[f.domain_half_length + d] =
              (c.far_corner[d] - c.origin[d]) / (2. * n);
        if (f.body != numbers::invalid_unsigned_int)
          properties[f.body] = body_index;
        std::copy(initial_internal_variables.begin(),
                  initial_internal_variables.end(),
                  properties.begin() +
                    particles.internal_offset[body.material]);
        const types::particle_index id =
          (body_index * grid.triangulation.n_global_active_cells() +
           c.cell->global_active_cell_index()) *
            id_stride +
          k;
        particles.handler.insert_particle(
          x, xi, id, c.cell, make_array_view(properties));
        ++result.n_created;
      }

      const std::vector<Body<dim>> &bodies;
      const unsigned int            body_index;
      const Body<dim>              &body;
      const double                  density;
      const BackgroundGrid<dim>    &grid;
      ParticleSet<dim>             &particles;
      const std::vector<double>    &initial_internal_variables;
      const unsigned int            id_stride;
      const unsigned int            n;
      const unsigned int            per_cell;
      const BoundingBox<dim>        shape_box;
      /** One particle's properties, reused. */
      std::vector<double> properties;
    };
  } // namespace

  template <int dim>
  GeneratedParticles
  generate_particles(const std::vector<Body<dim>> &bodies,
                     const unsigned int            body_index,
                     const double                  density,
                     const BackgroundGrid<dim>    &grid,
                     ParticleSet<dim>             &particles,
                     const std::vector<double>    &initial_internal_variables,
                     const unsigned int            id_stride)
  {
    BodyFiller<dim> filler(bodies,
                           body_index,
                           density,
                           grid,
                           particles,
                           initial_internal_variables,
                           id_stride);
    check_id_range(grid, body_index, id_stride);
    // Count first and reserve, so that the particle pool grows once: grown
    // by doubling while filling, it held up to twice the pool at the last
    // growth (the old copy and the new).
    filler.counting = true;
    for (const GridCell<dim> &c : grid.cells)
      filler.fill(c);
    particles.handler.reserve(particles.handler.n_locally_owned_particles() +
                              filler.result.n_created);
    filler.counting = false;
    filler.result   = GeneratedParticles();
    for (const GridCell<dim> &c : grid.cells)
      filler.fill(c);
    particles.changed();
    return filler.result;
  }

#define DEALMPM_INSTANTIATE(dim)                  \
  template GeneratedParticles generate_particles( \
    const std::vector<Body<dim>> &,               \
    unsigned int,                                 \
    double,                                       \
    const BackgroundGrid<dim> &,                  \
    ParticleSet<dim> &,                           \
    const std::vector<double> &,                  \
    unsigned int);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
