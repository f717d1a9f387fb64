#pragma once

#include <deal.II/base/tensor.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

#include <vector>

namespace dealmpm
{
  /**
   * The particle -> node weights of one step: for each local particle (in
   * the order the kernels visit them: grid.cells, then the particles of each
   * cell), a variable number of entries (node, N, grad N). Computed once per
   * step and read by every P2G and G2P of that step. Hanging nodes are
   * already resolved into their masters.
   */
  template <int dim>
  struct Stencil
  {
    std::vector<unsigned int>   begin; ///< n_particles + 1 offsets
    std::vector<unsigned int>   node;  ///< local index into nodal vectors
    std::vector<double>         N;
    std::vector<Tensor<1, dim>> grad_N;

    std::size_t
    n_particles() const
    {
      return begin.empty() ? 0 : begin.size() - 1;
    }
  };

  /** Linear (Q1) weights at each particle's reference location. */
  template <int dim>
  void
  compute_linear_stencil(const BackgroundGrid<dim> &grid,
                         const ParticleSet<dim>    &particles,
                         Stencil<dim>              &stencil);

  /**
   * GIMP weights (Bardenhagen and Kober 2004) on grids of axis-aligned boxes:
   * S_i = (1 / V) int over the particle domain of N_i, grad S_i = (1 / V) int
   * of grad N_i, summed over the (owned or ghost) cells the domain overlaps,
   * with hanging nodes resolved, V the covered volume. The domain is the box
   * of half-lengths domain_half_length (uGIMP), stretched by F_dd when
   * @p follow_deformation (cpGIMP). Needs grid.find_neighbors().
   */
  template <int dim>
  void
  compute_gimp_stencil(const BackgroundGrid<dim> &grid,
                       const ParticleSet<dim>    &particles,
                       const bool                 follow_deformation,
                       Stencil<dim>              &stencil);
} // namespace dealmpm
