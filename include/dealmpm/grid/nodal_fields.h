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
    /** Whether a node (owned or ghost) has 0 < weight < 1 this step: G2P
     * then looks at the weights of each particle's cell (in most steps of
     * most scenes no node is light, and G2P uses no weights). */
    bool has_light_nodes = false;
    /** Scratch interleaved by node, empty with linear weights computed
     * where used: P2G through stored or windowed weights sums mass,
     * momentum and force into it; G2P through windowed weights reads the
     * velocity and its increment from it (fill_velocity_block()), a
     * const sweep's scratch. */
    mutable std::vector<double> p2g_block;

    void
    reinit(
      const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
    {
      mass.reinit(partitioner);
      increment_weight = NodalVector(); // sized again on first use
      has_light_nodes  = false;
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
