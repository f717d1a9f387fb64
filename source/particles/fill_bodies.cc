#include <dealmpm/base/run_messages.h>
#include <dealmpm/particles/fill_bodies.h>

#include <algorithm>

namespace dealmpm
{
  template <int dim>
  void
  fill_bodies(SceneReader                            &reader,
              const std::vector<Body<dim>>           &bodies,
              const std::vector<double>              &densities,
              const std::vector<std::vector<double>> &initial,
              const BackgroundGrid<dim>              &grid,
              ParticleSet<dim>                       &particles)
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        SectionScope           section(reader, "Body " + std::to_string(b + 1));
        const BoundingBox<dim> box = bodies[b].shape->bounding_box();
        const auto            &g   = grid.bounding_box.get_boundary_points();
        const auto            &s   = box.get_boundary_points();
        const double tolerance     = 1e-10 * grid.bounding_box.side_length(0);
        for (unsigned int d = 0; d < dim; ++d)
          if (s.first[d] < g.first[d] - tolerance ||
              s.second[d] > g.second[d] + tolerance)
            reader.fail("Shape",
                        "a body inside the grid " + format_point(g.first) +
                          " - " + format_point(g.second) + ", but it spans " +
                          format_point(s.first) + " - " +
                          format_point(s.second));
      }


    unsigned int id_stride = 1;
    for (const auto &body : bodies)
      id_stride =
        std::max(id_stride,
                 Utilities::fixed_power<dim>(body.particles_per_direction));
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const unsigned int       m         = bodies[b].material;
        const GeneratedParticles generated = generate_particles(
          bodies, b, densities[m], grid, particles, initial[m], id_stride);
        const unsigned int overlapped =
          Utilities::MPI::min(generated.overlapped_body, grid.comm);
        if (overlapped != numbers::invalid_unsigned_int)
          {
            SectionScope section(reader, "Body " + std::to_string(b + 1));
            reader.fail("Allow overlap",
                        "a body that does not overlap 'Body " +
                          std::to_string(overlapped + 1) +
                          "' (it would be filled twice); set 'Allow overlap "
                          "= true' in this body to let its particles replace "
                          "those of Body " +
                          std::to_string(overlapped + 1) + " there");
          }
        if (Utilities::MPI::sum(double(generated.n_created), grid.comm) == 0)
          {
            SectionScope section(reader, "Body " + std::to_string(b + 1));
            reader.fail("Shape",
                        "a body that covers at least one particle position of "
                        "the grid (it is smaller than the particle spacing, "
                        "outside the grid or covered by later bodies that "
                        "replace it)");
          }
      }
    particles.handler.update_cached_numbers();
  }

#define DEALMPM_INSTANTIATE(dim)                                      \
  template void fill_bodies(SceneReader &,                            \
                            const std::vector<Body<dim>> &,           \
                            const std::vector<double> &,              \
                            const std::vector<std::vector<double>> &, \
                            const BackgroundGrid<dim> &,              \
                            ParticleSet<dim> &);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
