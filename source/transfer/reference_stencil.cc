#include <deal.II/lac/la_parallel_vector.h>

#include <dealmpm/transfer/reference_stencil.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace dealmpm
{
  template <int dim>
  void
  compute_reference_stencil(const BackgroundGrid<dim> &grid,
                            const Kernel<dim>         &kernel,
                            ParticleSet<dim>          &particles,
                            const bool                 apic,
                            Stencil<dim>              &stencil)
  {
    const CoreFields       &f = particles.fields;
    const std::size_t       n = particles.handler.n_locally_owned_particles();
    std::vector<Point<dim>> current_position(n);
    std::vector<Tensor<2, dim>> current_F(n);
    Tensor<2, dim>              identity;
    for (unsigned int d = 0; d < dim; ++d)
      identity[d][d] = 1.;
    for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t k, auto &p, const GridCell<dim> &c) {
        const auto props    = p.get_properties();
        current_position[k] = p.get_location();
        current_F[k]        = read_tensor<dim>(&props[f.deformation_gradient]);
        const Point<dim> X =
          current_position[k] - read_vector<dim>(&props[f.displacement]);
        p.set_location(X);
        p.set_reference_location(c.reference_point(X));
        write_tensor<dim>(&props[f.deformation_gradient], identity);
      });
    kernel.compute_stencil(grid, particles, stencil);
    if (apic)
      record_positions(grid, particles, stencil);
    // X must lie in the particle's own cell: an effect that moved a particle
    // without adding the move to its displacement would give it weights of
    // another place.
    for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t, const auto &p, const GridCell<dim> &) {
        const Point<dim> xi = p.get_reference_location();
        for (unsigned int d = 0; d < dim; ++d)
          if (!stencil.failed && (xi[d] < -1e-9 || xi[d] > 1. + 1e-9))
            {
              stencil.failed          = true;
              stencil.failed_particle = p.get_id();
              stencil.failed_location = p.get_location();
              stencil.failure =
                "its reference position x - u lies outside the cell it "
                "started in";
            }
      });
    for_each_particle_in_stencil_order(
      grid,
      particles,
      [&](const std::size_t k, auto &p, const GridCell<dim> &) {
        p.set_location(current_position[k]);
        write_tensor<dim>(&p.get_properties()[f.deformation_gradient],
                          current_F[k]);
      });
    stencil.reference = true;
  }

  template <int dim>
  std::pair<unsigned int, unsigned int>
  bodies_apart(const BackgroundGrid<dim> &grid,
               const ParticleSet<dim>    &particles,
               const Stencil<dim>        &stencil,
               const unsigned int         n_bodies)
  {
    if (n_bodies < 2)
      return {0, 0};
    // Each node's smallest body, over all ranks.
    LinearAlgebra::distributed::Vector<double> smallest(grid.partitioner);
    const auto for_each_entry = [&](const auto &visit) {
      for_each_particle_in_stencil_order(
        grid,
        particles,
        [&](const std::size_t k, const auto &p, const GridCell<dim> &) {
          const double body = particles.body_of(p.get_properties());
          for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
            if (stencil.N[e] > 0.)
              visit(body, stencil.node[e]);
        });
    };
    for (double &value : smallest)
      value = n_bodies;
    for (unsigned int i = 0; i < grid.partitioner->n_ghost_indices(); ++i)
      smallest.local_element(grid.partitioner->locally_owned_size() + i) =
        n_bodies;
    for_each_entry([&](const double body, const unsigned int node) {
      smallest.local_element(node) =
        std::min(smallest.local_element(node), body);
    });
    smallest.compress(VectorOperation::min);
    smallest.update_ghost_values();

    // Every body joins the smallest body at each node it touches.
    std::vector<std::pair<unsigned int, unsigned int>> joined;
    for_each_entry([&](const double body, const unsigned int node) {
      joined.emplace_back(static_cast<unsigned int>(body),
                          static_cast<unsigned int>(
                            smallest.local_element(node)));
    });
    std::sort(joined.begin(), joined.end());
    joined.erase(std::unique(joined.begin(), joined.end()), joined.end());
    std::vector<unsigned int> group(n_bodies);
    std::iota(group.begin(), group.end(), 0u);
    const auto root = [&](unsigned int b) {
      while (group[b] != b)
        b = group[b] = group[group[b]];
      return b;
    };
    for (const auto &pairs : Utilities::MPI::all_gather(grid.comm, joined))
      for (const auto &[a, b] : pairs)
        group[root(a)] = root(b);
    for (unsigned int b = 1; b < n_bodies; ++b)
      if (root(b) != root(0))
        return {0, b};
    return {0, 0};
  }

#define DEALMPM_INSTANTIATE(dim)                                       \
  template void compute_reference_stencil(const BackgroundGrid<dim> &, \
                                          const Kernel<dim> &,         \
                                          ParticleSet<dim> &,          \
                                          bool,                        \
                                          Stencil<dim> &);             \
  template std::pair<unsigned int, unsigned int> bodies_apart(         \
    const BackgroundGrid<dim> &,                                       \
    const ParticleSet<dim> &,                                          \
    const Stencil<dim> &,                                              \
    unsigned int);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
