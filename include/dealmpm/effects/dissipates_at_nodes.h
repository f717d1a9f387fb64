#pragma once

#include <utility>
#include <vector>

namespace dealmpm
{
  /**
   * An effect whose forces dissipate work at grid nodes (wall friction,
   * contact between bodies): heat conduction, when listed, turns that
   * work into heat at those nodes in the same step (after G2P), shared by
   * the particles there as the nodes' temperature increments are.
   */
  class DissipatesAtNodes
  {
  public:
    virtual ~DissipatesAtNodes() = default;

    /** The work (J, per metre in 2D) dissipated at this rank's locally
     * owned nodes in this step's after_grid_update: (local index, work),
     * a node may appear more than once (the works add up). */
    const std::vector<std::pair<unsigned int, double>> &
    dissipated_at_nodes() const
    {
      return dissipated;
    }

  protected:
    /** Refilled by each after_grid_update (also from const helpers). */
    mutable std::vector<std::pair<unsigned int, double>> dissipated;
  };
} // namespace dealmpm
