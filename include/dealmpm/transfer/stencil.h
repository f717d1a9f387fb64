#pragma once

#include <deal.II/base/tensor.h>

#include <dealmpm/grid/background_grid.h>
#include <dealmpm/particles/particle_set.h>

#include <string>
#include <vector>

namespace dealmpm
{
  template <int dim>
  class LatticeBlocks;
  template <int dim>
  struct QuadraticBSplineGrid;

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
    /** APIC with stored weights only (empty otherwise, also with weights
     * computed where used, which need none: affine_transfer.h): each
     * particle's position when the weights were computed. The affine
     * transfers measure x_i - x_p from it, also in MUSL's re-map after the
     * particles have moved. */
    std::vector<Point<dim>> position;
    /** Made once at the particles' reference positions and kept for the
     * run (total Lagrangian: compute_reference_stencil()). */
    bool reference = false;
    /** The weights are computed where they are used: linear ones
     * (LinearWeights), or on three-node windows (WindowWeights) the
     * quadratic B-spline's of @p spline or GIMP's on @p gimp_lattice
     * (GimpWindows); begin, node,
     * N and grad_N stay empty. Set when the step's P2G and G2P sweeps are
     * the weights' only readers (Simulation::weights_where_used()). */
    bool where_used = false;
    /** With where_used: the B-spline's lattice, or nullptr. */
    const QuadraticBSplineGrid<dim> *spline = nullptr;
    /** With where_used: GIMP's lattice (Kernel::gimp_lattice()), or
     * nullptr, and where the particles keep their domain_half_length. */
    const LatticeBlocks<dim> *gimp_lattice     = nullptr;
    unsigned int              gimp_half_length = numbers::invalid_unsigned_int;
    /** cpGIMP on windows: the domains stretch with F's diagonal, so each
     * step's stress update checks that every half-length along d stays
     * within gimp_stretch_limit[d] (half the grid's shortest edge along d;
     * ParticleCheck::domains_fit), and the next step computes its weights
     * where used only if all do; else it stores them
     * (Simulation::finish_step()). */
    bool           gimp_follows_deformation = false;
    Tensor<1, dim> gimp_stretch_limit;

    /** Whether the sweeps compute the weights on three-node windows. */
    bool
    on_windows() const
    {
      return where_used && (spline != nullptr || gimp_lattice != nullptr);
    }

    /** The first particle whose weights could not be computed (a CPDI
     * domain reaching past the cells next to its own); the run stops. */
    bool                  failed          = false;
    types::particle_index failed_particle = 0;
    Point<dim>            failed_location;
    std::string           failure;

    std::size_t
    n_particles() const
    {
      return begin.empty() ? 0 : begin.size() - 1;
    }
  };

  /** Fill stencil.position (for APIC) in the stencil's particle order. */
  template <int dim>
  void
  record_positions(const BackgroundGrid<dim> &grid,
                   const ParticleSet<dim>    &particles,
                   Stencil<dim>              &stencil);

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
   * @p follow_deformation (cpGIMP). Needs grid.find_neighbors(). With
   * @p lattice, a particle whose cell has one and whose domain stays
   * inside it gets the same weights as products of 1D ones.
   */
  template <int dim>
  void
  compute_gimp_stencil(const BackgroundGrid<dim> &grid,
                       const ParticleSet<dim>    &particles,
                       const bool                 follow_deformation,
                       Stencil<dim>              &stencil,
                       const LatticeBlocks<dim>  *lattice = nullptr);

  /**
   * CPDI weights (Sadeghirad, Brannon and Burghardt 2011): the particle
   * domain is the parallelogram (parallelepiped) spanned by r_d = F e_d l_d
   * around the particle; the grid's Q1 functions are interpolated
   * multilinearly from its 2^dim corners, so S_i = mean of N_i at the
   * corners and grad S_i = sum_c N_i(x_c) R^{-T} s_c / 2^dim (R = [r_d],
   * s_c the corner's signs). Corners may lie in any owned or ghost cell that
   * shares a vertex with the particle's cell; a corner just past the grid's
   * boundary uses the nearest cell's functions extrapolated (they still sum
   * to one and reproduce linear fields). Works on any quadrilateral or
   * hexahedral grid, also with hanging nodes. Needs grid.find_neighbors().
   * With @p lattice, a particle in a cell that has one, on a grid of boxes,
   * whose corners stay inside it gets the same weights summed by lattice
   * node.
   */
  template <int dim>
  void
  compute_cpdi_stencil(const BackgroundGrid<dim> &grid,
                       const ParticleSet<dim>    &particles,
                       Stencil<dim>              &stencil,
                       const LatticeBlocks<dim>  *lattice = nullptr);
} // namespace dealmpm
