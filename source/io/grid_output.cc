#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <dealmpm/io/grid_output.h>
#include <dealmpm/io/output_file.h>

#include <sstream>

namespace dealmpm
{
  template <int dim>
  std::string
  write_grid_output(const BackgroundGrid<dim> &grid,
                    const NodalFields<dim>    &fields,
                    const std::string         &directory,
                    const unsigned int         counter)
  {
    // Everything collective (ghost exchanges) comes before the files, so
    // that a rank that cannot write still takes part in all of it.
    const auto ghosted = [&](const NodalVector &v, NodalVector &copy) {
      copy.reinit(grid.partitioner);
      copy.copy_locally_owned_data_from(v);
      grid.hanging_node_constraints.distribute(copy);
      copy.update_ghost_values();
    };
    NodalVector                  mass;
    std::array<NodalVector, dim> velocity_components;
    ghosted(fields.mass, mass);
    for (unsigned int d = 0; d < dim; ++d)
      ghosted(fields.velocity[d], velocity_components[d]);

    // The velocity as one vector field (ParaView's glyphs and stream lines
    // want one), on an output-only FESystem(FE_Q(1), dim) whose vertex
    // values are copied from the scalar nodal vectors.
    const FESystem<dim> fe(FE_Q<dim>(1), dim);
    DoFHandler<dim>     vector_dofs(grid.triangulation);
    vector_dofs.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(vector_dofs, relevant);
    NodalVector velocity(vector_dofs.locally_owned_dofs(), relevant, grid.comm);
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
                velocity_components[d](scalar_cell->vertex_dof_index(v, 0));
        }
    // The owner of every node holds a cell at it: its value is the one all
    // ranks show.
    velocity.update_ghost_values();

    DataOut<dim> data_out;
    data_out.attach_triangulation(grid.triangulation);
    data_out.add_data_vector(grid.dof_handler, mass, "nodal_mass");
    data_out.add_data_vector(
      vector_dofs,
      velocity,
      std::vector<std::string>(dim, "nodal_velocity"),
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    Vector<float> level(grid.triangulation.n_active_cells());
    Vector<float> rank(grid.triangulation.n_active_cells());
    for (const auto &cell : grid.triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          level[cell->active_cell_index()] = cell->level();
          rank[cell->active_cell_index()]  = cell->subdomain_id();
        }
    data_out.add_data_vector(level, "level");
    data_out.add_data_vector(rank, "mpi_rank");
    data_out.build_patches();

    const std::string base  = "grid_" + Utilities::int_to_string(counter, 5);
    const auto        piece = [&](const unsigned int r) {
      return base + "." + Utilities::int_to_string(r) + ".vtu";
    };
    std::ostringstream vtu;
    data_out.write_vtu(vtu);
    OutputFile piece_file(directory + "/" +
                          piece(Utilities::MPI::this_mpi_process(grid.comm)));
    piece_file.write(vtu.str());
    piece_file.commit();
    if (Utilities::MPI::this_mpi_process(grid.comm) == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < Utilities::MPI::n_mpi_processes(grid.comm);
             ++r)
          pieces.push_back(piece(r));
        std::ostringstream pvtu;
        data_out.write_pvtu_record(pvtu, pieces);
        OutputFile record(directory + "/" + base + ".pvtu");
        record.write(pvtu.str());
        record.commit();
      }
    return base + ".pvtu";
  }

  template std::string
  write_grid_output(const BackgroundGrid<2> &,
                    const NodalFields<2> &,
                    const std::string &,
                    unsigned int);
  template std::string
  write_grid_output(const BackgroundGrid<3> &,
                    const NodalFields<3> &,
                    const std::string &,
                    unsigned int);
} // namespace dealmpm
