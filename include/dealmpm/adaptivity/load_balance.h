#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/particles/particle_handler.h>

#include <dealmpm/base/scene_reader.h>

#include <boost/signals2/connection.hpp>
#include <functional>

namespace dealmpm
{
  using namespace dealii;

  /**
   * The "Load balance" section: how the grid's cells are shared among the
   * ranks. A cell weighs 1 + w n for its n particles (most of a step's work
   * is per particle), and the grid is repartitioned by those weights at
   * the start and whenever the most loaded rank holds more than a limit
   * times the mean number of particles.
   */
  struct LoadBalanceSettings
  {
    unsigned int particle_weight = 10;  ///< w: a particle's cost in cells
    double       imbalance_limit = 1.2; ///< max / mean cell weight per rank
    unsigned int check_interval  = 10;  ///< steps between checks
    /** Steps between repartitions whatever the imbalance; 0: never. */
    unsigned int repartition_interval = 0;
    bool         enabled              = true;

    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check the section (the reader at the top level). */
    static LoadBalanceSettings
    read(SceneReader &reader);
  };

  /** Particles per rank: the fewest, the most and the mean. */
  struct ParticleBalance
  {
    double min  = 0;
    double max  = 0;
    double mean = 0;
  };

  /** The locally owned particles of every rank, reduced (collective). */
  template <int dim>
  ParticleBalance
  particle_balance(const Particles::ParticleHandler<dim> &handler,
                   const MPI_Comm                         comm);

  /**
   * Connect the cell weights 1 + w n to the triangulation's weight signal,
   * so that every repartition (explicit, or in a refinement) balances
   * particles. A cell to be refined gives each child its share n / 2^dim; a
   * cell to be coarsened gets its children's sum. The particles must be
   * sorted into their cells when the signal fires. Keep the connection in
   * a scoped_connection that dies before the handler.
   */
  template <int dim>
  boost::signals2::connection
  connect_particle_weights(parallel::distributed::Triangulation<dim> &tria,
                           const Particles::ParticleHandler<dim>     &handler,
                           const unsigned int particle_weight);

  /**
   * Connect the cell weights 1 + w n for the particles n that the bodies
   * will put in a cell, @p expected_particles at its centre (for a cell to
   * be refined, at its parent's), while the grid is refined at the start:
   * the refinement's own partition then shares out particles that are not
   * made yet, and the start needs no repartition of the filled grid (which
   * costs about as much as building the grid again).
   */
  template <int dim>
  boost::signals2::connection
  connect_expected_weights(
    parallel::distributed::Triangulation<dim>             &tria,
    const std::function<unsigned int(const Point<dim> &)> &expected_particles,
    const unsigned int                                     particle_weight);

  /** The most loaded rank's cell weights (1 + w n for n particles) over
   * the mean, what a repartition evens out (collective). */
  template <int dim>
  double
  weight_imbalance(const parallel::distributed::Triangulation<dim> &tria,
                   const Particles::ParticleHandler<dim>           &handler,
                   const unsigned int particle_weight);

  /** The weight imbalance below which the start keeps the cells where
   * the grid's refinement put them: a repartition costs about a grid
   * build, which 5 % of a run's time pays back only in long runs. */
  constexpr double start_imbalance_tolerance = 1.05;
} // namespace dealmpm
