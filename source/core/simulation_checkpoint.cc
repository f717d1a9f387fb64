#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/parameter_file.h>
#include <dealmpm/core/simulation.h>
#include <dealmpm/io/checkpoint.h>
#include <dealmpm/io/output_file.h>
#include <dealmpm/io/region_checkpoint.h>

#include <fstream>
#include <sstream>

// Saving a run and resuming it: the checkpoint's folder is written by
// io/checkpoint.h, what goes into it is decided here.
namespace dealmpm
{
  template <int dim>
  std::string
  Simulation<dim>::write_checkpoint()
  {
    TimerOutput::Scope        t(*computing_timer, "checkpoint");
    const CheckpointSettings &s = run_settings.checkpoint;
    const std::string folder = start_checkpoint(s.directory, loop.step, comm);
    // The particles travel with their cells (deal.II's lists brought up
    // to the step's order), all their properties included.
    particles->update_handler(grid);
    particles->handler.prepare_for_serialization();
    grid.triangulation.save(folder + "/grid");
    save_fem_regions(regions, folder, comm);
    // Every rank's accumulators (work is summed over the ranks).
    RunState state = run_state();
    state.effect_states_by_rank =
      Utilities::MPI::gather(comm, state.effect_states, 0);
    std::string problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          CheckpointInfo info;
          info.dim                = dim;
          info.n_ranks            = Utilities::MPI::n_mpi_processes(comm);
          info.step               = loop.step;
          info.time               = loop.time;
          info.coarse_grid        = grid.coarse_checksum;
          info.particle_layout    = layout_description(particles->layout);
          info.scene              = scene_entry_list;
          info.mass_threshold     = mass_threshold;
          info.mean_particle_mass = mean_particle_mass;
          info.max_signal_rate    = max_signal_rate;
          info.cfl_warned         = cfl_warned;
          info.write(folder + "/checkpoint.txt");
          std::ostringstream text;
          state.save(text);
          OutputFile file(folder + "/run_state.txt");
          file.write(text.str());
          file.commit();
        }
      catch (const OutputError &e)
        {
          problem = e.what();
        }
    agree_on_output_error(problem, "", comm);
    test_kill_in_checkpoint(comm);
    const std::string saved =
      publish_checkpoint(s.directory, folder, loop.step, s.keep, comm);
    last_checkpoint_step = loop.step;
    last_checkpoint_time = std::chrono::steady_clock::now();
    return saved;
  }

  template <int dim>
  CheckpointInfo
  Simulation<dim>::find_saved_run(SceneReader &reader, const std::string &where)
  {
    resumed_checkpoint = find_checkpoint(where, resume_warning);
    CheckpointInfo saved =
      CheckpointInfo::read(resumed_checkpoint + "/checkpoint.txt");
    const std::string cannot = reader.file_name() +
                               ": cannot resume the run saved in " +
                               resumed_checkpoint + ": ";
    if (saved.dim != dim)
      throw InputError(cannot + "it is " + std::to_string(saved.dim) +
                       "D, the scene " + std::to_string(dim) + "D");
    const std::string change =
      first_scene_change(saved.scene, scene_entry_list);
    if (!change.empty())
      throw InputError(cannot + change +
                       " (a resumed run may change only 'Time/End time', "
                       "'Time/Maximum number of steps' and the sections "
                       "Output, Checkpoint, Load balance and Checks)");
    return saved;
  }

  template <int dim>
  void
  Simulation<dim>::restore_saved_run(const CheckpointInfo &saved)
  {
    const std::string file = resumed_checkpoint + "/run_state.txt";
    // A repartition on another number of ranks counts for this run.
    const double  repartitions = loop.repartitions;
    std::ifstream in(file);
    try
      {
        loop.load(in);
      }
    catch (const std::exception &e)
      {
        throw InputError(file + ": cannot be read (" + one_line(e) + ")");
      }
    loop.repartitions += repartitions;
    if (loop.effect_states.size() != effects.size() || loop.step != saved.step)
      throw InputError(file + ": does not belong to " + resumed_checkpoint +
                       "/checkpoint.txt");
    // Each rank its own accumulators; on another number of ranks, the
    // shared values of rank 0 and the sums of the shares on rank 0.
    const auto        &by_rank = loop.effect_states_by_rank;
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    if (by_rank.size() != saved.n_ranks)
      throw InputError(file + ": does not hold every rank's state");
    for (unsigned int e = 0; e < effects.size(); ++e)
      {
        if (by_rank.size() == Utilities::MPI::n_mpi_processes(comm))
          {
            effects[e]->restore_state(by_rank[rank][e]);
            continue;
          }
        std::vector<double>     state  = by_rank[0][e];
        const std::vector<bool> shared = effects[e]->state_shared_by_ranks();
        for (unsigned int k = 0; k < state.size(); ++k)
          if (k >= shared.size() || !shared[k])
            {
              state[k] = 0;
              if (rank == 0)
                for (const auto &of_rank : by_rank)
                  state[k] += of_rank[e][k];
            }
        effects[e]->restore_state(state);
      }
    restore_fem_regions(regions, resumed_checkpoint, saved.n_ranks, comm);
    mass_threshold = saved.mass_threshold;
    if (saved.mean_particle_mass > 0)
      mean_particle_mass = saved.mean_particle_mass;
    max_signal_rate      = saved.max_signal_rate;
    cfl_warned           = saved.cfl_warned;
    last_checkpoint_step = loop.step;
  }

  template <int dim>
  unsigned int
  Simulation<dim>::open_output(const Statistics &initial)
  {
    const bool   resumed = !resumed_checkpoint.empty();
    unsigned int n_removed =
      output_writer.open(scene_file, initial, resumed ? &loop.output : nullptr);
    // An earlier run's checkpoints, or those the resumed run wrote after
    // the one it continues from (their future is being computed again).
    std::string problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          n_removed +=
            remove_checkpoints(run_settings.checkpoint.directory,
                               resumed ? static_cast<long long>(loop.step) :
                                         -1LL);
        }
      catch (const OutputError &e)
        {
          problem = e.what();
        }
    agree_on_output_error(problem, "", comm);
    last_checkpoint_time = std::chrono::steady_clock::now();
    return n_removed;
  }

  template std::string
  Simulation<2>::write_checkpoint();
  template std::string
  Simulation<3>::write_checkpoint();
  template CheckpointInfo
  Simulation<2>::find_saved_run(SceneReader &, const std::string &);
  template CheckpointInfo
  Simulation<3>::find_saved_run(SceneReader &, const std::string &);
  template void
  Simulation<2>::restore_saved_run(const CheckpointInfo &);
  template void
  Simulation<3>::restore_saved_run(const CheckpointInfo &);
  template unsigned int
  Simulation<2>::open_output(const Statistics &);
  template unsigned int
  Simulation<3>::open_output(const Statistics &);
} // namespace dealmpm
