#pragma once

#include <deal.II/lac/la_parallel_vector.h>

#include <array>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  using NodalVector = LinearAlgebra::distributed::Vector<double>;

  /**
   * The grid state of one step, one distributed vector per scalar field over
   * the FE_Q(1) nodes (owned + ghost entries). P2G adds into mass, momentum
   * and force, compress() sums across ranks; the grid update turns them into
   * the end-of-step velocity v* and the velocity increment v* - v that G2P
   * reads. Hanging nodes never receive anything (the kernels only see
   * effective nodes).
   */
  template <int dim>
  struct NodalFields
  {
    NodalVector                  mass;
    std::array<NodalVector, dim> momentum;
    std::array<NodalVector, dim> force;
    std::array<NodalVector, dim> velocity;           ///< v* after the update
    std::array<NodalVector, dim> velocity_increment; ///< v* - v
    /** USL only (empty otherwise): the share of a node's own increment its
     * velocity gradient uses, min(1, m / stable mass); see
     * update_nodal_velocity(). */
    NodalVector increment_weight;
    /** Per grid cell (grid.cells' order), whether a node of it weighs less
     * than 1, so that G2P looks only there; empty when no node is light
     * (then G2P uses no weights). */
    std::vector<unsigned char> light_cells;

    void
    reinit(
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
    {
      mass.reinit(partitioner);
      increment_weight = NodalVector(); // sized again on first use
      light_cells.clear();
      for (unsigned int d = 0; d < dim; ++d)
        {
          momentum[d].reinit(partitioner);
          force[d].reinit(partitioner);
          velocity[d].reinit(partitioner);
          velocity_increment[d].reinit(partitioner);
        }
    }
  };
} // namespace dealmpm
