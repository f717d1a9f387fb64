#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <dealmpm/io/grid_output.h>
#include <dealmpm/io/output_file.h>
#include <dealmpm/io/output_folder.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <sstream>

namespace dealmpm
{
  namespace
  {
    /** @p v with hanging nodes interpolated and ghost values (collective):
     * a node's value as every cell at it shows it. */
    template <int dim>
    void
    ghosted_copy(const BackgroundGrid<dim> &grid,
                 const NodalVector         &v,
                 NodalVector               &copy)
    {
      copy.reinit(grid.partitioner);
      copy.copy_locally_owned_data_from(v);
      grid.hanging_node_constraints.distribute(copy);
      copy.update_ghost_values();
    }

    /**
     * The velocity as one vector field (ParaView's glyphs and stream lines
     * want one), on an output-only FESystem(FE_Q(1), dim) distributed on
     * @p vector_dofs, whose vertex values are copied from the scalar nodal
     * vectors @p components (ghosted).
     */
    template <int dim>
    void
    velocity_field(const BackgroundGrid<dim>          &grid,
                   const std::array<NodalVector, dim> &components,
                   DoFHandler<dim>                    &vector_dofs,
                   NodalVector                        &velocity)
    {
      const FESystem<dim> fe(FE_Q<dim>(1), dim);
      vector_dofs.distribute_dofs(fe);
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(vector_dofs, relevant);
      velocity.reinit(vector_dofs.locally_owned_dofs(), relevant, grid.comm);
      for (const auto &cell : vector_dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const typename DoFHandler<dim>::active_cell_iterator scalar_cell(
              &grid.triangulation,
              cell->level(),
              cell->index(),
              &grid.dof_handler);
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int d = 0; d < dim; ++d)
                velocity(cell->vertex_dof_index(v, d)) =
                  components[d](scalar_cell->vertex_dof_index(v, 0));
          }
      // The owner of every node holds a cell at it: its value is the one
      // all ranks show.
      velocity.update_ghost_values();
    }

