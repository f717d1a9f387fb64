#include <deal.II/base/utilities.h>
#include <deal.II/fe/mapping_q_eulerian.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <dealmpm/io/grid_output.h>
#include <dealmpm/io/region_output.h>

#include <array>
#include <cmath>

namespace dealmpm
{
  template <int dim>
  std::string
  write_region_output(const SolidRegion<dim> &region,
                      const std::string      &directory,
                      const std::string      &base,
                      const OutputFormat      format,
                      const double            time)
  {
    using Vector_ = LinearAlgebra::distributed::Vector<double>;
    Vector_ u(region.get_displacement()), v(region.get_velocity());
    u.update_ghost_values();
    v.update_ghost_values();

    std::vector<SymmetricTensor<2, 3>> stress;
    std::vector<double>                von_mises;
    std::vector<std::vector<double>>   internal;
    region.cell_means(stress, von_mises, internal);
    const unsigned int n_active = region.get_triangulation().n_active_cells();
    static const char *names[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
    static const std::array<std::array<unsigned int, 2>, 6> index = {
      {{{0, 0}}, {{1, 1}}, {{2, 2}}, {{0, 1}}, {{1, 2}}, {{0, 2}}}};
    std::vector<Vector<float>> stress_data(6, Vector<float>(n_active));
    Vector<float>              von_mises_data(n_active), rank(n_active);
    const std::vector<FieldDescription> fields =
      region.get_material().internal_variables();
    unsigned int n_internal = 0;
    for (const FieldDescription &f : fields)
      n_internal += f.n_components;
    std::vector<Vector<float>> internal_data(n_internal,
                                             Vector<float>(n_active));
    std::size_t                c = 0;
    for (const auto &cell : region.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int a = cell->active_cell_index();
          for (unsigned int k = 0; k < 6; ++k)
            stress_data[k][a] = stress[c][index[k][0]][index[k][1]];
          von_mises_data[a] = von_mises[c];
          rank[a]           = cell->subdomain_id();
          for (unsigned int j = 0; j < n_internal; ++j)
            internal_data[j][a] = internal[c][j];
          ++c;
        }

    DataOut<dim> data_out;
    data_out.attach_dof_handler(region.get_dof_handler());
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector(dim, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(u,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             vector);
    data_out.add_data_vector(v,
                             std::vector<std::string>(dim, "velocity"),
                             DataOut<dim>::type_dof_data,
                             vector);
    for (unsigned int k = 0; k < 6; ++k)
      data_out.add_data_vector(stress_data[k],
                               std::string("stress_") + names[k],
                               DataOut<dim>::type_cell_data);
    data_out.add_data_vector(von_mises_data,
                             "von_mises",
                             DataOut<dim>::type_cell_data);
    unsigned int j = 0;
    for (const FieldDescription &f : fields)
      for (unsigned int k = 0; k < f.n_components; ++k, ++j)
        data_out.add_data_vector(internal_data[j],
                                 f.n_components == 1 ?
                                   f.name :
                                   f.name + "_" + std::to_string(k),
                                 DataOut<dim>::type_cell_data);
    data_out.add_data_vector(rank, "mpi_rank", DataOut<dim>::type_cell_data);
    // The deformed mesh, as the particles are shown where they are.
    const MappingQEulerian<dim, Vector_> deformed(region.degree(),
                                                  region.get_dof_handler(),
                                                  u);
    data_out.build_patches(deformed, region.degree());
    return write_pieces(
      data_out, directory, base, region.get_communicator(), format, time);
  }

  template std::string
  write_region_output(const SolidRegion<2> &,
                      const std::string &,
                      const std::string &,
                      OutputFormat,
                      double);
  template std::string
  write_region_output(const SolidRegion<3> &,
                      const std::string &,
                      const std::string &,
                      OutputFormat,
                      double);
} // namespace dealmpm
