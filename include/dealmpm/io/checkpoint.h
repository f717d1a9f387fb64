#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <dealmpm/base/property_layout.h>
#include <dealmpm/base/scene_reader.h>

#include <chrono>
#include <string>
#include <vector>

namespace dealmpm
{
  using namespace dealii;

  /**
   * The "Checkpoint" section: when a run saves itself so that
   * `dealmpm scene.prm --resume` can continue it (after a crash, a kill by
   * the batch system, or to run it further).
   */
  struct CheckpointSettings
  {
    unsigned int step_interval  = 0;    ///< steps between checkpoints; 0: none
    double       wall_interval  = 0;    ///< wall seconds between them; 0: none
    bool         on_stop_signal = true; ///< one when SIGTERM/SIGINT stop it
    unsigned int keep           = 2;    ///< the newest this many are kept
    std::string  directory;             ///< resolved (never empty)

    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check the section (the reader at the top level); an empty
     * Directory is @p output_directory/checkpoints. */
    static CheckpointSettings
    read(SceneReader &reader, const std::string &output_directory);

    /** Whether a checkpoint is due by wall time, the last one taken (or
     * the run started) at @p last (this rank's clock). */
    bool
    due_by_time(const std::chrono::steady_clock::time_point last) const
    {
      return wall_interval > 0 && std::chrono::duration<double>(
                                    std::chrono::steady_clock::now() - last)
                                      .count() >= wall_interval;
    }
  };

  /**
   * What a checkpoint folder says about the run it saved besides the grid,
   * the particles (p4est's and deal.II's files "grid*") and the RunState
   * ("run_state.txt"): written as "checkpoint.txt", read before anything is
   * loaded, so that a resume that does not fit is refused with one line.
   * Doubles are written in hexadecimal, to the last bit.
   */
  struct CheckpointInfo
  {
    unsigned int dim     = 0;
    unsigned int n_ranks = 0;
    unsigned int step    = 0;
    double       time    = 0;
    /** BackgroundGrid::coarse_checksum of the grid before refinement. */
    std::string coarse_grid;
    /** Per particle property: "name offset components". */
    std::vector<std::string> particle_layout;
    /** The scene's entries that a resume must not change (scene_entries). */
    std::vector<std::string> scene;
    /** The run's numbers that are not in its RunState. */
    double mass_threshold = 0;
    /** 0 in checkpoints written before it was saved: keep the scene's. */
    double mean_particle_mass = 0;
    double max_signal_rate    = 0;
    bool   cfl_warned         = false;

    void
    write(const std::string &file) const;
    /** Throws InputError naming @p file when it is not a whole one. */
    static CheckpointInfo
    read(const std::string &file);
  };

  /**
   * Every entry of a parsed scene as "Section/Entry = value", except those
   * a resumed run may change: Time/End time, Time/Maximum number of steps
   * and the Output, Checkpoint and Load balance sections.
   */
  std::vector<std::string>
  scene_entries(const ParameterHandler &prm);

  /** The first entry in which @p now differs from @p saved, as a phrase
   * for a message, or "" when none does. */
  std::string
  first_scene_change(const std::vector<std::string> &saved,
                     const std::vector<std::string> &now);

  /** Each field of @p layout as "name offset components" (what a
   * checkpoint's particles hold, in order). */
  std::vector<std::string>
  layout_description(const PropertyLayout &layout);

  /** "checkpoint-00000120" for step 120. */
  std::string
  checkpoint_name(const unsigned int step);

  /**
   * Collective: rank 0 makes the empty folder @p directory /
   * checkpoint-NNNNNNNN.tmp (removing what an interrupted write left);
   * returns its path. Throws OutputError on every rank when it cannot.
   */
  std::string
  start_checkpoint(const std::string &directory,
                   const unsigned int step,
                   const MPI_Comm     comm);

  /**
   * Collective, after every rank has written into @p folder (from
   * start_checkpoint): rank 0 renames it to its final name, then writes
   * the pointer file "latest" (to a temporary file renamed over it) and
   * removes all but the newest @p keep checkpoints. Until the rename, the
   * earlier checkpoints and "latest" are untouched: a run killed during a
   * write leaves its last good checkpoint. Returns the final path.
   */
  std::string
  publish_checkpoint(const std::string &directory,
                     const std::string &folder,
                     const unsigned int step,
                     const unsigned int keep,
                     const MPI_Comm     comm);

  /**
   * The checkpoint to resume from: @p path is a checkpoint folder, or a
   * folder of checkpoints whose "latest" names one (the newest whole one
   * when "latest" is missing or names a damaged one; @p warning then says
   * so). Throws InputError when there is none.
   */
  std::string
  find_checkpoint(const std::string &path, std::string &warning);

  /** Remove the checkpoints in @p directory (rank 0): all of them, or
   * those after step @p after (a resumed run's abandoned future). Returns
   * how many; throws OutputError. */
  unsigned int
  remove_checkpoints(const std::string &directory, const long long after = -1);

  /**
   * For the checkpoint tests only: the environment variable
   * DEALMPM_KILL_IN_CHECKPOINT=n makes rank 0 kill its process (SIGKILL)
   * in the middle of its n-th checkpoint write, after the grid and
   * particles are written and before anything is published.
   */
  void
  test_kill_in_checkpoint(const MPI_Comm comm);
} // namespace dealmpm
