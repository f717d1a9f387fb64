#pragma once

#include <dealmpm/diagnostics/accuracy_report.h>
#include <dealmpm/io/output_record.h>

#include <iosfwd>
#include <vector>

namespace dealmpm
{
  /**
   * Everything a run has learnt besides its particles and grid: where it is
   * (time, step, the last step's size), what it has written (the output
   * record), when it writes next, its speed counters, the particles it lost or
   * held at a wall, the accuracy monitor, and each effect's accumulators (in
   * the order the scene lists them, filled when the state is saved). Written
   * and read whole, so that a later `resume` can rebuild the loop from a saved
   * run instead of from the scene's start.
   */
  struct RunState
  {
    double          time           = 0;
    unsigned int    step           = 0;
    double          next_output    = 0;
    double          particle_steps = 0; ///< summed over the steps
    double          stepping_time  = 0; ///< wall seconds of steps + checks
    double          lost_particles = 0; ///< all ranks
    double          lost_mass      = 0; ///< their mass, all ranks
    double          held_particles = 0; ///< put back on a wall, all ranks
    double          last_dt = 0; ///< the last step's size (Newmark needs it)
    double          repartitions     = 0; ///< of the grid among the ranks
    double          adaptations      = 0; ///< grid changes by 'Adaptivity'
    double          split_particles  = 0; ///< particles split in two^dim
    double          merged_particles = 0; ///< removed by merging
    OutputRecord    output;
    AccuracyMonitor accuracy;
    /** Each effect's saved_state() (of this rank). */
    std::vector<std::vector<double>> effect_states;
    /** In a checkpoint: every rank's effect_states, by rank (a resumed
     * run gives each rank its own, or on another number of ranks the
     * shares of sums to one rank, Effect::state_shared_by_ranks()). */
    std::vector<std::vector<std::vector<double>>> effect_states_by_rank;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &time &step &next_output &particle_steps &stepping_time;
      archive &lost_particles &held_particles &last_dt &repartitions &output;
      archive &adaptations &split_particles &merged_particles;
      archive                               &lost_mass;
      archive                               &accuracy;
      archive                               &effect_states;
      archive                               &effect_states_by_rank;
    }

    /** As text with every double to the last bit. */
    void
    save(std::ostream &out) const;
    void
    load(std::istream &in);
  };
} // namespace dealmpm