    /** Per active cell (locally owned ones set): its refinement level and
     * the rank that owns it. */
    template <int dim>
    void
    cell_levels_and_ranks(const BackgroundGrid<dim> &grid,
                          Vector<float>             &level,
                          Vector<float>             &rank)
    {
      level.reinit(grid.triangulation.n_active_cells());
      rank.reinit(grid.triangulation.n_active_cells());
      for (const auto &cell : grid.triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            level[cell->active_cell_index()] = grid.level(cell);
            rank[cell->active_cell_index()]  = cell->subdomain_id();
          }
    }

  } // namespace

  /** This rank's piece <base>.<rank>.vtu and, on rank 0, the record
   * <base>.pvtu that lists every rank's piece; returns the record's
   * name. */
  namespace
  {
    /** <directory>/<base>.h5 of all ranks, through a temporary file
     * renamed over it; returns its XDMF Grid element at @p time. */
    template <int dim>
    std::string
    write_hdf5(const DataOut<dim> &data_out,
               const std::string  &directory,
               const std::string  &base,
               const MPI_Comm      comm,
               const double        time)
    {
      // Duplicate vertices are kept: cell data (a region's stress) stays
      // constant in each cell, as in the .vtu files.
      DataOutBase::DataOutFilter filter(
        DataOutBase::DataOutFilterFlags(false, true));
      data_out.write_filtered_data(filter);
      const std::string name = base + ".h5", path = directory + "/" + name;
      std::string       problem;
      try
        {
          data_out.write_hdf5_parallel(filter, path + ".tmp", comm);
        }
      catch (const std::exception &e)
        {
          problem = "output file " + path + " cannot be written";
        }
      if (problem.empty() && Utilities::MPI::this_mpi_process(comm) == 0 &&
          std::rename((path + ".tmp").c_str(), path.c_str()) != 0)
        problem = "output file " + path + ": " + std::strerror(errno);
      agree_on_output_error(problem, "", comm);
      std::string grid =
        data_out.create_xdmf_entry(filter, step_folder + "/" + name, time, comm)
          .get_xdmf_content(3, ReferenceCells::get_hypercube<dim>());
      // deal.II writes the time with 6 digits: not enough to tell apart
      // outputs a step apart, nor to match the particles' series.
      const std::size_t begin = grid.find("<Time Value=\"");
      if (begin != std::string::npos)
        {
          const std::size_t  value = begin + 13;
          std::ostringstream precise;
          precise << std::setprecision(17) << time;
          grid.replace(value, grid.find('"', value) - value, precise.str());
        }
      return grid;
    }
  } // namespace

  template <int dim>
  std::string
  write_pieces(DataOut<dim>      &data_out,
               const std::string &directory,
               const std::string &base,
               const MPI_Comm     comm,
               const OutputFormat format,
               const double       time)
  {
    if (format == OutputFormat::hdf5)
      return write_hdf5(data_out, directory, base, comm, time);
    const auto piece = [&](const unsigned int r) {
      return base + "." + Utilities::int_to_string(r) + ".vtu";
    };
    // zlib's fastest level: at deal.II's default (best compression) a 3D
    // region of 32k cells spent 1.7 s of each output in deflate.
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    std::ostringstream vtu;
    data_out.write_vtu(vtu);
    OutputFile piece_file(directory + "/" +
                          piece(Utilities::MPI::this_mpi_process(comm)));
    piece_file.write(vtu.str());
    piece_file.commit();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < Utilities::MPI::n_mpi_processes(comm); ++r)
          pieces.push_back(piece(r));
        std::ostringstream pvtu;
        data_out.write_pvtu_record(pvtu, pieces);
        OutputFile record(directory + "/" + base + ".pvtu");
        record.write(pvtu.str());
        record.commit();
      }
    return base + ".pvtu";
  }

  template <int dim>
  std::string
  write_grid_output(const BackgroundGrid<dim> &grid,
                    const NodalFields<dim>    &fields,
                    const std::string         &directory,
                    const unsigned int         counter,
                    const OutputFormat         format,
                    const double               time)
  {
    // Everything collective (ghost exchanges) comes before the files, so
    // that a rank that cannot write still takes part in all of it.
    NodalVector                  mass;
    std::array<NodalVector, dim> velocity_components;
    ghosted_copy(grid, fields.mass, mass);
    for (unsigned int d = 0; d < dim; ++d)
      ghosted_copy(grid, fields.velocity[d], velocity_components[d]);
    DoFHandler<dim> vector_dofs(grid.triangulation);
    NodalVector     velocity;
    velocity_field<dim>(grid, velocity_components, vector_dofs, velocity);

    DataOut<dim> data_out;
    data_out.attach_triangulation(grid.triangulation);
    data_out.add_data_vector(grid.dof_handler, mass, "nodal_mass");
    data_out.add_data_vector(
      vector_dofs,
      velocity,
      std::vector<std::string>(dim, "nodal_velocity"),
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    Vector<float> level, rank;
    cell_levels_and_ranks(grid, level, rank);
    data_out.add_data_vector(level, "level");
    data_out.add_data_vector(rank, "mpi_rank");
    data_out.build_patches();
    return write_pieces(data_out,
                        directory,
                        "grid_" + Utilities::int_to_string(counter, 5),
                        grid.comm,
                        format,
                        time);
  }

#define DEALMPM_INSTANTIATE(dim)                                      \
  template std::string write_grid_output(const BackgroundGrid<dim> &, \
                                         const NodalFields<dim> &,    \
                                         const std::string &,         \
                                         unsigned int,                \
                                         OutputFormat,                \
                                         double);                     \
  template std::string write_pieces(DataOut<dim> &,                   \
                                    const std::string &,              \
                                    const std::string &,              \
                                    MPI_Comm,                         \
                                    OutputFormat,                     \
                                    double);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
