#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <dealmpm/io/grid_output.h>

namespace dealmpm
{
  template <int dim>
  std::string
  write_grid_output(const BackgroundGrid<dim> &grid,
                    const NodalFields<dim>    &fields,
                    const std::string         &directory,
                    const unsigned int         counter)
  {
    DataOut<dim> data_out;
    data_out.attach_dof_handler(grid.dof_handler);
    std::vector<NodalVector> copies;
    copies.reserve(dim + 1);
    const auto add = [&](const NodalVector &v, const std::string &name) {
      copies.emplace_back(grid.partitioner);
      copies.back().copy_locally_owned_data_from(v);
      grid.hanging_node_constraints.distribute(copies.back());
      copies.back().update_ghost_values();
      data_out.add_data_vector(copies.back(), name);
    };
    add(fields.mass, "nodal_mass");
    const char *axes[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      add(fields.velocity[d], std::string("nodal_velocity_") + axes[d]);

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
    return data_out.write_vtu_with_pvtu_record(
      directory + "/", "grid", counter, grid.comm, 5, 0);
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
