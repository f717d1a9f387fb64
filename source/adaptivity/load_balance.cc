#include <deal.II/base/mpi.h>

#include <dealmpm/adaptivity/load_balance.h>

namespace dealmpm
{
  void
  LoadBalanceSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load balance");
    prm.declare_entry(
      "Enabled",
      "true",
      Patterns::Bool(),
      "On more than one rank: share the cells so that each rank holds about "
      "as many particles as the others (at the start, unless the grid's "
      "refinement shared them by the bodies already, and whenever the "
      "imbalance passes the limit). 'false': cells are shared by count, "
      "which puts a compact body on few ranks.");
    prm.declare_entry(
      "Particle weight",
      "10",
      Patterns::Integer(1, 100000),
      "A cell weighs 1 + this times its particles when the cells are "
      "shared: what a particle costs per step compared with an empty cell.");
    prm.declare_entry(
      "Imbalance limit",
      "1.2",
      Patterns::Double(),
      "Repartition when the most loaded rank's cells weigh more than this "
      "times the mean over the ranks (> 1; a cell weighs 1 + 'Particle "
      "weight' times its particles, what a repartition evens out). Where "
      "the cells are too few or too heavy to share that evenly, when the "
      "imbalance passes this times what the last repartition reached.");
    prm.declare_entry("Check interval",
                      "10",
                      Patterns::Integer(1),
                      "Steps between imbalance checks (one reduction each).");
    prm.declare_entry("Repartition interval",
                      "0",
                      Patterns::Integer(0),
                      "Also repartition every this many steps, whatever the "
                      "imbalance; 0: only when the imbalance passes the "
                      "limit.");
    prm.leave_subsection();
  }

  LoadBalanceSettings
  LoadBalanceSettings::read(SceneReader &reader)
  {
    LoadBalanceSettings s;
    SectionScope        section(reader, "Load balance");
    s.enabled              = reader.get_bool("Enabled");
    s.particle_weight      = reader.get_integer("Particle weight");
    s.imbalance_limit      = reader.get_double("Imbalance limit");
    s.check_interval       = reader.get_integer("Check interval");
    s.repartition_interval = reader.get_integer("Repartition interval");
    if (!(s.imbalance_limit > 1))
      reader.fail("Imbalance limit", "a number > 1");
    return s;
  }

  template <int dim>
  ParticleBalance
  particle_balance(const Particles::ParticleHandler<dim> &handler,
                   const MPI_Comm                         comm)
  {
    const double local = handler.n_locally_owned_particles();
    // One reduction: min of (n, -n).
    double extremes[2] = {local, -local};
    Utilities::MPI::min(ArrayView<const double>(extremes, 2),
                        comm,
                        ArrayView<double>(extremes, 2));
    ParticleBalance balance;
    balance.min  = extremes[0];
    balance.max  = -extremes[1];
    balance.mean = double(handler.n_global_particles()) /
                   Utilities::MPI::n_mpi_processes(comm);
    return balance;
  }

  template <int dim>
  boost::signals2::connection
  connect_particle_weights(parallel::distributed::Triangulation<dim> &tria,
                           const Particles::ParticleHandler<dim>     &handler,
                           const unsigned int particle_weight)
  {
    using CellStatus = typename Triangulation<dim>::CellStatus;
    return tria.signals.weight.connect(
      [&handler,
       particle_weight](const typename Triangulation<dim>::cell_iterator &cell,
                        const CellStatus status) -> unsigned int {
        types::particle_index n = 0;
        switch (status)
          {
            case CellStatus::CELL_PERSIST:
              n = handler.n_particles_in_cell(cell);
              break;
            case CellStatus::CELL_REFINE:
              // Called once per child, with the parent: a child's share.
              n = (handler.n_particles_in_cell(cell) +
                   GeometryInfo<dim>::max_children_per_cell - 1) /
                  GeometryInfo<dim>::max_children_per_cell;
              break;
            case CellStatus::CELL_COARSEN:
              for (const auto &child : cell->child_iterators())
                n += handler.n_particles_in_cell(child);
              break;
            default:
              break;
          }
        return 1 + particle_weight * static_cast<unsigned int>(n);
      });
  }

  template <int dim>
  double
  weight_imbalance(const parallel::distributed::Triangulation<dim> &tria,
                   const Particles::ParticleHandler<dim>           &handler,
                   const unsigned int particle_weight)
  {
    const double local =
      tria.n_locally_owned_active_cells() +
      double(particle_weight) * handler.n_locally_owned_particles();
    // One reduction for the max and the mean.
    const Utilities::MPI::MinMaxAvg weights =
      Utilities::MPI::min_max_avg(local, tria.get_communicator());
    return weights.avg > 0 ? weights.max / weights.avg : 1.;
  }

  template <int dim>
  boost::signals2::connection
  connect_expected_weights(
    parallel::distributed::Triangulation<dim>             &tria,
    const std::function<unsigned int(const Point<dim> &)> &expected_particles,
    const unsigned int                                     particle_weight)
  {
    using CellStatus = typename Triangulation<dim>::CellStatus;
    return tria.signals.weight.connect(
      [expected_particles,
       particle_weight](const typename Triangulation<dim>::cell_iterator &cell,
                        const CellStatus status) -> unsigned int {
        // A cell to be coarsened does not occur in a refinement; a cell to
        // be refined is asked once per child, which do not exist yet.
        const unsigned int n = status == CellStatus::CELL_COARSEN ?
                                 0 :
                                 expected_particles(cell->center());
        return 1 + particle_weight * n;
      });
  }

  template ParticleBalance
  particle_balance(const Particles::ParticleHandler<2> &, const MPI_Comm);
  template ParticleBalance
  particle_balance(const Particles::ParticleHandler<3> &, const MPI_Comm);
  template boost::signals2::connection
  connect_particle_weights(parallel::distributed::Triangulation<2> &,
                           const Particles::ParticleHandler<2> &,
                           const unsigned int);
  template boost::signals2::connection
  connect_particle_weights(parallel::distributed::Triangulation<3> &,
                           const Particles::ParticleHandler<3> &,
                           const unsigned int);
  template boost::signals2::connection
  connect_expected_weights(
    parallel::distributed::Triangulation<2> &,
    const std::function<unsigned int(const Point<2> &)> &,
    const unsigned int);
  template boost::signals2::connection
  connect_expected_weights(
    parallel::distributed::Triangulation<3> &,
    const std::function<unsigned int(const Point<3> &)> &,
    const unsigned int);
  template double
  weight_imbalance(const parallel::distributed::Triangulation<2> &,
                   const Particles::ParticleHandler<2> &,
                   const unsigned int);
  template double
  weight_imbalance(const parallel::distributed::Triangulation<3> &,
                   const Particles::ParticleHandler<3> &,
                   const unsigned int);
} // namespace dealmpm
